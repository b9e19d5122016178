#include "cnc_core/motion/PlaneMapping.h"

#include <cmath>

#include "cnc_core/machine/Transformation.h"
#include "cnc_core/toolpath/CurveMath.h"

namespace mtc::core::motion {

namespace {
constexpr double kDegPerRad = 180.0 / curve::kPi;

double rotationSign(int polarDirection) {
    return polarDirection == 1 ? -1.0 : 1.0;
}
}  // namespace

PlaneMapping PlaneMapping::of(const Motion& m, const MotionLimits& limits) {
    PlaneMapping p;
    p.describe(m, limits);
    return p;
}

void PlaneMapping::describe(const Motion& m, const MotionLimits& limits) {
    kind_ = 30;
    axis1_ = axis2_ = linear_ = rotary_ = -1;
    radius_ = 0.0;
    polar_ = {};
    rotaryAxis_ = {};
    const int a1 = m.transformAxis1, a2 = m.transformAxis2;
    if (m.transformation == 30 || a1 < 0 || a2 < 0 || a1 >= limits.axisCount ||
        a2 >= limits.axisCount)
        return;
    const AxisLimit& l1 = limits.axes[static_cast<std::size_t>(a1)];
    const AxisLimit& l2 = limits.axes[static_cast<std::size_t>(a2)];
    axis1_ = a1;
    axis2_ = a2;
    polar_ = {l1.polarDirection, l2.polarDirection};
    rotaryAxis_ = {l1.rotary, l2.rotary};
    if (m.transformation == 32 && m.effectiveRadius > 0.0) {
        kind_ = 32;
        radius_ = m.effectiveRadius;
    } else if (m.transformation == 31 && l1.rotary != l2.rotary) {
        kind_ = 31;
        linear_ = l1.rotary ? a2 : a1;
        rotary_ = l1.rotary ? a1 : a2;
    } else {
        axis1_ = axis2_ = -1;
    }
}

bool PlaneMapping::developed(int axis) const {
    if (kind_ != 32) return false;
    return (axis == axis1_ && rotaryAxis_[0]) || (axis == axis2_ && rotaryAxis_[1]);
}

double PlaneMapping::developedUnits(int axis, double degreesValue) const {
    return developed(axis) ? degreesValue / kDegPerRad * radius_ : degreesValue;
}

void PlaneMapping::transformToPlane(const Position& machine, Position& plane) const {
    if (kind_ == 32) {
        for (int k = 0; k < 2; ++k) {
            const auto a = static_cast<std::size_t>(k == 0 ? axis1_ : axis2_);
            if (rotaryAxis_[static_cast<std::size_t>(k)])
                plane[a] = curve::developedFromDegrees(machine[a], radius_,
                                                       polar_[static_cast<std::size_t>(k)]);
        }
    } else if (kind_ == 31) {
        const auto l = static_cast<std::size_t>(linear_), r = static_cast<std::size_t>(rotary_);
        const int polar = polar_[rotary_ == axis1_ ? 0 : 1];
        const double angle = rotationSign(polar) * machine[r] / kDegPerRad;
        plane[l] = machine[l] * std::cos(angle);
        plane[r] = machine[l] * std::sin(angle);
    }
}

void PlaneMapping::toMachine(const Position& plane, Position& machine) const {
    const Position previous = machine;
    machine = plane;
    if (kind_ == 32) {
        for (int k = 0; k < 2; ++k) {
            const auto a = static_cast<std::size_t>(k == 0 ? axis1_ : axis2_);
            if (rotaryAxis_[static_cast<std::size_t>(k)])
                machine[a] = curve::degreesFromDeveloped(plane[a], radius_,
                                                         polar_[static_cast<std::size_t>(k)]);
        }
    } else if (kind_ == 31) {
        const auto l = static_cast<std::size_t>(linear_), r = static_cast<std::size_t>(rotary_);
        const double sign = rotationSign(polar_[rotary_ == axis1_ ? 0 : 1]);
        const int linearPolar = polar_[linear_ == axis1_ ? 0 : 1];
        double radius = std::hypot(plane[l], plane[r]);
        double angle =
            radius == 0.0 ? previous[r] * sign : std::atan2(plane[r], plane[l]) * kDegPerRad;
        if (linearPolar == 1 && radius != 0.0) {
            radius = -radius;
            angle += 180.0;
        }
        machine[l] = radius;
        machine[r] = nearestTurn(sign * angle, previous[r]);
    }
}

}  // namespace mtc::core::motion
