#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace mtc::core::lookahead {

/// Most axes a look-ahead polygon may move (X Y Z U V W A B C).
constexpr int kMaxLookAheadAxes = 9;

/// Axis positions of one point, one entry per axis of the polygon's axis
/// table (AxisLimits order). Fixed capacity: no heap allocation per point.
using AxisVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxLookAheadAxes, 1>;

/// Motion of one polygon element.
enum class ElementKind { Line, ArcCw, ArcCcw };

/// Which source block an element (or a generated element) belongs to.
struct BlockRef {
    int blockIndex = -1;  ///< index of the source block in its program (-1 = none)
    int number = -1;      ///< N number of the source block, -1 = none
    int line = 0;         ///< 1-based source line
};

/// One element of the polygon of an LA_ON ... LA_OFF segment: a straight
/// line, or a circular arc in the active plane (other axes move linearly
/// with the arc: helix). Units: mm (deg for rotary axes), feeds in mm/min.
struct PathElement {
    ElementKind kind = ElementKind::Line;
    AxisVector start;         ///< start point, every axis
    AxisVector end;           ///< end point, every axis
    AxisVector center;        ///< arcs: centre (only the two plane components are used)
    int planeFirst = 0;       ///< arcs: axis index of the plane's first axis (X for G17)
    int planeSecond = 1;      ///< arcs: axis index of the plane's second axis (Y for G17)
    bool fullCircle = false;  ///< arcs: one whole turn (closesCircle() of the block, D-016)
    double feed = 0.0;        ///< programmed path velocity F, mm/min (> 0)
    /// Axis velocities programmed with F<axis>= (mm/min); 0 = none for that axis.
    AxisVector axisFeed;
    double accelerationFactor = 1.0;  ///< ACC_EFF / 100 (0.01 .. 2.0)
    BlockRef ref;                     ///< the source block
    /// 0 = the programmed block itself; > 0 = an element the look-ahead
    /// generated (TRC corner arc, approach or retract line).
    int generated = 0;
};

/// Per-axis machine limits, in axis table order.
struct AxisLimits {
    std::vector<std::string> names;  ///< axis names as written in programs ("X", "Z1")
    AxisVector maxVelocity;          ///< mm/min (deg/min)
    AxisVector maxAcceleration;      ///< mm/s^2 (deg/s^2)
    int size() const { return static_cast<int>(names.size()); }
    /// Index of the axis called `name`, or -1.
    int indexOf(const std::string& name) const;
};

/// Global variables of the enhanced look-ahead function (seed 001 ch. 6)
/// that the planner uses.
struct LookAheadParameters {
    double metbMs = 5.0;          ///< minimum execution time of a block, 3..30 ms
    double vfbt = 1.0;            ///< velocity factor for block transitions, 1..10
    double blockCycleMs = 2.0;    ///< NC block cycle time (METB must exceed it)
    int maxSubBlocksPerRamp = 8;  ///< upper bound of sub-blocks per acceleration phase
};

}  // namespace mtc::core::lookahead
