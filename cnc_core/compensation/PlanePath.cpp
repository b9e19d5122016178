#include "cnc_core/compensation/PlanePath.h"

#include <algorithm>
#include <cmath>

#include "cnc_core/geometry/ArcSweep.h"

namespace mtc::core::comp {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// Angle from `from` to `to` around the arc's centre, in the arc's sense, [0, 2pi).
double angleAlong(const PlanePath& p, const Vec2& from, const Vec2& to) {
    const Vec2 a = from - p.centre, b = to - p.centre;
    double angle = p.turn() * std::atan2(cross(a, b), a.dot(b));
    if (angle < 0.0) angle += 2.0 * kPi;
    return angle;
}

}  // namespace

double PlanePath::sweep() const {
    if (!isArc()) return 0.0;
    return std::fabs(arcSweep(start.x(), start.y(), end.x(), end.y(), centre.x(), centre.y(),
                              kind == PathKind::ArcCw, fullCircle));
}

double PlanePath::length() const {
    return isArc() ? radius() * sweep() : (end - start).norm();
}

bool PlanePath::degenerate() const {
    return !isArc() && (end - start).norm() < kSamePoint;
}

Vec2 PlanePath::startTangent() const {
    if (!isArc()) return (end - start).normalized();
    return turn() * leftNormal((start - centre).normalized());
}

Vec2 PlanePath::endTangent() const {
    if (!isArc()) return (end - start).normalized();
    return turn() * leftNormal((end - centre).normalized());
}

double PlanePath::parameterOf(const Vec2& point) const {
    if (!isArc()) {
        const Vec2 d = end - start;
        const double squared = d.squaredNorm();
        return squared > 0.0 ? (point - start).dot(d) / squared : 0.0;
    }
    return angleAlong(*this, start, point) / sweep();
}

bool offsetPath(const PlanePath& path, double distance, PlanePath& out) {
    out = path;
    if (!path.isArc()) {
        const Vec2 shift = distance * leftNormal(path.startTangent());
        out.start += shift;
        out.end += shift;
        return true;
    }
    const double radius = path.radius() - path.turn() * distance;
    if (radius < kSamePoint) return false;
    out.start = path.centre + (path.start - path.centre).normalized() * radius;
    out.end = path.centre + (path.end - path.centre).normalized() * radius;
    return true;
}

int carrierIntersections(const PlanePath& a, const PlanePath& b, Vec2 out[2]) {
    if (!a.isArc() && !b.isArc()) {
        const Vec2 d = a.end - a.start, e = b.end - b.start;
        const double denominator = cross(d, e);
        if (std::abs(denominator) <= 1e-12 * d.norm() * e.norm()) return 0;  // parallel
        out[0] = a.start + d * (cross(b.start - a.start, e) / denominator);
        return 1;
    }
    if (!a.isArc() || !b.isArc()) {
        const PlanePath& line = a.isArc() ? b : a;
        const PlanePath& circle = a.isArc() ? a : b;
        const Vec2 d = (line.end - line.start).normalized();
        const double radius = circle.radius();
        const Vec2 foot = line.start + (circle.centre - line.start).dot(d) * d;
        const double h2 = radius * radius - (circle.centre - foot).squaredNorm();
        if (h2 < -1e-9 * radius) return 0;
        const double h = std::sqrt(std::max(0.0, h2));
        out[0] = foot - h * d;
        out[1] = foot + h * d;
        return h > 0.0 ? 2 : 1;
    }
    const double r1 = a.radius(), r2 = b.radius();
    const Vec2 between = b.centre - a.centre;
    const double distance = between.norm();
    if (distance < kSamePoint) return 0;  // concentric: no single crossing
    if (distance > r1 + r2 + 1e-9 || distance < std::abs(r1 - r2) - 1e-9) return 0;
    const double along = (distance * distance + r1 * r1 - r2 * r2) / (2.0 * distance);
    const double h = std::sqrt(std::max(0.0, r1 * r1 - along * along));
    const Vec2 u = between / distance;
    const Vec2 base = a.centre + along * u;
    out[0] = base + h * leftNormal(u);
    out[1] = base - h * leftNormal(u);
    return h > 0.0 ? 2 : 1;
}

bool pathsCross(const PlanePath& a, const PlanePath& b, Vec2& where, double margin) {
    Vec2 points[2];
    const int count = carrierIntersections(a, b, points);
    for (int i = 0; i < count; ++i) {
        const double u = a.parameterOf(points[i]), v = b.parameterOf(points[i]);
        if (u > margin && u < 1.0 - margin && v > margin && v < 1.0 - margin) {
            where = points[i];
            return true;
        }
    }
    return false;
}

}  // namespace mtc::core::comp
