#include "cnc_core/motion/MotionLimits.h"

#include <algorithm>
#include <cmath>

namespace mtc::core::motion {

namespace {

/// A configured number if it is finite and inside [low, high], else `fallback`.
double bounded(double value, double low, double high, double fallback) {
    return std::isfinite(value) && value >= low && value <= high ? value : fallback;
}

}  // namespace

MotionLimits MotionLimits::fromConfig(const ProcessConfig& process) {
    MotionLimits limits;
    limits.axisCount = std::min<int>(static_cast<int>(process.axes.size()), kMaxAxes);
    // Seed 001 ch. 6: velocity change at a block transition = 2 * a * VFBT,
    // reached within one NC block cycle (docs/decisions/lookahead.md LA-004).
    const double vfbt = bounded(process.number("B071", 1.0), 1.0, 10.0, 1.0);
    const double cycle = bounded(process.number("B073", 2.0), 0.1, 100.0, 2.0) / 1000.0;
    for (int i = 0; i < limits.axisCount; ++i) {
        const AxisConfig& axis = process.axes[static_cast<std::size_t>(i)];
        AxisLimit& limit = limits.axes[static_cast<std::size_t>(i)];
        limit.velocity = bounded(axis.maxVelocity, 1e-6, 1e9, 10000.0) / 60.0;
        limit.acceleration = bounded(axis.maxAcceleration, 1e-6, 1e9, 2000.0);
        limit.velocityStep = 2.0 * limit.acceleration * vfbt * cycle;
        limit.rotary = axis.kind != AxisKind::Linear;
        limit.polarDirection = axis.polarDirection;
        if (axis.kind == AxisKind::Spindle && axis.spindleIndex >= 1 && axis.spindleIndex <= 3) {
            const auto s = static_cast<std::size_t>(axis.spindleIndex);
            limits.spindleAxis[s] = i;
            limits.spindles[s].present = true;
            limits.spindles[s].maxSpeed = bounded(axis.maxSpeed, 0.0, 1e7, 0.0);
            limits.spindles[s].acceleration = limit.acceleration / 6.0;  // deg/s^2 -> rpm/s
        }
    }
    limits.feedOverrideMax = bounded(process.number("B074", 150.0), 100.0, 200.0, 150.0);
    return limits;
}

}  // namespace mtc::core::motion
