#include "cnc_core/interp/MotionPlanner.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cnc_core/geometry/ArcSweep.h"
#include "cnc_core/machine/AxisNameTable.h"
#include "cnc_core/motion/SegmentGeometry.h"
#include "cnc_core/text/Numbers.h"

namespace mtc::core {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string format(double value) {
    return formatFixed(value, 4);
}

std::string shortNumber(double value) {
    return formatGeneral(value, 6);
}

/// FEED_MISSING, FEED_PER_REVOLUTION_NO_SPEED or FEED_TOO_SMALL: cold paths
/// out of line, plan() runs for every move.
[[gnu::cold]] bool feedError(const BlockContext& context, int g, double feed, double feedRate) {
    if (feed <= 0.0)
        return context.error("FEED_MISSING", "G" + std::to_string(g) + " needs a feed F > 0");
    if (feedRate <= 0.0)
        return context.error(
            "FEED_PER_REVOLUTION_NO_SPEED",
            "G95 feed per revolution needs a spindle speed S of the reference spindle");
    // bounded simulated time (issue 22 §6, MOT-010)
    return context.error("FEED_TOO_SMALL", "the path feed " + shortNumber(feedRate) +
                                               " mm/min is below the smallest feed " +
                                               shortNumber(kMinimumFeed) + " mm/min");
}

[[gnu::cold]] bool radiusMismatch(const BlockContext& context, const BlockInput& input, double r1,
                                  double r2, double arcTolerance) {
    return context.error(
        "ARC_RADIUS_MISMATCH", "start and end point are not on one circle around the centre",
        input.centerColumn,
        {"radius at the start point " + format(r1) + " mm",
         "radius at the end point " + format(r2) + " mm",
         "difference " + format(r2 - r1) + " mm, tolerance " + format(arcTolerance) + " mm"});
}

/// ARC_RADIUS_ZERO or ARC_RADIUS_MISMATCH. The radii by value: the frame
/// path's arc calls it directly, so that its geometry is never needed in memory.
[[gnu::cold]] bool radiiError(const BlockContext& context, const BlockInput& input, double r1,
                              double r2, double arcTolerance) {
    if (r1 < 1e-9)
        return context.error("ARC_RADIUS_ZERO", "the circle's start point is its centre");
    return radiusMismatch(context, input, r1, r2, arcTolerance);
}

/// What an arc's axis time is worked out from: start, end and centre (work
/// coordinates of the plane axes), radii at start and end, the sweep, the
/// helical axes' time and the plane axes' seconds per unit.
struct ArcFigures {
    double s1, s2, e1, e2, c1, c2;
    double r1, r2, angle, signedSweep;
    double helixSeconds, secondsPerUnit1, secondsPerUnit2;
};

/// The time the slowest axis needs for its share of the arc at its
/// max_velocity, the plane axes at the peak of their tangent share. Out of
/// line: arcMove() asks it only when arcAxisBound() does not decide.
[[gnu::noinline]] double arcAxisSeconds(const ArcFigures& t) {
    // The plane axes' shares of the tangent peak where the circle runs
    // along them (motion::arcTangentExtreme).
    const double a0 = std::atan2(t.s2 - t.c2, t.s1 - t.c1);
    // |sin| and |cos| at the ends from the radius vectors (no trigonometry).
    const double endSin = t.r2 > 0.0 ? (t.e2 - t.c2) / t.r2 : std::sin(a0 + t.signedSweep);
    const double endCos = t.r2 > 0.0 ? (t.e1 - t.c1) / t.r2 : std::cos(a0 + t.signedSweep);
    const double path = t.r1 * t.angle;
    return std::max(
        {t.helixSeconds,
         path * motion::arcTangentExtreme(a0, t.signedSweep, false, (t.s2 - t.c2) / t.r1, endSin) *
             t.secondsPerUnit1,
         path * motion::arcTangentExtreme(a0, t.signedSweep, true, (t.s1 - t.c1) / t.r1, endCos) *
             t.secondsPerUnit2});
}

/// An upper bound of arcAxisSeconds() (MOT-024): the plane axes' shares of
/// the unit tangent are at most 1 (to a few ulps; the margin covers them), so
/// each plane term is at most the arc's length `path` (r1 x angle) times the
/// axis's seconds per unit. Below the feed's time it is the move's axis time
/// (max(feedSeconds, either) is the same then); NaN takes the exact path.
/// From scalars: arcMove() builds the ArcFigures only when this does not decide.
double arcAxisBound(double path, double helixSeconds, double secondsPerUnit1,
                    double secondsPerUnit2) {
    constexpr double kMargin = 1.0 + 1e-9;
    return std::max(
        {helixSeconds, path * secondsPerUnit1 * kMargin, path * secondsPerUnit2 * kMargin});
}

}  // namespace

double MotionPlanner::offsetOf(const ModalState& modal, int axis) const {
    return offsets_->value(modal.g[kGroupZeroOffset], modal.plane.definitionOf(axis));
}

void MotionPlanner::recomputeWork(ModalState& modal) const {
    const Transformation& t = modal.transformation;
    for (int a = 0; a < axes_->count(); ++a)
        if (!t.transforms(a))
            modal.work[static_cast<size_t>(a)] =
                modal.machine[static_cast<size_t>(a)] - offsetOf(modal, a);
    if (!t.active()) return;
    const int p1 = t.planeAxis(0), p2 = t.planeAxis(1);
    double c1 = 0, c2 = 0;
    t.toPlane(*axes_, modal.machine[static_cast<size_t>(p1)],
              modal.machine[static_cast<size_t>(p2)], c1, c2);
    modal.work[static_cast<size_t>(p1)] = c1 - offsetOf(modal, p1);
    modal.work[static_cast<size_t>(p2)] = c2 - offsetOf(modal, p2);
}

double MotionPlanner::programmedValue(const ModalState& next, int axis, double value) const {
    const AxisModel& model = axes_->axis(axis);
    const bool lengthUnit = !model.rotary || next.transformation.transforms(axis);
    if (!lengthUnit) return value;
    value *= millimetresPerUnit(next);
    if (next.g[kGroupRadiusDiameter] == 16 && next.plane.definitionOf(axis) == AxisDefinition::X)
        value *= 0.5;
    return value;
}

void MotionPlanner::toMachine(const ModalState& current, ModalState& next,
                              std::uint16_t axisMask) const {
    const Transformation& t = next.transformation;
    bool planeTouched = false;
    for (int a = 0; axisMask >> a; ++a) {
        if (!((axisMask >> a) & 1u)) continue;
        if (t.transforms(a)) {
            planeTouched = true;
            continue;
        }
        next.machine[static_cast<size_t>(a)] =
            next.work[static_cast<size_t>(a)] + offsetOf(next, a);
    }
    if (!planeTouched) return;
    const auto p1 = static_cast<size_t>(t.planeAxis(0)), p2 = static_cast<size_t>(t.planeAxis(1));
    t.toMachine(*axes_, next.work[p1] + offsetOf(next, t.planeAxis(0)),
                next.work[p2] + offsetOf(next, t.planeAxis(1)), current.machine[p1],
                current.machine[p2], next.machine[p1], next.machine[p2]);
}

bool MotionPlanner::travelLimit(const BlockContext& context, const BlockInput& input,
                                const AxisModel& m, int axis, double position) const {
    return context.error("TRAVEL_LIMIT",
                         "axis " + m.displayName() + " would move to " + format(position) +
                             ", outside its travel range " + format(m.minPosition) + " .. " +
                             format(m.maxPosition),
                         input.axisColumn[static_cast<size_t>(axis)]);
}

bool MotionPlanner::planGeneral(const BlockContext& context, const BlockInput& input,
                                const ModalState& current, BlockPlan& plan,
                                double arcTolerance) const {
    ModalState& next = plan.next;
    const bool incremental = next.g[kGroupDimension] == 91;
    for (int i = 0; i < input.axisCount; ++i) {
        const int a = input.axisOrder[static_cast<size_t>(i)];
        const double v = programmedValue(next, a, input.axisValue[static_cast<size_t>(a)]);
        double& work = next.work[static_cast<size_t>(a)];
        work = incremental ? work + v : v;
        const AxisModel& m = axes_->axis(a);
        if (m.spindle) next.rotaryAxisMode[static_cast<size_t>(m.spindleIndex)] = 1;
    }
    const std::uint32_t moved = movedAxes(input, next);
    toMachine(current, next, input.axisMask);
    for (int a = 0; moved >> a; ++a) {
        const AxisModel& m = axes_->axis(a);
        if (!((moved >> a) & 1u) || !m.limited()) continue;
        const double p = next.machine[static_cast<size_t>(a)];
        if (p < m.minPosition - 1e-9 || p > m.maxPosition + 1e-9)
            return travelLimit(context, input, m, a, p);
    }
    const int g = next.g[kGroupInterpolation];
    plan.hasMotion = true;
    plan.motionType = motionTypeOf(g);
    if (g == 0) {
        plan.feedRate = 0.0;
        next.time += rapidTime(current, next, moved);
        return true;
    }
    double length = 0.0;
    double axisSeconds = 0.0;  // the time the slowest axis needs at its max_velocity
    if (g >= 2) {
        if (!arc(context, input, current, plan, arcTolerance, length, axisSeconds)) return false;
    } else {
        for (int a = 0; moved >> a; ++a) {
            if (!((moved >> a) & 1u)) continue;
            const double d =
                next.work[static_cast<size_t>(a)] - current.work[static_cast<size_t>(a)];
            length += d * d;
            axisSeconds = std::max(axisSeconds, std::fabs(d) * secondsPerPlaneUnit(next, a));
        }
        length = std::sqrt(length);
    }
    return finishMove(context, input, plan, g, moved, length, axisSeconds);
}

bool MotionPlanner::feedRefused(const BlockContext& context, int g, double feed, double feedRate) {
    return feedError(context, g, feed, feedRate);
}

double MotionPlanner::secondsPerPlaneUnit(const ModalState& next, int axis) const {
    const AxisModel& m = axes_->axis(axis);
    const Transformation& t = next.transformation;
    if (!t.transforms(axis)) return m.rapidSecondsPerUnit;
    if (t.kind() == 32)  // developed surface: mm of the cylinder with radius RI
        return m.rotary ? m.rapidSecondsPerUnit * 180.0 / (kPi * t.effectiveRadius())
                        : m.rapidSecondsPerUnit;
    // G31: both plane coordinates move with the linear plane axis's limit.
    const int linear = axes_->axis(t.planeAxis(0)).rotary ? t.planeAxis(1) : t.planeAxis(0);
    return axes_->axis(linear).rapidSecondsPerUnit;
}

bool MotionPlanner::feedPerRevolutionAxes(const BlockContext& context, const BlockInput& input,
                                          const ModalState& next, std::uint32_t moved) const {
    // Seed 003, 3.6: feed per revolution is a function of the linear main
    // axes; every axis can perform it except a rotary axis with definition
    // X, Y or Z (free plane selection, lateral cylinder, facing).
    for (int a = 0; moved >> a; ++a) {
        if (!((moved >> a) & 1u) || !axes_->axis(a).rotary) continue;
        const AxisDefinition d = next.plane.definitionOf(a);
        if (d != AxisDefinition::X && d != AxisDefinition::Y && d != AxisDefinition::Z) continue;
        const std::string machineName = axes_->axis(a).displayName();
        const std::string programName = programmedAxisName(*axes_, next.transformation, a);
        const std::string name =
            programName == machineName ? machineName : machineName + " (" + programName + ")";
        return context.error("G95_ROTARY_AXIS",
                             "G95 feed per revolution: the rotary axis " + name +
                                 " has definition " + definitionLetter(d) +
                                 " and cannot move with feed per revolution (seed 003, 3.6); "
                                 "use G94",
                             input.axisColumn[static_cast<size_t>(a)]);
    }
    return true;
}

std::uint32_t MotionPlanner::movedAxes(const BlockInput& input, const ModalState& next) const {
    std::uint32_t moved = input.axisMask;
    const Transformation& t = next.transformation;
    if (t.active() && (moved & ((1u << t.planeAxis(0)) | (1u << t.planeAxis(1)))))
        moved |= (1u << t.planeAxis(0)) | (1u << t.planeAxis(1));  // G31 couples both
    return moved;
}

double MotionPlanner::rapidTime(const ModalState& current, const ModalState& next,
                                std::uint32_t moved) const {
    double seconds = 0.0;
    for (int a = 0; moved >> a; ++a) {
        if (!((moved >> a) & 1u)) continue;
        const double d = std::fabs(next.machine[static_cast<size_t>(a)] -
                                   current.machine[static_cast<size_t>(a)]);
        const double t = d * axes_->axis(a).rapidSecondsPerUnit;
        if (t > seconds) seconds = t;
    }
    return seconds;
}

// Inline in both arcs (arc() and framedArc()): one call and frame less per arc.
[[gnu::always_inline]] inline void MotionPlanner::arcMove(
    const BlockInput& input, const ModalState& current, BlockPlan& plan,
    const ArcGeometry& geometry, double arcTolerance, double& length, double& axisSeconds) const {
    ModalState& next = plan.next;
    const int p1 = geometry.p1, p2 = geometry.p2;
    const double s1 = geometry.s1, s2 = geometry.s2, e1 = geometry.e1, e2 = geometry.e2;
    const double r1 = geometry.r1;
    const double centre[2] = {geometry.c1, geometry.c2};
    // D-016: an end within the radius tolerance of the start closes the circle.
    const bool full = closesCircle(s1, s2, e1, e2, arcTolerance);
    const double angle = std::fabs(
        arcSweep(s1, s2, e1, e2, centre[0], centre[1], plan.motionType == MotionType::ArcCW, full));
    double helix = 0.0, helixSeconds = 0.0;
    const std::uint32_t others = input.axisMask & ~((1u << p1) | (1u << p2));
    for (int a = 0; others >> a; ++a) {
        if (!((others >> a) & 1u)) continue;
        const double d = next.work[static_cast<size_t>(a)] - current.work[static_cast<size_t>(a)];
        helix += d * d;
        helixSeconds = std::max(helixSeconds, std::fabs(d) * secondsPerPlaneUnit(next, a));
    }
    length = helix == 0.0 ? r1 * angle : std::sqrt(r1 * angle * r1 * angle + helix);
    // The feed's time as plan() works it out (feedCache_ as there; a feed
    // it refuses gives an error after this, whatever the figure).
    const double feed = pathFeedOf(next);
    if (feed != feedCache_.feed) feedCache_ = {feed, 60.0 / feed};
    const double perUnit1 = geometry.perUnit1, perUnit2 = geometry.perUnit2;
    const double bound = arcAxisBound(r1 * angle, helixSeconds, perUnit1, perUnit2);
    if (bound < length * feedCache_.secondsPerUnit) {
        axisSeconds = bound;
    } else {
        const double signedSweep = plan.motionType == MotionType::ArcCW ? -angle : angle;
        axisSeconds = arcAxisSeconds({s1, s2, e1, e2, centre[0], centre[1], r1, geometry.r2, angle,
                                      signedSweep, helixSeconds, perUnit1, perUnit2});
    }
    plan.planeAxis1 = p1;
    plan.planeAxis2 = p2;
    const Transformation& t = next.transformation;
    const double c1 = centre[0] + offsetOf(next, p1), c2 = centre[1] + offsetOf(next, p2);
    plan.planeCenter1 = c1;
    plan.planeCenter2 = c2;
    plan.fullCircle = full;
    if (t.kind() == 32) {
        t.toMachine(*axes_, c1, c2, current.machine[static_cast<size_t>(p1)],
                    current.machine[static_cast<size_t>(p2)], plan.center1, plan.center2);
    } else {
        plan.center1 = c1;
        plan.center2 = c2;
    }
}

bool MotionPlanner::arc(const BlockContext& context, const BlockInput& input,
                        const ModalState& current, BlockPlan& plan, double arcTolerance,
                        double& length, double& axisSeconds) const {
    ModalState& next = plan.next;
    const int p1 = next.plane.firstAxis(), p2 = next.plane.secondAxis();
    if (p1 < 0 || p2 < 0)
        return context.error("ARC_PLANE", "the working plane is not spanned by two axes");
    const Transformation& transformation = next.transformation;
    for (int p : {p1, p2})
        if (axes_->axis(p).rotary && !transformation.transforms(p))
            return context.error("ARC_ROTARY_AXIS",
                                 "a circle with the rotary axis " + axes_->axis(p).displayName() +
                                     " in the plane needs G31 or G32 first (seed 003, 4.2)");
    if (input.centerMask == 0)
        return context.error("ARC_CENTER_MISSING", "a circle needs its centre (I, J or K)");
    const bool incremental = next.g[kGroupDimension] == 91;
    double centre[2] = {current.work[static_cast<size_t>(p1)],
                        current.work[static_cast<size_t>(p2)]};
    static constexpr AxisDefinition kDefinition[3] = {AxisDefinition::X, AxisDefinition::Y,
                                                      AxisDefinition::Z};
    static constexpr char kLetter[3] = {'I', 'J', 'K'};
    for (int k = 0; k < 3; ++k) {
        if (!((input.centerMask >> k) & 1u)) continue;
        const int axis = next.plane.axisOf(kDefinition[k]);
        if (axis != p1 && axis != p2)
            return context.error(
                "ARC_CENTER_NOT_IN_PLANE",
                std::string(1, kLetter[k]) + " belongs to an axis outside the working plane",
                input.centerColumn);
        const int slot = axis == p1 ? 0 : 1;
        const double v = programmedValue(next, axis, input.center[static_cast<size_t>(k)]);
        centre[slot] = incremental ? centre[slot] + v : v;
    }
    ArcGeometry geometry(p1, p2, current, next, centre, secondsPerPlaneUnit(next, p1),
                         secondsPerPlaneUnit(next, p2));
    if (!arcRadii(geometry, arcTolerance))
        return radiiError(context, input, geometry.r1, geometry.r2, arcTolerance);
    arcMove(input, current, plan, geometry, arcTolerance, length, axisSeconds);
    return true;
}

// The frame path's arc (MotionPlannerFrame.cpp): here beside arcMove(), which it inlines.
bool MotionPlanner::framedArc(const BlockContext& context, const BlockInput& input,
                              const ModalState& current, BlockPlan& plan,
                              double arcTolerance) const {
    const ModalState& next = plan.next;
    const int p1 = frame_.p1, p2 = frame_.p2;
    const bool incremental = next.g[kGroupDimension] == 91;
    // The centre's two coordinates by name, not by a computed index: an
    // array indexed by the slot would live on the stack.
    double c1 = current.work[static_cast<size_t>(p1)], c2 = current.work[static_cast<size_t>(p2)];
    for (int k = 0; k < 3; ++k) {
        if (!((input.centerMask >> k) & 1u)) continue;
        const bool first = frame_.centreSlot[static_cast<size_t>(k)] == 0;
        const auto axis = static_cast<size_t>(first ? p1 : p2);
        const double v =
            input.center[static_cast<size_t>(k)] * frame_.inch[axis] * frame_.diameter[axis];
        if (first)
            c1 = incremental ? c1 + v : v;
        else
            c2 = incremental ? c2 + v : v;
    }
    const double centre[2] = {c1, c2};
    ArcGeometry geometry(p1, p2, current, next, centre,
                         frame_.secondsPerUnit[static_cast<size_t>(p1)],
                         frame_.secondsPerUnit[static_cast<size_t>(p2)]);
    if (!arcRadii(geometry, arcTolerance))
        return radiiError(context, input, geometry.r1, geometry.r2, arcTolerance);
    double length = 0.0, axisSeconds = 0.0;
    arcMove(input, current, plan, geometry, arcTolerance, length, axisSeconds);
    return finishMove(context, input, plan, next.g[kGroupInterpolation], input.axisMask, length,
                      axisSeconds);
}

}  // namespace mtc::core
