#include "cnc_core/compiler/CornerGeometry.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "cnc_core/geometry/ArcSweep.h"

namespace mtc::core {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kEpsilon = 1e-9;
constexpr double kStep = 1e-4;  // applied sizes are multiples of 0.0001
/// The largest step count the bisection considers (2^40 steps = 1.1e8 mm),
/// so that the count stays exact in a double and an int64.
constexpr double kMaxCornerSteps = 1099511627776.0;

/// (x, y) turned by +90 degrees.
Point2 leftOf(const Point2& v) {
    return Point2(-v.y(), v.x());
}
double cross(const Point2& a, const Point2& b) {
    return a.x() * b.y() - a.y() * b.x();
}

/// Angle of `v` from `from`, counter-clockwise, in [0, 2 pi).
double angleBetween(const Point2& from, const Point2& v) {
    double angle = std::atan2(cross(from, v), from.dot(v));
    if (angle < 0.0) angle += 2.0 * kPi;
    return angle;
}

/// An offset curve: a line (point + direction) or a circle (centre, radius).
struct Offset {
    bool circle = false;
    Point2 point = Point2::Zero();      ///< line: a point; circle: centre
    Point2 direction = Point2::Zero();  ///< line: unit direction
    double radius = 0.0;
};

/// `e` moved by `distance` to its left (in the direction of travel).
bool offsetOf(const PathElement& e, double distance, Offset& out) {
    if (!e.arc) {
        const Point2 d = (e.end - e.start).normalized();
        out = {false, e.start + leftOf(d) * distance, d, 0.0};
        return true;
    }
    const double r = e.ccw ? e.radius - distance : e.radius + distance;
    out = {true, e.center, Point2::Zero(), r};
    return r > kEpsilon;
}

/// Intersections of two offset curves (0, 1 or 2 points).
int intersect(const Offset& p, const Offset& q, std::array<Point2, 2>& points) {
    if (!p.circle && !q.circle) {
        const double det = cross(p.direction, q.direction);
        if (std::fabs(det) < kEpsilon) return 0;
        const double t = cross(q.point - p.point, q.direction) / det;
        points[0] = p.point + p.direction * t;
        return 1;
    }
    if (p.circle != q.circle) {
        const Offset& line = p.circle ? q : p;
        const Offset& circle = p.circle ? p : q;
        const Point2 foot =
            line.point + line.direction * line.direction.dot(circle.point - line.point);
        const double h2 = circle.radius * circle.radius - (foot - circle.point).squaredNorm();
        if (h2 < -kEpsilon) return 0;
        const double h = std::sqrt(std::max(0.0, h2));
        points[0] = foot + line.direction * h;
        points[1] = foot - line.direction * h;
        return 2;
    }
    const Point2 delta = q.point - p.point;
    const double d = delta.norm();
    if (d < kEpsilon) return 0;
    const double a = (p.radius * p.radius - q.radius * q.radius + d * d) / (2.0 * d);
    const double h2 = p.radius * p.radius - a * a;
    if (h2 < -kEpsilon) return 0;
    const double h = std::sqrt(std::max(0.0, h2));
    const Point2 base = p.point + delta * (a / d);
    const Point2 across = leftOf(delta / d);
    points[0] = base + across * h;
    points[1] = base - across * h;
    return 2;
}

/// The point of `e`'s line or circle nearest to `c` (the tangency point of a
/// circle around `c` that touches `e`).
Point2 footOn(const PathElement& e, const Point2& c) {
    if (!e.arc) {
        const Point2 d = (e.end - e.start).normalized();
        return e.start + d * d.dot(c - e.start);
    }
    return e.center + (c - e.center).normalized() * e.radius;
}

/// The corner's turn: +1 left, -1 right, 0 no bend or a reversal.
int turnAt(const PathElement& a, const PathElement& b) {
    const Point2 ta = a.tangentAt(a.length()), tb = b.tangentAt(0.0);
    const double c = cross(ta, tb);
    if (std::fabs(c) < 1e-9) return 0;
    return c > 0.0 ? 1 : -1;
}

bool within(double s, double low, double high) {
    return s >= low - 1e-7 && s <= high + 1e-7;
}

/// The rounding of radius r if it fits, else false.
bool tryRounding(const PathElement& a, double aMinimum, const PathElement& b, double r,
                 CornerFit& fit) {
    const int turn = turnAt(a, b);
    if (turn == 0) return false;
    Offset oa, ob;
    if (!offsetOf(a, turn * r, oa) || !offsetOf(b, turn * r, ob)) return false;
    std::array<Point2, 2> candidates;
    const int n = intersect(oa, ob, candidates);
    if (n == 0) return false;
    const Point2 corner = a.end;
    Point2 c = candidates[0];
    if (n == 2 && (candidates[1] - corner).norm() < (c - corner).norm()) c = candidates[1];
    const Point2 pa = footOn(a, c), pb = footOn(b, c);
    const double sa = a.parameterOf(pa), sb = b.parameterOf(pb);
    if (!within(sa, aMinimum, a.length()) || !within(sb, 0.0, b.length())) return false;
    fit = {r, false, pa, pb, sa, c, turn > 0};
    return true;
}

bool tryChamfer(const PathElement& a, double aMinimum, const PathElement& b, double w,
                CornerFit& fit) {
    if (turnAt(a, b) == 0) return false;
    const double sa = a.length() - w;
    if (!within(sa, aMinimum, a.length()) || !within(w, 0.0, b.length())) return false;
    fit = {w, false, a.pointAt(sa), b.pointAt(w), sa, Point2::Zero(), false};
    return true;
}

bool tryCorner(CornerKind kind, const PathElement& a, double aMinimum, const PathElement& b,
               double size, CornerFit& fit) {
    return kind == CornerKind::Chamfer ? tryChamfer(a, aMinimum, b, size, fit)
                                       : tryRounding(a, aMinimum, b, size, fit);
}

}  // namespace

PathElement PathElement::line(const Point2& from, const Point2& to) {
    PathElement e;
    e.start = from;
    e.end = to;
    return e;
}

PathElement PathElement::circle(const Point2& from, const Point2& to, const Point2& centre,
                                bool ccw) {
    PathElement e;
    e.arc = true;
    e.ccw = ccw;
    e.start = from;
    e.end = to;
    e.center = centre;
    e.radius = (from - centre).norm();
    return e;
}

double PathElement::sweep() const {
    return std::abs(
        arcSweep(start.x(), start.y(), end.x(), end.y(), center.x(), center.y(), !ccw, fullCircle));
}

double PathElement::length() const {
    return arc ? radius * sweep() : (end - start).norm();
}

Point2 PathElement::pointAt(double s) const {
    if (!arc) {
        const double l = length();
        return l < kEpsilon ? start : start + (end - start) * (s / l);
    }
    const double angle = (ccw ? 1.0 : -1.0) * s / radius;
    return center + Eigen::Rotation2Dd(angle) * (start - center);
}

Point2 PathElement::tangentAt(double s) const {
    if (!arc) return (end - start).normalized();
    const Point2 radial = (pointAt(s) - center).normalized();
    return ccw ? leftOf(radial) : Point2(-leftOf(radial));
}

double PathElement::parameterOf(const Point2& p) const {
    if (!arc) {
        const double l = length();
        return l < kEpsilon ? 0.0 : (p - start).dot(end - start) / l;
    }
    double angle = angleBetween(start - center, p - center);
    if (!ccw && angle > 0.0) angle = 2.0 * kPi - angle;
    if (angle > sweep() + 1e-9 && 2.0 * kPi - angle < 1e-9) angle = 0.0;
    return angle * radius;
}

CornerFit fitCorner(CornerKind kind, const PathElement& a, double aMinimum, const PathElement& b,
                    double requested) {
    CornerFit fit;
    fit.pointA = a.end;
    fit.pointB = b.start;
    fit.parameterA = a.length();
    if (!(requested > 0.0) || !std::isfinite(requested)) return fit;
    if (tryCorner(kind, a, aMinimum, b, requested, fit)) return fit;
    // Bisection over whole steps of 0.0001: `low` steps fit (0 = nothing),
    // `high` steps do not. The number of probes is the bit length of the
    // step count (at most 64), whatever the requested size.
    const double maximumSteps = std::min(std::ceil(requested / kStep), kMaxCornerSteps);
    std::int64_t low = 0, high = static_cast<std::int64_t>(maximumSteps);
    CornerFit reduced;
    while (high - low > 1) {
        const std::int64_t middle = low + (high - low) / 2;
        CornerFit probe;
        if (tryCorner(kind, a, aMinimum, b, static_cast<double>(middle) * kStep, probe)) {
            low = middle;
            reduced = probe;  // the fit of `low`
        } else {
            high = middle;
        }
    }
    if (low == 0) {
        fit.reduced = true;
        return fit;
    }
    reduced.applied = static_cast<double>(low) * kStep;
    reduced.reduced = true;
    return reduced;
}

}  // namespace mtc::core
