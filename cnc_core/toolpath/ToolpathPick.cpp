#include "cnc_core/toolpath/ToolpathPick.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace mtc::core {

namespace {

/// Distance on the screen from (x, y) to the segment between pixels a and b.
double pixelDistance(const std::array<double, 2>& a, const std::array<double, 2>& b, double x,
                     double y) {
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    const double lengthSquared = dx * dx + dy * dy;
    const double t = lengthSquared > 0.0
                         ? std::clamp(((x - a[0]) * dx + (y - a[1]) * dy) / lengthSquared, 0.0, 1.0)
                         : 0.0;
    return std::hypot(a[0] + t * dx - x, a[1] + t * dy - y);
}

double vertexDistance(const ToolpathLayer& layer, const ScreenProjection& view, std::uint32_t from,
                      std::uint32_t to, double x, double y) {
    return pixelDistance(view.pixel(layer.xyz.data() + 3 * static_cast<std::size_t>(from)),
                         view.pixel(layer.xyz.data() + 3 * static_cast<std::size_t>(to)), x, y);
}

/// Pixels per layer unit: the screen length of a unit step along each axis
/// (the largest, so the tolerance in pixels is never underestimated).
double pixelsPerUnit(const ScreenProjection& view, const float* at) {
    const auto origin = view.pixel(at);
    double most = 0.0;
    for (std::size_t axis = 0; axis < 3; ++axis) {
        float step[3] = {at[0], at[1], at[2]};
        step[axis] += 1.0f;
        const auto p = view.pixel(step);
        most = std::max(most, std::hypot(p[0] - origin[0], p[1] - origin[1]));
    }
    return most;
}

}  // namespace

std::array<double, 2> ScreenProjection::pixel(const float* xyz) const {
    double ndc[4];
    for (std::size_t row = 0; row < 4; ++row)
        ndc[row] = toNdc[4 * row] * xyz[0] + toNdc[4 * row + 1] * xyz[1] +
                   toNdc[4 * row + 2] * xyz[2] + toNdc[4 * row + 3];
    const double w = std::abs(ndc[3]) > 1e-12 ? ndc[3] : 1e-12;
    return {originX + (ndc[0] / w + 1.0) / 2.0 * width,
            originY + (ndc[1] / w + 1.0) / 2.0 * height};
}

std::optional<std::uint32_t> pickSegment(const ToolpathLayer& layer, const DecimatedLayer& coarse,
                                         const ScreenProjection& view, double x, double y,
                                         double maxPixels) {
    double best = std::numeric_limits<double>::infinity();
    std::uint32_t found = 0;
    auto measure = [&](std::uint32_t first, std::uint32_t last) {
        for (std::uint32_t s = first; s < last; ++s) {
            const std::uint32_t v = layer.segmentStart[s];
            const double d = vertexDistance(layer, view, v, v + 1, x, y);
            if (d < best) {
                best = d;
                found = s;
            }
        }
    };
    if (coarse.cellCount() == 0 || coarse.dropped) {
        measure(0, static_cast<std::uint32_t>(layer.segmentCount()));
    } else {
        const double slack = std::isfinite(coarse.tolerance) && layer.vertexCount() > 0
                                 ? coarse.tolerance * pixelsPerUnit(view, layer.xyz.data())
                                 : std::numeric_limits<double>::infinity();
        std::vector<std::pair<double, std::uint32_t>> cells(coarse.cellCount());
        for (std::size_t i = 0; i < coarse.cellCount(); ++i)
            cells[i] = {
                vertexDistance(layer, view, coarse.ends[2 * i], coarse.ends[2 * i + 1], x, y),
                static_cast<std::uint32_t>(i)};
        std::sort(cells.begin(), cells.end());
        for (const auto& [distance, cell] : cells) {
            if (distance - slack > std::min(best, maxPixels)) break;
            const auto [first, last] = coarse.segmentsOf(cell);
            measure(first, last);
        }
    }
    if (best > maxPixels) return std::nullopt;
    return found;
}

}  // namespace mtc::core
