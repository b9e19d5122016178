#include "cnc_core/toolpath/ToolpathGeometry.h"

#include <algorithm>

namespace mtc::core {

void ToolpathBounds::add(double x, double y, double z) {
    const double p[3] = {x, y, z};
    for (int i = 0; i < 3; ++i) {
        const auto k = static_cast<std::size_t>(i);
        if (empty || p[i] < min[k]) min[k] = p[i];
        if (empty || p[i] > max[k]) max[k] = p[i];
    }
    empty = false;
}

double ToolpathBounds::size() const {
    if (empty) return 0.0;
    return std::max({max[0] - min[0], max[1] - min[1], max[2] - min[2]});
}

std::array<double, 3> ToolpathLayer::vertex(std::size_t index) const {
    return {xyz[3 * index], xyz[3 * index + 1], xyz[3 * index + 2]};
}

void ToolpathLayer::addSegment(const std::array<double, 3>& from, const std::array<double, 3>& to) {
    const float f[3] = {static_cast<float>(from[0]), static_cast<float>(from[1]),
                        static_cast<float>(from[2])};
    const std::size_t n = xyz.size();
    const bool continues =
        chainOpen_ && n >= 3 && xyz[n - 3] == f[0] && xyz[n - 2] == f[1] && xyz[n - 1] == f[2];
    if (!continues) {
        xyz.insert(xyz.end(), f, f + 3);
        bounds.add(from[0], from[1], from[2]);
    }
    segmentStart.push_back(static_cast<std::uint32_t>(xyz.size() / 3 - 1));
    for (double v : to)
        xyz.push_back(static_cast<float>(v));
    bounds.add(to[0], to[1], to[2]);
    chainOpen_ = true;
}

void ToolpathLayer::clear() {
    xyz.clear();
    segmentStart.clear();
    bounds = {};
    chainOpen_ = false;
}

std::size_t ToolpathLayer::memoryBytes() const {
    return xyz.capacity() * sizeof(float) + segmentStart.capacity() * sizeof(std::uint32_t);
}

std::pair<std::uint32_t, std::uint32_t> ToolpathGeometry::sceneRange(std::size_t move) const {
    const auto last = move + 1 < moves.size() ? moves[move + 1].firstScene
                                              : static_cast<std::uint32_t>(scene.segmentCount());
    return {moves[move].firstScene, last};
}

std::pair<std::uint32_t, std::uint32_t> ToolpathGeometry::developedRange(std::size_t move) const {
    const auto last = move + 1 < moves.size()
                          ? moves[move + 1].firstDeveloped
                          : static_cast<std::uint32_t>(developed.segmentCount());
    return {moves[move].firstDeveloped, last};
}

namespace {
/// Last move whose first segment (by `first`) is <= segment, if it contains it.
template <typename First>
long findMove(const std::vector<ToolpathMove>& moves, std::uint32_t segment, std::size_t count,
              First first) {
    if (segment >= count || moves.empty()) return -1;
    auto it =
        std::upper_bound(moves.begin(), moves.end(), segment,
                         [&](std::uint32_t s, const ToolpathMove& m) { return s < first(m); });
    if (it == moves.begin()) return -1;
    // Moves without segments share their first index with the next move: the
    // upper bound lands after all of them, on the one that owns the segment.
    return static_cast<long>(std::distance(moves.begin(), it)) - 1;
}
}  // namespace

ToolpathBounds ToolpathGeometry::cuttingBounds(bool developed) const {
    const ToolpathLayer& layer = developed ? this->developed : scene;
    ToolpathBounds box;
    for (std::size_t m = 0; m < moves.size(); ++m) {
        if (moves[m].kind == ToolpathKind::Rapid) continue;
        const auto [first, last] = developed ? developedRange(m) : sceneRange(m);
        for (std::uint32_t segment = first; segment < last; ++segment) {
            const std::size_t start = layer.segmentStart[segment];
            for (std::size_t v : {start, start + 1}) {
                const auto p = layer.vertex(v);
                box.add(p[0], p[1], p[2]);
            }
        }
    }
    return box;
}

long ToolpathGeometry::moveOfSceneSegment(std::uint32_t segment) const {
    return findMove(moves, segment, scene.segmentCount(),
                    [](const ToolpathMove& m) { return m.firstScene; });
}

long ToolpathGeometry::moveOfDevelopedSegment(std::uint32_t segment) const {
    return findMove(moves, segment, developed.segmentCount(),
                    [](const ToolpathMove& m) { return m.firstDeveloped; });
}

std::vector<std::uint32_t> ToolpathGeometry::movesOfBlock(int program, std::uint32_t block) const {
    std::vector<std::uint32_t> found;
    for (std::size_t i = 0; i < moves.size(); ++i)
        if (moves[i].block == block && moves[i].program == program)
            found.push_back(static_cast<std::uint32_t>(i));
    return found;
}

ToolpathFrame ToolpathGeometry::frameOf(std::size_t move) const {
    if (move >= moves.size() || moves[move].frame >= frames.size()) return {};
    return frames[moves[move].frame];
}

std::size_t ToolpathGeometry::memoryBytes() const {
    return moves.capacity() * sizeof(ToolpathMove) + frames.capacity() * sizeof(ToolpathFrame) +
           scene.memoryBytes() + developed.memoryBytes() + contour.memoryBytes() +
           developedContour.memoryBytes();
}

void ToolpathGeometry::clear() {
    moves.clear();
    frames.clear();
    scene.clear();
    developed.clear();
    contour.clear();
    developedContour.clear();
    cylinderRadius = 0.0;
    cylinderAxis = -1;
    cylinderFrom = cylinderTo = 0.0;
    truncated = false;
}

}  // namespace mtc::core
