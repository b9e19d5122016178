#include "cnc_core/removal/RemovalSink.h"

#include <cmath>

#include "cnc_core/contour/GneExpansion.h"
#include "cnc_core/toolpath/CurveMath.h"

namespace mtc::core::removal {

namespace {

constexpr std::uint64_t kMaxRapidNotes = 20;

ToolpathSettings pathSettings(const PartModel& part) {
    ToolpathSettings settings;
    settings.tolerance = part.resolution() / 4.0;
    return settings;
}

}  // namespace

ToolSweep::ToolSweep(const ProcessAxes& axes, const PartModel& part)
    : part_(part), axes_(axes), path_(axes, pathSettings(part)) {}

ToolSweep::Position ToolSweep::offsetOf(const Motion& m) {
    return m.compensated ? m.toolOffset : Position{};
}

void ToolSweep::pass(const Motion& m) {
    path_.motion(m);  // keeps the tool offsets of consecutive moves
    path_.clearGeometry();
    lastOffset_ = offsetOf(m);
    lastCompensated_ = m.compensated;
    chords_.clear();
    jacketChords_.clear();
}

void ToolSweep::carryOffsets(Motion& m) const {
    m.compensated = lastCompensated_;
    m.toolOffset = lastOffset_;
    m.programmedEnd = m.end;
    if (!m.compensated) return;
    for (int a = 0; a < m.axisCount && a < kMaxAxes; ++a)
        m.programmedEnd[static_cast<std::size_t>(a)] -= m.toolOffset[static_cast<std::size_t>(a)];
}

bool ToolSweep::developedChords(const Motion& m, const Position& previousOffset) {
    const int count = axes_.count();
    const int a1 = m.transformAxis1, a2 = m.transformAxis2;
    if (part_.profile() == nullptr || !(m.effectiveRadius > 0.0) || a1 < 0 || a2 < 0 ||
        a1 >= count || a2 >= count)
        return false;
    const int rotary = axes_.axis(a1).rotary ? a1 : (axes_.axis(a2).rotary ? a2 : -1);
    const int linear = !axes_.axis(a1).rotary ? a1 : (!axes_.axis(a2).rotary ? a2 : -1);
    if (rotary < 0 || linear < 0 || path_.sceneAxis(linear) != part_.axialAxis()) return false;
    // The tool centre across the axis: on the radial scene axis (angle 0 of
    // the wrap, TP-002) and the one after it, linear along the move.
    const int radial = path_.machineAxisOfScene(part_.radialAxis());
    const int side = path_.machineAxisOfScene((part_.radialAxis() + 1) % 3);
    const Position end = offsetOf(m);
    const auto centre = [&](const Position& at, const Position& offset, int axis) {
        const auto k = static_cast<std::size_t>(axis);
        return axis < 0 ? 0.0 : at[k] - offset[k];
    };
    const double x0 = centre(m.start, previousOffset, radial), x1 = centre(m.end, end, radial);
    const double y0 = centre(m.start, previousOffset, side), y1 = centre(m.end, end, side);
    const int polar = axes_.axis(rotary).polarDirection;
    const ToolpathLayer& developed = path_.geometry().developed;
    const std::size_t n = developed.segmentCount();
    const auto point = [&](std::size_t vertex, std::size_t step) {
        const std::array<double, 3> v = developed.vertex(vertex);  // axial, developed mm
        const double f = static_cast<double>(step) / static_cast<double>(n);
        const double x = x0 + (x1 - x0) * f, y = y0 + (y1 - y0) * f;
        const double degrees = curve::degreesFromDeveloped(v[1], m.effectiveRadius, polar);
        return JacketPoint{degrees * curve::kPi / 180.0 + std::atan2(y, x), v[0], std::hypot(x, y)};
    };
    for (std::size_t s = 0; s < n; ++s)
        jacketChords_.push_back(
            {point(developed.segmentStart[s], s), point(developed.segmentStart[s] + 1, s + 1)});
    return n > 0;
}

ToolSweep::Kind ToolSweep::sweep(const Motion& m, const ToolData& tool) {
    chords_.clear();
    jacketChords_.clear();
    path_.motion(m);  // keeps the tool offsets of consecutive moves
    const Position previousOffset = lastOffset_;
    lastOffset_ = offsetOf(m);
    lastCompensated_ = m.compensated;
    if (m.transformation == 32 && developedChords(m, previousOffset)) {
        path_.clearGeometry();
        cutter_ = Cutter{tool.radius, 0, true};  // a driven end mill, standing radially
        return Kind::Developed;
    }
    if (m.transformation != 30) {
        path_.clearGeometry();
        return Kind::Transformed;
    }
    // Outside G41/G42 a turning tool's programmed point is its tip; the
    // nose centre (what the profile is cut with) lies inside it.
    std::array<double, 3> shift{0, 0, 0};
    cutter_ = Cutter{tool.radius, 0, part_.profile() != nullptr && !tool.turning()};
    if (part_.profile() != nullptr && tool.turning()) {
        const Eigen::Vector2d edge = gne::edgeVector(tool.orientation);  // (axial, radial)
        if (edge.y() > 0.0) {
            path_.clearGeometry();
            return Kind::InsideTool;
        }
        cutter_.body = edge.x() < 0.0 ? 1 : (edge.x() > 0.0 ? -1 : 0);
        if (!m.compensated) {
            shift[static_cast<std::size_t>(part_.axialAxis())] = -tool.radius * edge.x();
            shift[static_cast<std::size_t>(part_.radialAxis())] = -tool.radius * edge.y();
        }
    }
    const ToolpathLayer& scene = path_.geometry().scene;
    for (std::size_t s = 0; s < scene.segmentCount(); ++s) {
        ToolChord chord{scene.vertex(scene.segmentStart[s]),
                        scene.vertex(scene.segmentStart[s] + 1)};
        for (std::size_t k = 0; k < 3; ++k) {
            chord.a[k] += shift[k];
            chord.b[k] += shift[k];
        }
        chords_.push_back(chord);
    }
    path_.clearGeometry();
    return Kind::Swept;
}

RemovalSink::RemovalSink(const ProcessAxes& axes, PartModel& part)
    : part_(part), sweep_(axes, part) {}

void RemovalSink::motion(const Motion& m) {
    ++counts_.moves;
    const ToolData tool = toolSource_ ? toolSource_() : ToolData{};
    if (counts_.moves == 1) {
        ++counts_.approachMoves;
        sweep_.pass(m);
        return;
    }
    switch (sweep_.sweep(m, tool)) {
        case ToolSweep::Kind::Transformed:
            ++counts_.transformedMoves;
            return;
        case ToolSweep::Kind::InsideTool:
            ++counts_.insideToolMoves;
            return;
        case ToolSweep::Kind::Swept:
            cutChords(m);
            return;
        case ToolSweep::Kind::Developed:
            cutJacket(m);
            return;
    }
}

void RemovalSink::cutJacket(const Motion& m) {
    std::string note;
    if (part_.makeJacket(note) == nullptr) {  // cannot happen: developed chords need a profile
        ++counts_.transformedMoves;
        return;
    }
    if (!note.empty())  // said once: the jacket is made at the first G32 move
        notes_.warning("REMOVAL_DEVELOPED_COARSER", m.where, note,
                       {"a coarser resolution keeps the G32 cuts as fine as the part's"});
    ++counts_.developedMoves;
    bool removed = false;
    for (const auto& chord : sweep_.jacketChords())
        removed = part_.cutJacket(chord[0], chord[1], sweep_.cutter().radius) || removed;
    if (removed) countCut(m);
}

void RemovalSink::cutChords(const Motion& m) {
    bool removed = false;
    for (const ToolChord& chord : sweep_.chords())
        removed = part_.cut(chord.a, chord.b, sweep_.cutter()) || removed;
    if (removed) countCut(m);
}

void RemovalSink::countCut(const Motion& m) {
    ++counts_.cuttingMoves;
    if (m.type != MotionType::Rapid) return;
    if (++counts_.rapidCuts <= kMaxRapidNotes)
        notes_.warning("REMOVAL_RAPID_CUT", m.where, "rapid move (G0) cuts into the part",
                       {"a rapid move through material would break the tool on the machine"});
}

}  // namespace mtc::core::removal
