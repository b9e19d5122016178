#include "cnc_core/contour/Geometry2D.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "cnc_core/geometry/ArcSweep.h"
#include "cnc_core/language/CheckedNumber.h"

namespace mtc::core::gne {
namespace {

std::vector<Point> lineLine(const Locus& a, const Locus& b, bool* same) {
    Eigen::Matrix2d m;
    m.col(0) = a.direction;
    m.col(1) = -b.direction;
    if (std::fabs(m.determinant()) < 1e-12) {
        if (same) *same = std::fabs(cross(a.direction, b.point - a.point)) < kTolerance;
        return {};
    }
    const Eigen::Vector2d t = m.partialPivLu().solve(b.point - a.point);
    return {a.point + t[0] * a.direction};
}

std::vector<Point> lineCircle(const Locus& l, const Locus& c) {
    const Point foot = l.point + l.direction * l.direction.dot(c.point - l.point);
    const double d = (foot - c.point).norm();
    if (d > c.radius + kTolerance) return {};
    const double h = std::sqrt(std::max(0.0, c.radius * c.radius - d * d));
    if (h < kTolerance) return {foot};
    return {foot - h * l.direction, foot + h * l.direction};
}

std::vector<Point> circleCircle(const Locus& a, const Locus& b, bool* same) {
    const Point delta = b.point - a.point;
    const double d = delta.norm();
    if (d < kTolerance) {
        if (same) *same = std::fabs(a.radius - b.radius) < kTolerance;
        return {};
    }
    if (d > a.radius + b.radius + kTolerance || d < std::fabs(a.radius - b.radius) - kTolerance)
        return {};
    const double along = (d * d + a.radius * a.radius - b.radius * b.radius) / (2.0 * d);
    const double h = std::sqrt(std::max(0.0, a.radius * a.radius - along * along));
    const Point u = delta / d;
    const Point base = a.point + along * u;
    if (h < kTolerance) return {base};
    return {base + h * leftNormal(u), base - h * leftNormal(u)};
}

}  // namespace

bool Locus::contains(const Point& p, double tolerance) const {
    if (circle) return std::fabs((p - point).norm() - radius) <= tolerance;
    return std::fabs(cross(direction, p - point)) <= tolerance;
}

std::vector<Point> intersect(const Locus& a, const Locus& b, bool* same) {
    if (same) *same = false;
    std::vector<Point> points = !a.circle && !b.circle ? lineLine(a, b, same)
                                : !a.circle            ? lineCircle(a, b)
                                : !b.circle            ? lineCircle(b, a)
                                                       : circleCircle(a, b, same);
    std::sort(points.begin(), points.end(), [](const Point& p, const Point& q) {
        if (std::fabs(p.x() - q.x()) > kTolerance) return p.x() < q.x();
        return p.y() < q.y();
    });
    return points;
}

Point direction(double degrees) {
    const double a = degrees * kPi / 180.0;
    return Point(std::cos(a), std::sin(a));
}

double Segment::sweep() const {
    if (!isArc()) return 0.0;
    // Constructed contour geometry: a full circle only when the end lies in
    // the start's direction (the contour's full circles end where they start).
    return std::fabs(arcSweep(start.x(), start.y(), end.x(), end.y(), centre.x(), centre.y(),
                              kind == ArcCW, false));
}

double Segment::length() const {
    return isArc() ? radius() * sweep() : (end - start).norm();
}

Point Segment::startTangent() const {
    if (!isArc()) return (end - start).normalized();
    const Point n = leftNormal((start - centre).normalized());
    return kind == ArcCCW ? n : Point(-n);
}

Point Segment::endTangent() const {
    if (!isArc()) return (end - start).normalized();
    const Point n = leftNormal((end - centre).normalized());
    return kind == ArcCCW ? n : Point(-n);
}

Point Segment::at(double t) const {
    if (!isArc()) return start + t * (end - start);
    const double a = (kind == ArcCCW ? 1.0 : -1.0) * sweep() * t;
    const Point u = start - centre;
    return centre + Point(u.x() * std::cos(a) - u.y() * std::sin(a),
                          u.x() * std::sin(a) + u.y() * std::cos(a));
}

Segment Segment::reversed() const {
    Segment r = *this;
    std::swap(r.start, r.end);
    if (kind == ArcCW)
        r.kind = ArcCCW;
    else if (kind == ArcCCW)
        r.kind = ArcCW;
    return r;
}

std::vector<Point> tessellate(const std::vector<Segment>& path, double chordError) {
    std::vector<Point> points;
    if (path.empty()) return points;
    points.push_back(path.front().start);
    for (const Segment& s : path) {
        int pieces = 1;
        if (s.isArc()) {
            const double r = s.radius();
            const double step = r > chordError ? 2.0 * std::acos(1.0 - chordError / r) : kPi / 4;
            pieces = clampedInteger(std::ceil(s.sweep() / step), 2, 2000);
        }
        for (int i = 1; i <= pieces; ++i)
            points.push_back(s.at(static_cast<double>(i) / pieces));
        points.back() = s.end;
    }
    return points;
}

double distanceTo(const Segment& s, const Point& p) {
    if (!s.isArc()) {
        const Point d = s.end - s.start;
        const double len2 = d.squaredNorm();
        const double t = len2 > 0 ? std::clamp((p - s.start).dot(d) / len2, 0.0, 1.0) : 0.0;
        return (s.start + t * d - p).norm();
    }
    const Point u = p - s.centre;
    const Segment probe{s.kind, s.start, s.centre + u.normalized() * s.radius(), s.centre, -1};
    const bool inside = u.norm() > 1e-12 && probe.sweep() <= s.sweep() + 1e-12;
    if (inside) return std::fabs(u.norm() - s.radius());
    return std::min((p - s.start).norm(), (p - s.end).norm());
}

}  // namespace mtc::core::gne
