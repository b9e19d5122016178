#pragma once

#include <array>
#include <vector>

#include "cnc_core/removal/SweptDisc.h"

namespace mtc::core::removal {

/// An axis-parallel box (mm): the raw part of a mill.
struct Box {
    std::array<double, 3> min{0, 0, 0};
    std::array<double, 3> max{0, 0, 0};
};

/// The mill's part as a height field (z-map): the block's X Y face is
/// tiled by columns x rows cells; each cell keeps the height of the material
/// at its centre, from the block's top down to its bottom. A flat end mill
/// standing along Z cuts it: wherever the cutter's disc covers a cell
/// centre, the cell's height drops to the cutter's face (never below the
/// bottom: the shank goes through). Decision D-020 in docs/DECISIONS.md.
class HeightField {
  public:
    /// Heights start at the top of `stock`; columns, rows >= 1.
    HeightField(const Box& stock, int columns, int rows);

    /// Sweeps a flat end mill of `radius` whose face centre moves on the
    /// straight line from `a` to `b` (X, Y, Z; Z may change: a ramp). Exact
    /// at the cell centres; the work is the number of cells the sweep covers
    /// (at most the whole grid), whatever the coordinates. Chords with a
    /// non-finite coordinate cut nothing. True when material was removed.
    bool cut(const std::array<double, 3>& a, const std::array<double, 3>& b, double radius);

    /// Would the same sweep reach material, without changing anything? True
    /// when at some cell that still has material (height above the bottom)
    /// the face would come below height + `margin`: a negative margin asks
    /// whether more than -margin would be cut, a positive one whether the
    /// face comes within `margin` of the surface (a touch). A cell the tool
    /// meets so where the sweep starts counts only where the sweep goes
    /// more than |margin| deeper (moving away from the material is no new
    /// contact). Work as cut().
    bool touches(const std::array<double, 3>& a, const std::array<double, 3>& b, double radius,
                 double margin) const;

    /// Material taken away so far (mm^3): sum of (top - height) x cell area.
    double removedVolume() const;

    const Box& stock() const { return stock_; }
    int columns() const { return columns_; }
    int rows() const { return rows_; }
    double cellWidth() const { return width_; }
    double cellDepth() const { return depth_; }
    /// Centre of column `i` (X) and row `j` (Y).
    double columnX(int i) const { return stock_.min[0] + (i + 0.5) * width_; }
    double rowY(int j) const { return stock_.min[1] + (j + 0.5) * depth_; }
    /// Height of the material at cell (i, j).
    double height(int i, int j) const {
        return heights_[static_cast<std::size_t>(j) * static_cast<std::size_t>(columns_) +
                        static_cast<std::size_t>(i)];
    }

  private:
    /// Lowers the cells of row `j` the sweep covers (`row`: its X range; the
    /// face moves from height `za` to `zb`); true when one was lowered.
    bool cutRow(int j, const SweptDisc& disc, const Span& row, double za, double zb);
    /// The rows a sweep of `radius` from `a` to `b` can reach ({1, 0}: none,
    /// also for a non-finite coordinate or a sweep above `top`).
    std::array<int, 2> rowsReached(const std::array<double, 3>& a, const std::array<double, 3>& b,
                                   double radius, double top) const;
    /// The lowest face over cell (i, j) while the disc covers its centre
    /// (the bottom at least; +infinity when it never does).
    double faceOver(int i, int j, const SweptDisc& disc, double za, double zb) const;

    Box stock_;
    int columns_;
    int rows_;
    double width_;  ///< cell size along X
    double depth_;  ///< cell size along Y
    std::vector<float> heights_;
};

/// The cells whose centres origin + (k + 0.5) step lie in [lo, hi], clipped
/// to 0 .. count - 1: {first, last}, first > last when none. Safe for huge
/// and infinite bounds (NaN gives none).
std::array<int, 2> cellsWithin(double lo, double hi, double origin, double step, int count);

}  // namespace mtc::core::removal
