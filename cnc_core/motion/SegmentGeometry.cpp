#include "cnc_core/motion/SegmentGeometry.h"

#include <algorithm>
#include <cmath>

#include "cnc_core/geometry/ArcSweep.h"
#include "cnc_core/toolpath/CurveMath.h"

namespace mtc::core::motion {

namespace {

using curve::kPi;

/// Hands `store(i, value)` the `count` values `component(i)` divided by
/// their norm (undivided when the norm is 0) and returns the norm. Each
/// component is computed twice, for the norm and for the store, instead of
/// being read back: a wide load over the narrow stores just made there
/// stalled the store forwarding on every move (about a quarter of the time
/// of an arc's tangents). Same operations in the same order as storing,
/// summing the squares and dividing in place.
template <typename Component, typename Store>
double storeUnit(int count, const Component& component, const Store& store) {
    double sum = 0.0;
    for (int i = 0; i < count; ++i) {
        const double c = component(i);
        sum += c * c;
    }
    const double norm = std::sqrt(sum);
    const bool divide = !(norm <= 0.0);
    for (int i = 0; i < count; ++i)
        store(static_cast<std::size_t>(i), divide ? component(i) / norm : component(i));
    return norm;
}

/// Zeroes `v` from axis `count` to `before` (what a default geometry holds
/// there): the tangents hold 0 from axisCount_ on in every geometry (a
/// default one, and every describe() since), so only the axes the slot's
/// former move had beyond this one's need it (MOT-026).
void clearFrom(Position& v, int count, int before) {
    const int from = std::clamp(count, 0, kMaxAxes);
    const int to = std::clamp(before, 0, kMaxAxes);
    for (int i = from; i < to; ++i)
        v[static_cast<std::size_t>(i)] = 0.0;
}

}  // namespace

double arcTangentExtreme(double angle0, double sweep, bool secondAxis, double startShare,
                         double endShare) {
    // The tangent of a circle at polar angle a is (-sin a, cos a): the first
    // plane axis's share is |sin|, the second's |cos|. Extremes of |cos| lie
    // at k*pi, of |sin| at pi/2 + k*pi.
    const double lo = std::min(angle0, angle0 + sweep), hi = std::max(angle0, angle0 + sweep);
    const double phase = secondAxis ? 0.0 : kPi / 2.0;
    if (std::ceil((lo - phase) / kPi) * kPi + phase <= hi) return 1.0;
    return std::max(std::fabs(startShare), std::fabs(endShare));
}

SegmentGeometry SegmentGeometry::of(const Motion& m, const MotionLimits& limits) {
    SegmentGeometry g;
    g.describe(m, limits);
    return g;
}

// Every member ends up as of() leaves it: a reused queue slot is exactly a
// fresh one (the tangents past axisCount_ and the arc's figures of a line
// are cleared where the slot's former move left others).
void SegmentGeometry::describe(const Motion& m, const MotionLimits& limits) {
    mapping_.describe(m, limits);
    const int before = axisCount_;  // the tangents are 0 from here on
    axisCount_ = std::min(m.axisCount, limits.axisCount);
    machineEnd_ = m.end;
    mapping_.toPlane(m.start, start_);
    mapping_.toPlane(m.end, end_);
    const bool arc = (m.type == MotionType::ArcCW || m.type == MotionType::ArcCCW) &&
                     m.planeAxis1 >= 0 && m.planeAxis2 >= 0 && m.planeAxis1 < axisCount_ &&
                     m.planeAxis2 < axisCount_ && m.planeAxis1 != m.planeAxis2;
    if (!arc) {
        describeLine(before);
        return;
    }
    p1_ = m.planeAxis1;
    p2_ = m.planeAxis2;
    double c1 = m.center1, c2 = m.center2;
    if (mapping_.kind() == 32) {  // the interpreter gives the centre in machine positions
        Position centre = m.start;
        centre[static_cast<std::size_t>(p1_)] = c1;
        centre[static_cast<std::size_t>(p2_)] = c2;
        Position plane{};
        mapping_.toPlane(centre, plane);
        c1 = plane[static_cast<std::size_t>(p1_)];
        c2 = plane[static_cast<std::size_t>(p2_)];
    }
    describeArc(c1, c2, m.type == MotionType::ArcCW, m.fullCircle, before);
}

void SegmentGeometry::clearArc() {
    p1_ = p2_ = -1;
    center1_ = center2_ = 0.0;
    radius0_ = radius1_ = 0.0;
    angle0_ = sweep_ = 0.0;
    startPolar_ = endPolar_ = Polar{};
    planeShare_ = 0.0;
}

void SegmentGeometry::describeLine(int before) {
    // A line leaves the arc's figures as a default geometry holds them, so
    // only a slot whose former move was an arc needs them cleared (MOT-028).
    if (arc_) clearArc();
    arc_ = false;
    clearFrom(startTangent_, axisCount_, before);
    clearFrom(endTangent_, axisCount_, before);
    const auto difference = [this](int i) {
        const auto k = static_cast<std::size_t>(i);
        return end_[k] - start_[k];
    };
    // A line's tangent is the same at both ends: worked out once and stored
    // in both (the same operations as twice; not copied over, which would
    // read the narrow stores back with wide loads). The norm is the length.
    length_ = storeUnit(axisCount_, difference, [this](std::size_t k, double unit) {
        startTangent_[k] = unit;
        endTangent_[k] = unit;
    });
}

void SegmentGeometry::describeArc(double c1, double c2, bool clockwise, bool fullCircle,
                                  int before) {
    arc_ = true;
    center1_ = c1;
    center2_ = c2;
    const auto k1 = static_cast<std::size_t>(p1_), k2 = static_cast<std::size_t>(p2_);
    radius0_ = std::hypot(start_[k1] - c1, start_[k2] - c2);
    radius1_ = std::hypot(end_[k1] - c1, end_[k2] - c2);
    angle0_ = std::atan2(start_[k2] - c2, start_[k1] - c1);
    sweep_ = arcSweep(start_[k1], start_[k2], end_[k1], end_[k2], c1, c2, clockwise, fullCircle);
    const double sweep = std::fabs(sweep_);
    double helix = 0.0;
    for (int i = 0; i < axisCount_; ++i) {
        if (i == p1_ || i == p2_) continue;
        const double d = end_[static_cast<std::size_t>(i)] - start_[static_cast<std::size_t>(i)];
        helix += d * d;
    }
    const double arcLength = 0.5 * (radius0_ + radius1_) * sweep;
    length_ = std::sqrt(arcLength * arcLength + helix);
    planeShare_ = length_ > 0.0 ? std::sqrt(std::max(0.0, 1.0 - helix / (length_ * length_))) : 0.0;
    // cos and sin of the polar angle at both ends from the radius vectors:
    // the same values as from angle0_ and angle0_ + sweep_ (to rounding)
    // without four trigonometric calls per arc.
    startPolar_ = polar(start_[k1] - c1, start_[k2] - c2, radius0_, angle0_);
    endPolar_ = polar(end_[k1] - c1, end_[k2] - c2, radius1_, angle0_ + sweep_);
    clearFrom(startTangent_, axisCount_, before);
    clearFrom(endTangent_, axisCount_, before);
    arcTangent(startPolar_, radius0_, startTangent_);
    arcTangent(endPolar_, radius1_, endTangent_);
}

SegmentGeometry::Polar SegmentGeometry::polar(double d1, double d2, double radius, double angle) {
    if (radius > 0.0) return {d1 / radius, d2 / radius};
    return {std::cos(angle), std::sin(angle)};  // a point on the centre: the angle decides
}

void SegmentGeometry::arcTangent(Polar at, double radius, Position& tangent) const {
    const double dr = radius1_ - radius0_;
    // The plane components once (registers, not stores: storeUnit's reason).
    const double t1 = dr * at.cos - radius * sweep_ * at.sin;
    const double t2 = dr * at.sin + radius * sweep_ * at.cos;
    storeUnit(
        axisCount_,
        [&](int i) {
            if (i == p1_) return t1;
            if (i == p2_) return t2;
            const auto k = static_cast<std::size_t>(i);
            return end_[k] - start_[k];
        },
        [&tangent](std::size_t k, double unit) { tangent[k] = unit; });
}

void SegmentGeometry::planePoint(double s, Position& plane) const {
    const double u = length_ > 0.0 ? std::clamp(s / length_, 0.0, 1.0) : 1.0;
    for (int i = 0; i < axisCount_; ++i) {
        const auto k = static_cast<std::size_t>(i);
        plane[k] = start_[k] + (end_[k] - start_[k]) * u;
    }
    if (!arc_) return;
    const double angle = angle0_ + sweep_ * u;
    const double r = radius0_ + (radius1_ - radius0_) * u;
    plane[static_cast<std::size_t>(p1_)] = center1_ + r * std::cos(angle);
    plane[static_cast<std::size_t>(p2_)] = center2_ + r * std::sin(angle);
}

void SegmentGeometry::machinePointOnPath(double s, Position& machine) const {
    Position plane = machine;
    planePoint(s, plane);
    if (mapping_.identity()) {
        for (int i = 0; i < axisCount_; ++i)
            machine[static_cast<std::size_t>(i)] = plane[static_cast<std::size_t>(i)];
        return;
    }
    mapping_.toMachine(plane, machine);
}

double SegmentGeometry::maxTangentComponent(int axis) const {
    if (axis < 0 || axis >= axisCount_) return 0.0;
    const auto k = static_cast<std::size_t>(axis);
    // A line's two tangents are one value (describeLine() stores it twice).
    if (!arc_) return std::fabs(startTangent_[k]);
    if (axis != p1_ && axis != p2_)
        return std::max(std::fabs(startTangent_[k]), std::fabs(endTangent_[k]));
    // In-plane share of the tangent times the largest |sin| (axis 1) or |cos| (axis 2).
    const bool second = axis == p2_;
    return planeShare_ * arcTangentExtreme(angle0_, sweep_, second,
                                           second ? startPolar_.cos : startPolar_.sin,
                                           second ? endPolar_.cos : endPolar_.sin);
}

}  // namespace mtc::core::motion
