#include "cnc_core/removal/SweptDisc.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mtc::core::removal {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// The x range of the disc around (cx, cy) on the line y = `y`.
Span discRow(double cx, double cy, double radius, double y) {
    const double dy = y - cy;
    const double squared = radius * radius - dy * dy;
    if (!(squared >= 0.0)) return {};
    const double half = std::sqrt(squared);
    return {cx - half, cx + half};
}

/// The x values where `slope * x + offset` lies in [lo, hi] (slope may be 0).
Span linearRange(double slope, double offset, double lo, double hi) {
    if (slope == 0.0) return offset >= lo && offset <= hi ? Span{-kInfinity, kInfinity} : Span{};
    const double x1 = (lo - offset) / slope, x2 = (hi - offset) / slope;
    return {std::min(x1, x2), std::max(x1, x2)};
}

Span intersect(const Span& a, const Span& b) {
    return {std::max(a.lo, b.lo), std::min(a.hi, b.hi)};
}

/// The smallest range holding both (either may be empty).
Span hull(const Span& a, const Span& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)};
}

}  // namespace

Span sweptRow(const SweptDisc& d, double y) {
    Span row = hull(discRow(d.ax, d.ay, d.radius, y), discRow(d.bx, d.by, d.radius, y));
    const double dx = d.bx - d.ax, dy = d.by - d.ay;
    const double squared = dx * dx + dy * dy;
    const double length = std::sqrt(squared);
    if (!(length > 0.0) || !std::isfinite(squared)) return row;
    // The band between the two end discs: the projection on the chord lies in
    // [0, L^2] and the distance from the chord's line is at most the radius.
    const double ry = y - d.ay;
    const Span along = linearRange(dx, ry * dy - d.ax * dx, 0.0, squared);
    const Span across =
        linearRange(dy, -d.ax * dy - ry * dx, -d.radius * length, d.radius * length);
    const Span band = intersect(along, across);
    return hull(row, band);
}

Span coveringPositions(const SweptDisc& d, double px, double py) {
    const double dx = d.bx - d.ax, dy = d.by - d.ay;
    const double ex = d.ax - px, ey = d.ay - py;
    const double a = dx * dx + dy * dy;
    const double c = ex * ex + ey * ey - d.radius * d.radius;
    if (!(a > 0.0)) return c <= 0.0 ? Span{0.0, 1.0} : Span{};
    // |e + t d|^2 <= r^2  <=>  a t^2 + 2 h t + c <= 0
    const double h = dx * ex + dy * ey;
    const double discriminant = h * h - a * c;
    if (!(discriminant >= 0.0)) return {};
    const double root = std::sqrt(discriminant);
    return {std::max(0.0, (-h - root) / a), std::min(1.0, (-h + root) / a)};
}

}  // namespace mtc::core::removal
