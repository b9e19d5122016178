#include "cnc_core/removal/HeightField.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cnc_core/removal/SweptDisc.h"

namespace mtc::core::removal {

std::array<int, 2> cellsWithin(double lo, double hi, double origin, double step, int count) {
    const double first = std::ceil((lo - origin) / step - 0.5);
    const double last = std::floor((hi - origin) / step - 0.5);
    if (!(first <= last) || !(last >= 0.0) || !(first <= count - 1.0)) return {1, 0};
    // Clipped as doubles before the conversion: a coordinate of 1e300 is fine.
    return {static_cast<int>(std::max(first, 0.0)), static_cast<int>(std::min(last, count - 1.0))};
}

HeightField::HeightField(const Box& stock, int columns, int rows)
    : stock_(stock),
      columns_(std::max(columns, 1)),
      rows_(std::max(rows, 1)),
      width_((stock.max[0] - stock.min[0]) / columns_),
      depth_((stock.max[1] - stock.min[1]) / rows_),
      heights_(static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_),
               static_cast<float>(stock.max[2])) {}

std::array<int, 2> HeightField::rowsReached(const std::array<double, 3>& a,
                                            const std::array<double, 3>& b, double radius,
                                            double top) const {
    for (std::size_t k = 0; k < 3; ++k)
        if (!std::isfinite(a[k]) || !std::isfinite(b[k])) return {1, 0};
    if (!(radius >= 0.0) || !(std::min(a[2], b[2]) < top)) return {1, 0};  // above the top
    // Beside the block: no row needs scanning (the chords of a huge arc).
    if (std::max(a[0], b[0]) + radius < stock_.min[0] ||
        std::min(a[0], b[0]) - radius > stock_.max[0])
        return {1, 0};
    return cellsWithin(std::min(a[1], b[1]) - radius, std::max(a[1], b[1]) + radius, stock_.min[1],
                       depth_, rows_);
}

bool HeightField::cut(const std::array<double, 3>& a, const std::array<double, 3>& b,
                      double radius) {
    const auto [first, last] = rowsReached(a, b, radius, stock_.max[2]);
    if (first > last) return false;
    const SweptDisc disc{a[0], a[1], b[0], b[1], radius};
    const SweptRowScanner scanner(disc);
    bool removed = false;
    for (int j = first; j <= last; ++j)
        removed = cutRow(j, disc, scanner.row(rowY(j)), a[2], b[2]) || removed;
    return removed;
}

double HeightField::faceOver(int i, int j, const SweptDisc& disc, double za, double zb) const {
    const Span t = coveringPositions(disc, columnX(i), rowY(j));
    if (t.empty()) return std::numeric_limits<double>::infinity();
    const double z = std::min(za + (zb - za) * t.lo, za + (zb - za) * t.hi);
    return std::max(z, std::min(stock_.min[2], stock_.max[2]));
}

bool HeightField::touches(const std::array<double, 3>& a, const std::array<double, 3>& b,
                          double radius, double margin) const {
    const auto [first, last] = rowsReached(a, b, radius, stock_.max[2] + std::max(margin, 0.0));
    const SweptDisc disc{a[0], a[1], b[0], b[1], radius};
    const SweptRowScanner scanner(disc);
    const double bottom = std::min(stock_.min[2], stock_.max[2]);
    for (int j = first; j <= last; ++j) {
        const Span row = scanner.row(rowY(j));
        if (row.empty()) continue;
        const auto [from, to] = cellsWithin(row.lo, row.hi, stock_.min[0], width_, columns_);
        for (int i = from; i <= to; ++i) {
            const double h = height(i, j);
            if (!(h > bottom)) continue;  // cut through: nothing left to touch
            // As cutRow(): a level sweep has one face for every covered cell.
            const double face =
                a[2] == b[2] ? std::max(a[2], bottom) : faceOver(i, j, disc, a[2], b[2]);
            if (!(face < h + margin)) continue;
            // Met already where the sweep starts: contact only deeper than there.
            const double dx = columnX(i) - a[0], dy = rowY(j) - a[1];
            const double startFace = std::max(a[2], bottom);
            const bool atStart = dx * dx + dy * dy <= radius * radius && startFace < h + margin;
            if (!atStart || face < startFace - std::fabs(margin)) return true;
        }
    }
    return false;
}

bool HeightField::cutRow(int j, const SweptDisc& disc, const Span& row, double za, double zb) {
    if (row.empty()) return false;
    const auto [first, last] = cellsWithin(row.lo, row.hi, stock_.min[0], width_, columns_);
    if (first > last) return false;
    float* heights = heights_.data() + static_cast<std::size_t>(j) * columns_;
    const double bottom = std::min(stock_.min[2], stock_.max[2]);
    if (za == zb) {  // level: one face height for the whole row (the common case)
        const float face = static_cast<float>(std::max(za, bottom));
        int lowered = 0;
        for (int i = first; i <= last; ++i) {  // branch-free: the compiler vectorises it
            lowered += face < heights[i] ? 1 : 0;
            heights[i] = face < heights[i] ? face : heights[i];
        }
        return lowered > 0;
    }
    // A ramp: each cell drops to the lowest face position that covers its centre.
    bool removed = false;
    for (int i = first; i <= last; ++i) {
        const float face = static_cast<float>(faceOver(i, j, disc, za, zb));
        if (face < heights[i]) {
            heights[i] = face;
            removed = true;
        }
    }
    return removed;
}

double HeightField::removedVolume() const {
    const double top = static_cast<float>(stock_.max[2]);  // as the cells hold it
    double sum = 0.0;
    for (float h : heights_)
        sum += top - static_cast<double>(h);
    return sum * width_ * depth_;
}

}  // namespace mtc::core::removal
