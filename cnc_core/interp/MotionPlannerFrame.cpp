// The motion planner's frame path (MOT-025): a block without a
// transformation reads what its axes' conversion, travel limits and plane
// need from a PlanFrame built once per combination of G70/G71, G15/G16 and
// axis allocation, instead of working it out per axis and block. Same
// operations on the same values in the same order as the general path
// (MotionPlanner.cpp), the same diagnostics from the same functions. A
// block that only the general path can plan (a transformation, a repeated
// axis, an arc outside the frame's plane) goes there before anything is written.
// The frame path's arc, framedArc(), is in MotionPlanner.cpp beside arcMove().
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "cnc_core/interp/MotionPlanner.h"

namespace mtc::core {
namespace {

constexpr AxisDefinition kCentreDefinition[3] = {AxisDefinition::X, AxisDefinition::Y,
                                                 AxisDefinition::Z};

/// G15/G16 and G70/G71 of `next` as one key (two adjacent groups).
std::uint32_t radiusUnitsOf(const ModalState& next) {
    static_assert(kGroupUnits == kGroupRadiusDiameter + 1, "adjacent groups");
    std::uint32_t key = 0;
    std::memcpy(&key, &next.g[kGroupRadiusDiameter], sizeof key);
    return key;
}

}  // namespace

bool MotionPlanner::plan(const BlockContext& context, const BlockInput& input,
                         const ModalState& current, BlockPlan& plan,
                         const PlanningOptions& options) const {
    const double arcTolerance = options.arcTolerance;
    ModalState& next = plan.next;
    if (!options.shortcuts || input.repeatedAxisColumn != 0 || next.transformation.active())
        return planGeneral(context, input, current, plan, arcTolerance);
    if (!frameFits(next)) buildFrame(next);
    const int g = next.g[kGroupInterpolation];
    // ARC_PLANE, ARC_ROTARY_AXIS, ARC_CENTER_*: the general path reports them.
    if (g >= 2 &&
        (frame_.p1 < 0 || input.centerMask == 0 || (input.centerMask & ~frame_.centreInPlane) != 0))
        return planGeneral(context, input, current, plan, arcTolerance);
    const std::uint32_t mask = input.axisMask;
    const bool incremental = next.g[kGroupDimension] == 91;
    const double* offsets = offsets_->row(next.g[kGroupZeroOffset]);
    const PlanFrame& f = frame_;
    double squares = 0.0, axisSeconds = 0.0;
    for (std::uint32_t rest = mask; rest != 0; rest &= rest - 1) {
        const auto a = static_cast<size_t>(__builtin_ctz(rest));
        // programmedValue() as two factors: x 1 is exact.
        const double v = input.axisValue[a] * f.inch[a] * f.diameter[a];
        const double w = incremental ? next.work[a] + v : v;
        const double p = w + offsets[f.offsetColumn[a]];
        next.work[a] = w;
        next.machine[a] = p;
        if (p < f.low[a] || p > f.high[a])
            return travelLimit(context, input, axes_->axis(static_cast<int>(a)),
                               static_cast<int>(a), p);
        if (g == 0) {  // rapidTime()
            const double t = std::fabs(p - current.machine[a]) * f.secondsPerUnit[a];
            if (t > axisSeconds) axisSeconds = t;
        } else if (g < 2) {
            const double d = w - current.work[a];
            squares += d * d;
            axisSeconds = std::max(axisSeconds, std::fabs(d) * f.secondsPerUnit[a]);
        }
    }
    for (std::uint32_t rest = mask & f.spindleMask; rest != 0; rest &= rest - 1)
        next.rotaryAxisMode[static_cast<size_t>(
            f.spindleIndex[static_cast<size_t>(__builtin_ctz(rest))])] = 1;
    plan.hasMotion = true;
    plan.motionType = motionTypeOf(g);
    if (g == 0) {
        plan.feedRate = 0.0;
        next.time += axisSeconds;
        return true;
    }
    if (g >= 2) return framedArc(context, input, current, plan, arcTolerance);
    return finishMove(context, input, plan, g, mask, std::sqrt(squares), axisSeconds);
}

bool MotionPlanner::frameFits(const ModalState& next) const {
    return frame_.valid && frame_.radiusUnits == radiusUnitsOf(next) &&
           frame_.plane.sameAs(next.plane);
}

void MotionPlanner::buildFrame(const ModalState& next) const {
    PlanFrame& f = frame_;
    f.radiusUnits = radiusUnitsOf(next);
    f.plane = next.plane;
    f.spindleMask = 0;
    f.centreInPlane = 0;
    constexpr double kInf = std::numeric_limits<double>::infinity();
    for (int a = 0; a < axes_->count() && a < kMaxAxes; ++a) {
        const AxisModel& m = axes_->axis(a);
        const auto i = static_cast<size_t>(a);
        const AxisDefinition definition = next.plane.definitionOf(a);
        const bool lengthUnit = !m.rotary;  // no transformation in a frame
        f.inch[i] = lengthUnit ? millimetresPerUnit(next) : 1.0;
        f.diameter[i] =
            lengthUnit && next.g[kGroupRadiusDiameter] == 16 && definition == AxisDefinition::X
                ? 0.5
                : 1.0;
        f.low[i] = m.limited() ? m.minPosition - 1e-9 : -kInf;
        f.high[i] = m.limited() ? m.maxPosition + 1e-9 : kInf;
        f.secondsPerUnit[i] = m.rapidSecondsPerUnit;
        f.offsetColumn[i] = static_cast<std::uint8_t>(ZeroOffsetTable::column(definition));
        f.spindleIndex[i] = static_cast<std::uint8_t>(m.spindleIndex);
        if (m.spindle) f.spindleMask = static_cast<std::uint16_t>(f.spindleMask | (1u << a));
    }
    const int p1 = next.plane.firstAxis(), p2 = next.plane.secondAxis();
    const bool arcs = p1 >= 0 && p2 >= 0 && !axes_->axis(p1).rotary && !axes_->axis(p2).rotary;
    f.p1 = arcs ? p1 : -1;
    f.p2 = arcs ? p2 : -1;
    for (int k = 0; k < 3; ++k) {
        const int axis = next.plane.axisOf(kCentreDefinition[k]);
        const int slot = axis >= 0 && axis == p1 ? 0 : axis >= 0 && axis == p2 ? 1 : 2;
        f.centreSlot[static_cast<size_t>(k)] = static_cast<std::uint8_t>(slot);
        if (slot < 2) f.centreInPlane = static_cast<std::uint8_t>(f.centreInPlane | (1u << k));
    }
    f.valid = true;
}

bool MotionPlanner::finishChecked(const BlockContext& context, const BlockInput& input,
                                  BlockPlan& plan, int g, std::uint32_t moved, double length,
                                  double axisSeconds) const {
    ModalState& next = plan.next;
    const bool perRevolution = next.g[kGroupFeedType] == 95;
    if (perRevolution && !feedPerRevolutionAxes(context, input, next, moved)) return false;
    plan.feedRate = pathFeedOf(next);
    if (next.feed <= 0.0 || plan.feedRate < kMinimumFeed)
        return feedRefused(context, g, next.feed, plan.feedRate);
    if (plan.feedRate != feedCache_.feed) feedCache_ = {plan.feedRate, 60.0 / plan.feedRate};
    next.time += std::max(length * feedCache_.secondsPerUnit, axisSeconds);
    return true;
}

}  // namespace mtc::core
