#include "cnc_core/interp/BlockExecutor.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "cnc_core/contour/ToolCheck.h"
#include "cnc_core/interp/AuxFunctionGroups.h"
#include "cnc_core/text/Numbers.h"

namespace mtc::core {
namespace {

/// Groups without side effects: the programmed value simply becomes active.
constexpr int kPlainGroups[] = {kGroupToolPath,     kGroupFeedType,  kGroupDimension, kGroupUnits,
                                kGroupAcceleration, kGroupExactStop, kGroupToolLength};

bool reportProblems(const BlockContext& c, const std::vector<PlaneProblem>& problems, int column) {
    for (const auto& p : problems)
        c.error(p.code, p.message, p.column ? p.column : column);
    return problems.empty();
}

std::string formatNumber(double value) {
    return formatGeneral(value, 10);
}

/// BlockContext::error() out of line, for the functions every block with
/// aux words passes through: its strings and details list, built in place,
/// gave them large frames and six saved registers per call.
[[gnu::cold, gnu::noinline]] bool refuse(const BlockContext& c, const char* code,
                                         const char* message, int column) {
    return c.error(code, message, column);
}

[[gnu::cold, gnu::noinline]] bool twoOfOneMGroup(const BlockContext& c, int group, int column) {
    return c.error("M_GROUP_CONFLICT",
                   "two M functions of group " + std::to_string(group) + " in one block", column);
}

}  // namespace

bool BlockExecutor::planGeneral(const BlockContext& c, const BlockInput& in,
                                const InterpreterState& state, BlockPlan& plan,
                                const PlanningOptions& options) const {
    if (in.repeatedAxisColumn && in.g[kGroupPlane] != 20)
        return refuse(c, "WORD_TWICE", "an axis is programmed twice in one block",
                      in.repeatedAxisColumn);
    clearPlan(plan);
    ModalState& next = plan.next;
    // Only modal G, axis, I/J/K and F words (I-023): a usual block that
    // plan() did not take itself programs a modal group beside G0..G3 (or
    // an axis twice under G20), so modalGroups() runs; F needs no scalars().
    // The block with more takes the shortcuts below where it can
    // (InterpShortcuts.* compare with options.shortcuts off).
    constexpr std::uint32_t kInterpolationOnly = 1u << kGroupInterpolation;
    const bool shortcuts = options.shortcuts;
    if (shortcuts && !in.special) {
        if (in.gMask != 0 && !modalGroups(c, in, state.modal, next, state.reentry.valid))
            return false;
        if (in.hasFeed) next.feed = in.feed * millimetresPerUnit(next);
        if (in.axisMask == 0 || in.g[kGroupPlane] == 20) return true;
        return motion_.plan(c, in, state.modal, plan, options);
    }
    if (shortcuts && in.gMask == kInterpolationOnly && !in.hasRadius) {
        next.g[kGroupInterpolation] = in.g[kGroupInterpolation];
    } else if (in.gMask != 0 || in.hasRadius) {
        if (!modalGroups(c, in, state.modal, next, state.reentry.valid)) return false;
    }
    const bool otherScalars =
        in.dwell || in.hasTool || in.hasEdge || in.hasCorrection || in.spindleMask != 0;
    if (shortcuts && !otherScalars && in.hasFeed) {
        next.feed = in.feed * millimetresPerUnit(next);
    } else if ((otherScalars || in.hasFeed) && !scalars(c, in, plan)) {
        return false;
    }
    if ((in.mCount != 0 || in.qCount != 0) && !auxiliaries(c, in, state, plan)) return false;
    if (in.axisFunction != 0) return axisFunction(c, in, state, plan, options);
    if (in.axisMask == 0 || in.g[kGroupPlane] == 20) return true;
    if (in.dwell)
        return refuse(c, "DWELL_WITH_AXES", "G4 cannot be combined with axis words",
                      in.dwellColumn);
    return motion_.plan(c, in, state.modal, plan, options);
}

bool BlockExecutor::modalGroups(const BlockContext& c, const BlockInput& in,
                                const ModalState& current, ModalState& next, bool restoring) const {
    constexpr std::uint32_t kPlainMask = (1u << kGroupToolPath) | (1u << kGroupFeedType) |
                                         (1u << kGroupDimension) | (1u << kGroupUnits) |
                                         (1u << kGroupAcceleration) | (1u << kGroupExactStop) |
                                         (1u << kGroupToolLength);
    constexpr std::uint32_t kGeometryMask =
        (1u << kGroupPlane) | (1u << kGroupTransformation) | (1u << kGroupZeroOffset);
    if (in.gMask & kPlainMask)
        for (int group : kPlainGroups)
            if (in.g[static_cast<size_t>(group)] >= 0)
                next.g[static_cast<size_t>(group)] = in.g[static_cast<size_t>(group)];
    if ((in.gMask & kGeometryMask) || in.hasRadius) {
        if (!transformationOff(c, in, next) || !planeChange(c, in, current, next) ||
            !transformationOn(c, in, next, restoring))
            return false;
    }
    explicitGroups(in, next);
    if (in.gMask & kGeometryMask) motion_.recomputeWork(next);
    return true;
}

bool BlockExecutor::transformationOff(const BlockContext& c, const BlockInput& in,
                                      ModalState& next) const {
    (void)c;
    if (in.g[kGroupTransformation] != 30 || !next.transformation.active()) return true;
    next.transformation.deselect();
    next.g[kGroupTransformation] = 30;
    next.g[kGroupZeroOffset] = 53;
    next.g[kGroupRadiusDiameter] = (*setup_.defaults)[kGroupRadiusDiameter];
    return true;
}

bool BlockExecutor::planeChange(const BlockContext& c, const BlockInput& in,
                                const ModalState& current, ModalState& next) const {
    const int plane = in.g[kGroupPlane];
    if (plane < 0) return true;
    const int column = in.gColumn[kGroupPlane];
    if (next.transformation.active())
        return c.error("PLANE_CHANGE_IN_TRANSFORMATION",
                       "the plane cannot change while G" +
                           std::to_string(next.transformation.kind()) +
                           " is active; deselect it with G30 first",
                       column);
    if (plane != 20) {
        if (!reportProblems(c, next.plane.selectStandard(*setup_.axes, plane), column))
            return false;
        next.g[kGroupPlane] = static_cast<std::int16_t>(plane);
        return true;
    }
    if (in.spindleMask != 0)  // `G20 S2=0 Y0 Z0`: an S word is a spindle here, not a speed
        return c.error("G20_SPINDLE",
                       "spindles cannot span a plane, and a G20 block holds no other axis or "
                       "spindle words (seed 003, 3.2); program a spindle speed in its own block",
                       in.spindleColumn);
    std::vector<FreePlaneAxis> programmed;
    for (int i = 0; i < in.axisCount; ++i) {
        const int a = in.axisOrder[static_cast<size_t>(i)];
        programmed.push_back(
            {a, in.orderValue[static_cast<size_t>(i)], in.orderColumn[static_cast<size_t>(i)]});
    }
    if (!reportProblems(c, next.plane.selectFree(*setup_.axes, programmed), column)) return false;
    next.g[kGroupPlane] = 20;
    next.g[kGroupInterpolation] = 1;  // seed 003, 3.7: G20 activates G1 ...
    next.g[kGroupSurfaceSpeed] = 97;  // ... and replaces G96 by G97
    for (int i = 0; i < in.axisCount; ++i) {
        const AxisModel& m = setup_.axes->axis(in.axisOrder[static_cast<size_t>(i)]);
        if (m.spindle) next.rotaryAxisMode[static_cast<size_t>(m.spindleIndex)] = 1;
    }
    (void)current;
    return true;
}

bool BlockExecutor::transformationOn(const BlockContext& c, const BlockInput& in, ModalState& next,
                                     bool restoring) const {
    const int wanted = in.g[kGroupTransformation];
    if (in.hasRadius && wanted != 32)
        return c.error("RI_WITHOUT_G32", "RI (effective radius) belongs to G32", in.radiusColumn);
    if (wanted != 31 && wanted != 32) return true;
    const int column = in.gColumn[kGroupTransformation];
    const bool already = next.transformation.kind() == wanted;
    // ADJUST / REPOS (a re-entry point is set) may write G32 without RI, as
    // seed 000, 7.2 does: the RI of the last G32 of the computing process.
    const bool reuseRadius = restoring && !in.hasRadius && next.lastEffectiveRadius > 0.0;
    // RI is a length: in inch under G70 like the positions (seed 003, 4.2 "[mm]
    // or [inch]"); the transformation works in mm.
    const double unit = millimetresPerUnit(next);
    const double radius = reuseRadius ? next.lastEffectiveRadius : in.radius * unit;
    std::vector<PlaneProblem> problems =
        wanted == 32 ? next.transformation.selectCylinder(*setup_.axes, next.plane,
                                                          in.hasRadius || reuseRadius, radius)
                     : next.transformation.selectFacing(*setup_.axes, next.plane);
    if (!reportProblems(c, problems, column)) return false;
    if (already) return true;
    next.g[kGroupTransformation] = static_cast<std::int16_t>(wanted);
    next.g[kGroupZeroOffset] = 53;      // seed 003, 4.4: all zero shifts off on select
    next.g[kGroupRadiusDiameter] = 15;  // radius programming while active
    if (wanted == 32) next.lastEffectiveRadius = radius;
    return true;
}

void BlockExecutor::explicitGroups(const BlockInput& in, ModalState& next) const {
    constexpr std::uint32_t kExplicitMask = (1u << kGroupInterpolation) | (1u << kGroupZeroOffset) |
                                            (1u << kGroupRadiusDiameter) |
                                            (1u << kGroupSurfaceSpeed);
    if (!(in.gMask & kExplicitMask)) return;
    for (int group :
         {kGroupInterpolation, kGroupZeroOffset, kGroupRadiusDiameter, kGroupSurfaceSpeed})
        if (in.g[static_cast<size_t>(group)] >= 0)
            next.g[static_cast<size_t>(group)] = in.g[static_cast<size_t>(group)];
}

/// Longest dwell (G4 F, seconds): about 28 hours. A larger value would keep
/// the simulated station waiting without end (issue 15 §1).
constexpr double kMaxDwellSeconds = 99999.999;

bool BlockExecutor::scalars(const BlockContext& c, const BlockInput& in, BlockPlan& plan) const {
    ModalState& next = plan.next;
    const double unit = millimetresPerUnit(next);
    if (in.dwell) {
        if (!in.hasFeed)
            return c.error("DWELL_TIME_MISSING", "G4 needs the dwell time in F (seconds)",
                           in.dwellColumn);
        if (!(in.feed >= 0.0 && in.feed <= kMaxDwellSeconds))  // I-017a, NaN too
            return c.error("DWELL_TIME_RANGE",
                           "G4 dwell time must lie between 0 and 99999.999 seconds",
                           in.dwellColumn);
        plan.dwellSeconds = in.feed;
        next.time += in.feed;
    } else if (in.hasFeed) {
        next.feed = in.feed * unit;
    }
    if (in.hasTool) {
        if (in.tool != 0 && !setup_.tools->find(in.tool))
            return c.error("TOOL_UNKNOWN",
                           "T" + std::to_string(in.tool) +
                               " is not in the current tools list of process " +
                               std::to_string(setup_.config->index),
                           in.toolColumn);
        if (in.tool != 0) checkGneTool(c, in);
        next.tool = in.tool;
    }
    if (in.hasEdge) next.edge = in.edge;
    if (in.hasCorrection) next.correction = in.correction;
    return in.spindleMask == 0 || spindles(c, in, next);
}

void BlockExecutor::checkGneTool(const BlockContext& c, const BlockInput& in) const {
    const Block block = c.program.blocks[c.blockIndex];
    const std::string_view comment = c.program.text(block.comment);
    gne::ToolAssumption assumed;
    if (comment.rfind("GNE TOOL", 0) != 0 ||
        !gne::parseToolBlock("T" + std::to_string(in.tool) + " ;" + std::string(comment), assumed))
        return;
    // The edge of the block (E), else the tool's first edge, as the tool list has it.
    const ToolEdge* edge = setup_.tools->edge(in.tool, in.hasEdge ? in.edge : 0);
    ToolConfig actual;
    if (edge) {
        actual.number = in.tool;
        actual.radius = edge->totalRadius();
        actual.edgeOrientation = edge->orientation;
    }
    std::string message;
    for (const std::string& problem : gne::checkToolAssumption(assumed, edge ? &actual : nullptr))
        message += (message.empty() ? "" : "; ") + problem;
    if (!message.empty()) c.warning("GNE_TOOL_MISMATCH", message, in.toolColumn);
}

bool BlockExecutor::spindles(const BlockContext& c, const BlockInput& in, ModalState& next) const {
    const int reference = next.referenceSpindle;
    if ((in.spindleMask & 1u) && (in.spindleMask & (1u << reference)))
        return c.error("WORD_TWICE", "S and S" + std::to_string(reference) +
                                         " both program the reference spindle");
    for (int slot = 0; slot < kSpindleSlots; ++slot) {
        if (!((in.spindleMask >> slot) & 1u)) continue;
        const int spindle = slot == 0 ? reference : slot;
        const double speed = in.spindle[static_cast<size_t>(slot)];
        // A speed in rpm (G97) above the spindle's max_speed is refused
        // (issue 22 §6; docs/decisions/motion.md MOT-010). Under G96 S is a
        // cutting speed, and G92 S is itself a limit.
        if (!in.speedLimit && next.g[kGroupSurfaceSpeed] != 96) {
            const double limit = maxSpindleSpeed(spindle);
            if (limit > 0.0 && !(std::fabs(speed) <= limit))
                return c.error("SPEED_ABOVE_MAXIMUM", "S" + std::to_string(spindle) + " " +
                                                          formatNumber(speed) +
                                                          " rpm is above the spindle's max_speed " +
                                                          formatNumber(limit) + " rpm");
        }
        auto& target = in.speedLimit ? next.spindleLimit : next.spindleSpeed;
        target[static_cast<size_t>(spindle)] = speed;
    }
    return true;
}

double BlockExecutor::maxSpindleSpeed(int spindle) const {
    const int axis = setup_.axes->spindleAxis(spindle);
    if (axis < 0 || static_cast<std::size_t>(axis) >= setup_.config->axes.size()) return 0.0;
    return setup_.config->axes[static_cast<std::size_t>(axis)].maxSpeed;
}

// Inline in planGeneral, its only caller: one call and frame less per block with M or Q.
[[gnu::always_inline]] inline bool BlockExecutor::auxiliaries(const BlockContext& c,
                                                              const BlockInput& in,
                                                              const InterpreterState& state,
                                                              BlockPlan& plan) const {
    plan.auxChanged = true;
    plan.mGroups = state.mGroups;
    plan.lastQ = state.lastQ;
    std::uint32_t seen = 0;  // bit g: an M of group g (1..15) in the block
    for (int i = 0; i < in.mCount; ++i) {
        const int m = in.m[static_cast<size_t>(i)].value;
        const int column = in.m[static_cast<size_t>(i)].column;
        if (m > 999) return refuse(c, "M_RANGE", "M functions are M0..M999", column);
        const int group = (*setup_.mGroupOf)[static_cast<size_t>(m)];
        const std::uint32_t bit = group < 16 ? 1u << group : 0u;
        if (seen & bit) return twoOfOneMGroup(c, group, column);
        seen |= bit;
        plan.mGroups[static_cast<size_t>(group)] = m;
        if (AuxFunctionGroups::isProgramControl(m)) {
            if (plan.programControl >= 0)
                return refuse(c, "M_GROUP_CONFLICT", "two program control functions in one block",
                              column);
            plan.programControl = m;
        }
        const int spindle = m / 100 == 0 ? 1 : m / 100;
        const int function = m % 100;
        if ((function == 3 || function == 4 || function == 19) && spindle < kSpindleSlots)
            plan.next.rotaryAxisMode[static_cast<size_t>(spindle)] = 0;
    }
    if (in.qCount > 0) plan.lastQ = in.q[static_cast<size_t>(in.qCount - 1)].value;
    return true;
}

bool BlockExecutor::axisFunction(const BlockContext& c, const BlockInput& in,
                                 const InterpreterState& state, BlockPlan& plan,
                                 const PlanningOptions& options) const {
    const int g = in.axisFunction;
    const int column = in.axisFunctionColumn;
    const std::string name = "G" + std::to_string(g);
    if (in.g[kGroupPlane] == 20 || in.centerMask != 0 || in.dwell)
        return c.error("AXIS_FUNCTION_COMBINATION",
                       name + " cannot be combined with G20, G4 or circle centres", column);
    if (g == 77) return reposition(c, in, state, plan);
    if (in.axisMask == 0)
        return c.error("AXIS_FUNCTION_NO_AXIS", name + " needs the axes it acts on", column);
    ModalState& next = plan.next;
    if (g == 75) {  // the simulated drive meets no stop: it reaches the programmed point
        const auto interpolation = next.g[kGroupInterpolation];
        next.g[kGroupInterpolation] = 1;
        const bool ok = motion_.plan(c, in, state.modal, plan, options);
        next.g[kGroupInterpolation] = interpolation;
        return ok;
    }
    for (int a = 0; in.axisMask >> a; ++a) {  // G74: reference point = machine 0 (in range)
        if (!((in.axisMask >> a) & 1u)) continue;
        const AxisModel& m = setup_.axes->axis(a);
        double home = 0.0;
        if (m.limited()) home = std::min(std::max(home, m.minPosition), m.maxPosition);
        next.machine[static_cast<size_t>(a)] = home;
        if (m.spindle) next.rotaryAxisMode[static_cast<size_t>(m.spindleIndex)] = 1;
    }
    motion_.recomputeWork(next);
    machineMove(state.modal, in.axisMask, 0.0, plan);
    return true;
}

bool BlockExecutor::reposition(const BlockContext& c, const BlockInput& in,
                               const InterpreterState& state, BlockPlan& plan) const {
    const ReentryPoint& r = state.reentry;
    const int column = in.axisFunctionColumn;
    if (!r.valid)
        return c.error("REPOS_NO_REENTRY_POINT",
                       "G77 needs a re-entry point: it runs in the REPOS subroutine after an NC "
                       "program restart",
                       column);
    if (in.axisMask == 0 && in.spindleMask == 0)
        return c.error("AXIS_FUNCTION_NO_AXIS", "G77 needs the axes or spindles to re-establish",
                       column);
    ModalState& next = plan.next;
    for (int slot = 0; slot < kSpindleSlots; ++slot) {  // G77 S0 / S1=0: spindle mode, old speed
        if (!((in.spindleMask >> slot) & 1u)) continue;
        const auto j = static_cast<size_t>(slot == 0 ? next.referenceSpindle : slot);
        next.spindleSpeed[j] = r.spindleSpeed[j];
        next.rotaryAxisMode[j] = 0;
    }
    const double unit = millimetresPerUnit(next);
    const double feed = in.hasFeed ? in.feed * unit : state.modal.feed;
    next.feed = state.modal.feed;  // F of a G77 block is the repositioning feed only
    for (int a = 0; in.axisMask >> a; ++a) {
        if (!((in.axisMask >> a) & 1u)) continue;
        const AxisModel& m = setup_.axes->axis(a);
        next.machine[static_cast<size_t>(a)] = r.machine[static_cast<size_t>(a)];
        if (m.spindle) next.rotaryAxisMode[static_cast<size_t>(m.spindleIndex)] = 1;
    }
    motion_.recomputeWork(next);
    if (in.axisMask != 0) machineMove(state.modal, in.axisMask, feed, plan);
    return true;
}

void BlockExecutor::machineMove(const ModalState& current, std::uint32_t moved, double feed,
                                BlockPlan& plan) const {
    ModalState& next = plan.next;
    double squares = 0.0, rapidSeconds = 0.0;
    for (int a = 0; moved >> a; ++a) {
        if (!((moved >> a) & 1u)) continue;
        const double d =
            next.machine[static_cast<size_t>(a)] - current.machine[static_cast<size_t>(a)];
        squares += d * d;
        rapidSeconds =
            std::max(rapidSeconds, std::fabs(d) * setup_.axes->axis(a).rapidSecondsPerUnit);
    }
    plan.hasMotion = true;
    plan.motionType = feed > 0.0 ? MotionType::Linear : MotionType::Rapid;
    plan.feedRate = feed > 0.0 ? feed : 0.0;
    plan.planeAxis1 = plan.planeAxis2 = -1;
    next.time += feed > 0.0 ? std::sqrt(squares) / feed * 60.0 : rapidSeconds;
}

}  // namespace mtc::core
