#pragma once

// 2D geometry of the GNE (plane coordinates, 1st axis = x, 2nd axis = y):
// loci (lines and circles) with their intersections, and path segments
// (lines and arcs) with tessellation. Eigen only.

#include <Eigen/Core>
#include <vector>

namespace mtc::core::gne {

using Point = Eigen::Vector2d;

/// Length tolerance of the solver and the expansion (mm).
constexpr double kTolerance = 1e-6;
constexpr double kPi = 3.14159265358979323846;

/// A set of points a junction must lie on: a straight line (point + unit
/// direction) or a circle (centre + radius).
struct Locus {
    bool circle = false;
    Point point = Point::Zero();  ///< line: a point on it; circle: centre
    Point direction = Point::UnitX();
    double radius = 0.0;

    static Locus line(const Point& p, const Point& dir) {
        return {false, p, dir.normalized(), 0.0};
    }
    static Locus around(const Point& c, double r) { return {true, c, Point::UnitX(), r}; }
    /// True when `p` lies on the locus within `tolerance`.
    bool contains(const Point& p, double tolerance = 1e-4) const;
};

/// The intersection points of two loci, sorted by 1st then 2nd coordinate
/// (touching = one point). Coincident loci give no points and set `same`.
std::vector<Point> intersect(const Locus& a, const Locus& b, bool* same = nullptr);

/// Unit direction of an angle in degrees (from the 1st axis, counter-clockwise).
Point direction(double degrees);
/// Left normal (rotated +90 degrees).
inline Point leftNormal(const Point& d) {
    return Point(-d.y(), d.x());
}
/// z component of the cross product.
inline double cross(const Point& a, const Point& b) {
    return a.x() * b.y() - a.y() * b.x();
}

/// A solved piece of path: a straight line or an arc from `start` to `end`.
struct Segment {
    enum Kind { Line, ArcCW, ArcCCW } kind = Line;
    Point start = Point::Zero();
    Point end = Point::Zero();
    Point centre = Point::Zero();  ///< arcs only
    int source = -1;               ///< index of the contour element it comes from

    bool isArc() const { return kind != Line; }
    double radius() const { return (start - centre).norm(); }
    /// Swept angle in radians, positive, (0, 2pi]; 0 for lines.
    double sweep() const;
    double length() const;
    /// Unit tangent in travel direction at the start / end.
    Point startTangent() const;
    Point endTangent() const;
    /// Point at the parameter t in [0, 1] along the segment.
    Point at(double t) const;
    /// The same segment travelled backwards.
    Segment reversed() const;
};

/// Points along the segments, every arc split so that the chord error stays
/// below `chordError`; first point = first start, last = last end.
std::vector<Point> tessellate(const std::vector<Segment>& path, double chordError = 0.01);

/// Distance of `p` to a segment.
double distanceTo(const Segment& s, const Point& p);

}  // namespace mtc::core::gne
