#include "cnc_core/motion/PathLimits.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mtc::core::motion {

AxisLimit planeLimit(const SegmentGeometry& g, const MotionLimits& limits, int axis) {
    const PlaneMapping& map = g.mapping();
    if (map.identity()) return limits.axes[static_cast<std::size_t>(axis)];  // no unit to change
    int source = axis;
    if (map.kind() == 31 && (axis == map.axis1() || axis == map.axis2()))
        source =
            limits.axes[static_cast<std::size_t>(map.axis1())].rotary ? map.axis2() : map.axis1();
    AxisLimit l = limits.axes[static_cast<std::size_t>(source)];
    l.velocity = map.planeUnits(axis, l.velocity);
    l.acceleration = map.planeUnits(axis, l.acceleration);
    l.velocityStep = map.planeUnits(axis, l.velocityStep);
    return l;
}

PathLimits pathLimits(const SegmentGeometry& g, const MotionLimits& limits) {
    PathLimits out;
    if (!(g.length() > 0.0)) return out;
    constexpr double kNone = std::numeric_limits<double>::infinity();
    double velocity = kNone, acceleration = kNone, planeAcceleration = kNone;
    for (int i = 0; i < g.axisCount(); ++i) {
        const double share = g.maxTangentComponent(i);
        const bool inArcPlane = g.arc() && (i == g.planeAxis1() || i == g.planeAxis2());
        if (share <= 1e-12 && !inArcPlane) continue;  // an axis that does not move
        const AxisLimit l = planeLimit(g, limits, i);
        if (inArcPlane) planeAcceleration = std::min(planeAcceleration, l.acceleration);
        if (share <= 1e-12) continue;
        velocity = std::min(velocity, l.velocity / share);
        acceleration = std::min(acceleration, l.acceleration / share);
    }
    if (velocity == kNone) velocity = 0.0;
    if (acceleration == kNone) acceleration = 0.0;
    if (g.arc()) {
        acceleration *= 0.5;
        if (g.radius() > 0.0 && planeAcceleration != kNone)
            velocity = std::min(velocity, std::sqrt(0.5 * planeAcceleration * g.radius()));
    }
    out.velocity = velocity;
    out.acceleration = acceleration;
    return out;
}

}  // namespace mtc::core::motion
