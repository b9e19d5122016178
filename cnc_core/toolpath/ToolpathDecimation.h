#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "cnc_core/toolpath/ToolpathGeometry.h"

namespace mtc::core {

/// A coarser copy of one layer for drawing while the view moves. Each cell
/// is a straight line between two vertices of the layer that stands for a
/// run of consecutive segments of one chain and one kind; every vertex left
/// out lies within `tolerance` of its cell. Cell i stands for the full
/// segments [firstSegment[i], firstSegment[i] + (ends[2i+1] - ends[2i])).
struct DecimatedLayer {
    std::vector<std::uint32_t> ends;          ///< 2 layer vertex indices per cell
    std::vector<std::uint32_t> firstSegment;  ///< first full segment of each cell
    std::vector<ToolpathKind> kinds;          ///< colour class of each cell
    double tolerance = 0.0;  ///< deviation the cells keep (mm); grows to meet the budget
    bool dropped = false;    ///< runs were left out to meet the budget (see TP-010)

    std::size_t cellCount() const { return kinds.size(); }
    /// Full segments [first, last) that cell `cell` stands for.
    std::pair<std::uint32_t, std::uint32_t> segmentsOf(std::size_t cell) const;
};

/// Simplifies layer `developed ? g.developed : g.scene` (Douglas-Peucker per
/// run of one chain and one move kind) with `tolerance` (mm), doubling the
/// tolerance until at most `budget` cells remain, but not beyond 1/20 of the
/// layer's extent: then every n-th run is kept at that tolerance (a path
/// that retraces itself). When even one cell per run is over the budget,
/// runs of different kinds on a chain are joined (first kind's colour) and,
/// as the last resort, every n-th run is kept as one cell.
DecimatedLayer decimateLayer(const ToolpathGeometry& g, bool developed, double tolerance,
                             std::size_t budget);

/// Distance of `point` from the straight segment a-b.
double distanceToSegment(const std::array<double, 3>& point, const std::array<double, 3>& a,
                         const std::array<double, 3>& b);

}  // namespace mtc::core
