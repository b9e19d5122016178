#include "cnc_core/removal/RemovalSink.h"

#include "cnc_core/contour/GneExpansion.h"

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
    : part_(part), path_(axes, pathSettings(part)) {}

void ToolSweep::pass(const Motion& m) {
    path_.motion(m);  // keeps the tool offsets of consecutive moves
    path_.clearGeometry();
    chords_.clear();
}

ToolSweep::Kind ToolSweep::sweep(const Motion& m, const ToolData& tool) {
    chords_.clear();
    path_.motion(m);  // keeps the tool offsets of consecutive moves
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
    }
}

void RemovalSink::cutChords(const Motion& m) {
    bool removed = false;
    for (const ToolChord& chord : sweep_.chords())
        removed = part_.cut(chord.a, chord.b, sweep_.cutter()) || removed;
    if (!removed) return;
    ++counts_.cuttingMoves;
    if (m.type != MotionType::Rapid) return;
    if (++counts_.rapidCuts <= kMaxRapidNotes)
        notes_.warning("REMOVAL_RAPID_CUT", m.where, "rapid move (G0) cuts into the part",
                       {"a rapid move through material would break the tool on the machine"});
}

}  // namespace mtc::core::removal
