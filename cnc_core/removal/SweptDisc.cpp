#include "cnc_core/removal/SweptDisc.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mtc::core::removal {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// The x values where `slope * x + offset` lies in [lo, hi], given the
/// slope's reciprocal `inverse` (0: a slope of 0, or one too small to invert:
/// every x or none).
Span linearRangeBy(double inverse, double offset, double lo, double hi) {
    if (inverse == 0.0) return offset >= lo && offset <= hi ? Span{-kInfinity, kInfinity} : Span{};
    const double x1 = (lo - offset) * inverse, x2 = (hi - offset) * inverse;
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

SweptRowScanner::SweptRowScanner(const SweptDisc& disc)
    : d_(disc), radiusSquared_(disc.radius * disc.radius) {
    dx_ = d_.bx - d_.ax;
    dy_ = d_.by - d_.ay;
    lengthSquared_ = dx_ * dx_ + dy_ * dy_;
    const double length = std::sqrt(lengthSquared_);
    band_ = length > 0.0 && std::isfinite(lengthSquared_);
    halfWidth_ = d_.radius * length;  // |cross product| bound of the band
    const auto inverse = [](double v) {
        const double i = 1.0 / v;
        return std::isfinite(i) ? i : 0.0;  // 0 or subnormal: the band is axis-parallel
    };
    inverseDx_ = inverse(dx_);
    inverseDy_ = inverse(dy_);
}

Span SweptRowScanner::row(double y) const {
    const auto disc = [&](double cx, double cy) {
        const double squared = radiusSquared_ - (y - cy) * (y - cy);
        if (!(squared >= 0.0)) return Span{};
        const double half = std::sqrt(squared);
        return Span{cx - half, cx + half};
    };
    const Span ends = hull(disc(d_.ax, d_.ay), disc(d_.bx, d_.by));
    if (!band_) return ends;
    // The band between the two end discs: the projection on the chord lies in
    // [0, L^2] and the distance from the chord's line is at most the radius.
    const double ry = y - d_.ay;
    const Span along = linearRangeBy(inverseDx_, ry * dy_ - d_.ax * dx_, 0.0, lengthSquared_);
    const Span across = linearRangeBy(inverseDy_, -d_.ax * dy_ - ry * dx_, -halfWidth_, halfWidth_);
    return hull(ends, intersect(along, across));
}

Span sweptRow(const SweptDisc& d, double y) {
    return SweptRowScanner(d).row(y);
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
