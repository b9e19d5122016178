#pragma once

// Plane geometry of tool radius compensation: a line or an arc of the
// working plane (1st axis = x, 2nd axis = y, mm), its offset by the tool
// radius, and the intersections of two of them. Eigen only.

#include <Eigen/Core>

namespace mtc::core::comp {

using Vec2 = Eigen::Vector2d;

/// Two points closer than this are one point (mm).
inline constexpr double kSamePoint = 1e-7;

enum class PathKind : unsigned char { Line, ArcCw, ArcCcw };

/// A line or a circular arc in the plane. Arcs run from `start` to `end`
/// around `centre`; clockwise (G2) or counter-clockwise (G3) in the
/// (1st axis, 2nd axis) frame, as the interpreter defines them.
struct PlanePath {
    PathKind kind = PathKind::Line;
    Vec2 start = Vec2::Zero();
    Vec2 end = Vec2::Zero();
    Vec2 centre = Vec2::Zero();
    bool fullCircle = false;  ///< an arc whose start and end coincide: one whole turn

    bool isArc() const { return kind != PathKind::Line; }
    /// +1 counter-clockwise, -1 clockwise (arcs).
    double turn() const { return kind == PathKind::ArcCcw ? 1.0 : -1.0; }
    double radius() const { return (start - centre).norm(); }
    /// Swept angle of an arc in radians, (0, 2pi]; 0 for a line.
    double sweep() const;
    double length() const;
    /// True when the path has no direction (a line shorter than kSamePoint).
    bool degenerate() const;
    /// Unit tangent in travel direction at the start / at the end.
    Vec2 startTangent() const;
    Vec2 endTangent() const;
    /// Where `point` lies along the path: 0 at the start, 1 at the end
    /// (lines: projection; arcs: swept angle from the start over the sweep,
    /// in [0, 2pi / sweep)). The point is assumed to lie on the carrier.
    double parameterOf(const Vec2& point) const;
};

/// Left normal (the tangent rotated by +90 degrees).
inline Vec2 leftNormal(const Vec2& t) {
    return Vec2(-t.y(), t.x());
}
/// z component of the cross product.
inline double cross(const Vec2& a, const Vec2& b) {
    return a.x() * b.y() - a.y() * b.x();
}

/// The path moved by `distance` to its left (distance > 0) or right (< 0):
/// a line parallel, an arc concentric with the radius grown or shrunk.
/// False when an arc would shrink to (nearly) nothing: the tool radius is
/// not smaller than the radius of an arc it must follow on the inside.
bool offsetPath(const PlanePath& path, double distance, PlanePath& out);

/// Intersection points of the carriers of `a` and `b` (the whole line, the
/// whole circle): 0, 1 or 2 points into `out`; returns how many.
int carrierIntersections(const PlanePath& a, const PlanePath& b, Vec2 out[2]);

/// True when `a` and `b` cross at a point strictly inside both (parameters
/// in (margin, 1 - margin)); that point goes to `where`.
bool pathsCross(const PlanePath& a, const PlanePath& b, Vec2& where, double margin = 1e-6);

}  // namespace mtc::core::comp
