#pragma once

#include <Eigen/Core>

/// Exact plane geometry of chamfers and roundings (seed 001, ch. 2) between
/// lines and circular arcs. Coordinates are the two axes of the active
/// plane (1st plane axis, 2nd plane axis); G2 is clockwise in that frame.
namespace mtc::core {

using Point2 = Eigen::Vector2d;

/// A line or a circular arc of the programmed path, parametrised by path
/// length s in [0, length()].
struct PathElement {
    bool arc = false;
    bool ccw = false;  ///< arcs: G3 (counter-clockwise)
    Point2 start = Point2::Zero();
    Point2 end = Point2::Zero();
    Point2 center = Point2::Zero();  ///< arcs
    double radius = 0.0;             ///< arcs: distance centre-start
    /// Arcs: one whole turn (closesCircle() of a programmed block, D-016;
    /// never set for a constructed rounding).
    bool fullCircle = false;

    /// A line from `from` to `to`.
    static PathElement line(const Point2& from, const Point2& to);
    /// An arc from `from` to `to` around `centre` (radius from the start).
    static PathElement circle(const Point2& from, const Point2& to, const Point2& centre, bool ccw);

    /// Swept angle of an arc in (0, 2 pi] (arcSweep(), D-016).
    double sweep() const;
    double length() const;
    /// The point at path length s.
    Point2 pointAt(double s) const;
    /// Unit tangent in the direction of travel at path length s.
    Point2 tangentAt(double s) const;
    /// Path length of `p` (a point on the element's line or circle): lines by
    /// projection, arcs by the angle from the start in the direction of travel.
    double parameterOf(const Point2& p) const;
};

/// What to insert at a corner.
enum class CornerKind { Chamfer, Rounding };

/// The result of fitting a chamfer or rounding between `a` (ends at the
/// corner) and `b` (starts there).
struct CornerFit {
    double applied = 0.0;            ///< width / radius inserted (0: nothing inserted)
    bool reduced = false;            ///< applied < requested
    Point2 pointA = Point2::Zero();  ///< new end of `a` = start of the inserted element
    Point2 pointB = Point2::Zero();  ///< new start of `b` = end of the inserted element
    double parameterA = 0.0;         ///< path length of pointA on `a`
    Point2 center = Point2::Zero();  ///< rounding: centre of the inserted arc
    bool ccw = false;                ///< rounding: G3 when true, else G2
};

/// Fits a chamfer (width = distance removed from both elements, measured
/// along each element from the corner) or a rounding (tangent arc of the
/// given radius) of `requested` size between `a` and `b`. `a` may only be
/// shortened down to path length `aMinimum` (an earlier corner used the rest);
/// `b` may be shortened down to its full length. When the requested size does
/// not fit, the largest size that fits (0.0001 steps, possibly 0) is applied
/// (seed 001, ch. 2 note), found by bisection: at most 64 probes whatever
/// the requested size (a loop over the size would never end for 1e23). A corner without a bend
/// (tangent continuation) or a reversal takes 0.
CornerFit fitCorner(CornerKind kind, const PathElement& a, double aMinimum, const PathElement& b,
                    double requested);

}  // namespace mtc::core
