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

RemovalSink::RemovalSink(const ProcessAxes& axes, PartModel& part)
    : part_(part), path_(axes, pathSettings(part)) {}

void RemovalSink::motion(const Motion& m) {
    ++counts_.moves;
    const ToolData tool = toolSource_ ? toolSource_() : ToolData{};
    path_.motion(m);  // also keeps the tool offsets of consecutive moves
    if (counts_.moves == 1) {
        ++counts_.approachMoves;
        path_.clearGeometry();
        return;
    }
    if (m.transformation != 30) {
        ++counts_.transformedMoves;
        path_.clearGeometry();
        return;
    }
    cutChords(m, tool);
    path_.clearGeometry();
}

void RemovalSink::cutChords(const Motion& m, const ToolData& tool) {
    const ToolpathLayer& scene = path_.geometry().scene;
    // Outside G41/G42 a turning tool's programmed point is its tip; the
    // nose centre (what the profile is cut with) lies inside it.
    std::array<double, 3> shift{0, 0, 0};
    Cutter cutter{tool.radius, 0, part_.profile() != nullptr && !tool.turning()};
    if (part_.profile() != nullptr && tool.turning()) {
        const Eigen::Vector2d edge = gne::edgeVector(tool.orientation);  // (axial, radial)
        if (edge.y() > 0.0) {
            ++counts_.insideToolMoves;
            return;
        }
        cutter.body = edge.x() < 0.0 ? 1 : (edge.x() > 0.0 ? -1 : 0);
        if (!m.compensated) {
            shift[static_cast<std::size_t>(part_.axialAxis())] = -tool.radius * edge.x();
            shift[static_cast<std::size_t>(part_.radialAxis())] = -tool.radius * edge.y();
        }
    }
    bool removed = false;
    for (std::size_t s = 0; s < scene.segmentCount(); ++s) {
        std::array<double, 3> a = scene.vertex(scene.segmentStart[s]);
        std::array<double, 3> b = scene.vertex(scene.segmentStart[s] + 1);
        for (std::size_t k = 0; k < 3; ++k) {
            a[k] += shift[k];
            b[k] += shift[k];
        }
        removed = part_.cut(a, b, cutter) || removed;
    }
    if (!removed) return;
    ++counts_.cuttingMoves;
    if (m.type != MotionType::Rapid) return;
    if (++counts_.rapidCuts <= kMaxRapidNotes)
        notes_.warning("REMOVAL_RAPID_CUT", m.where, "rapid move (G0) cuts into the part",
                       {"a rapid move through material would break the tool on the machine"});
}

}  // namespace mtc::core::removal
