#pragma once

#include <array>
#include <cstdint>

#include "cnc_core/interp/BlockContext.h"
#include "cnc_core/interp/BlockInput.h"
#include "cnc_core/interp/BlockPlan.h"
#include "cnc_core/interp/InterpreterState.h"
#include "cnc_core/interp/MotionPlanner.h"
#include "cnc_core/interp/PlanningOptions.h"
#include "cnc_core/machine/MachineConfig.h"
#include "cnc_core/machine/ProcessAxes.h"
#include "cnc_core/machine/ZeroOffsetTable.h"
#include "cnc_core/tooldata/ToolList.h"

namespace mtc::core {

/// Second stage of a block: from the decoded words and the current state,
/// computes the complete effect of the block (BlockPlan) and checks every
/// rule that involves more than one word: G20 and G31/G32 boundary
/// conditions, RI usage, tool existence, M group conflicts, then the motion
/// (MotionPlanner). Order inside a block: simple modal groups, G30, plane,
/// G31/G32 (with their forced G1/G97 and G53/G15), zero offset, F S T E D,
/// M and Q, motion. Never changes the interpreter state.
class BlockExecutor {
  public:
    struct Setup {
        const ProcessConfig* config = nullptr;
        const ProcessAxes* axes = nullptr;
        const ZeroOffsetTable* offsets = nullptr;
        const ToolList* tools = nullptr;  ///< the process's tool list (T must be in it)
        const GGroupValues* defaults = nullptr;
        const std::array<std::uint8_t, 1000>* mGroupOf = nullptr;  ///< M number -> group 1..16
    };

    explicit BlockExecutor(const Setup& setup)
        : setup_(setup), motion_(setup.axes, setup.offsets) {}

    /// Fills `plan` for `input`. Precondition: plan.next equals state.modal
    /// (the interpreter keeps it so, which saves a copy per block). Returns
    /// false when the block must be rejected (errors added through `context`).
    /// Inline for the usual block (I-023) with no G word but G0..G3 and no
    /// axis written twice: what planGeneral() does for it, without a call of
    /// its own (InterpShortcuts.* compare with options.shortcuts off).
    bool plan(const BlockContext& context, const BlockInput& input, const InterpreterState& state,
              BlockPlan& plan, const PlanningOptions& options) const {
        constexpr std::uint32_t kOtherGroups = ~(1u << kGroupInterpolation);
        if (!options.shortcuts || input.special || input.repeatedAxisColumn != 0 ||
            (input.gMask & kOtherGroups) != 0)
            return planGeneral(context, input, state, plan, options);
        clearPlan(plan);
        ModalState& next = plan.next;
        if (input.gMask != 0) next.g[kGroupInterpolation] = input.g[kGroupInterpolation];
        if (input.hasFeed) next.feed = input.feed * millimetresPerUnit(next);
        if (input.axisMask == 0) return true;  // (no G20: only group 1 is programmed)
        return motion_.plan(context, input, state.modal, plan, options);
    }

  private:
    /// plan() of every block.
    bool planGeneral(const BlockContext& context, const BlockInput& input,
                     const InterpreterState& state, BlockPlan& plan,
                     const PlanningOptions& options) const;
    /// What a block without motion, dwell, program control or aux functions plans.
    static void clearPlan(BlockPlan& plan) {
        plan.hasMotion = false;
        plan.dwellSeconds = -1.0;
        plan.programControl = -1;
        plan.auxChanged = false;
    }
    /// G words (and RI): plain groups, G30, plane, G31/G32, explicit groups.
    /// `restoring`: a re-entry point is set (ADJUST / REPOS), G32 may omit RI.
    bool modalGroups(const BlockContext& c, const BlockInput& in, const ModalState& current,
                     ModalState& next, bool restoring) const;
    bool transformationOff(const BlockContext& c, const BlockInput& in, ModalState& next) const;
    bool planeChange(const BlockContext& c, const BlockInput& in, const ModalState& current,
                     ModalState& next) const;
    bool transformationOn(const BlockContext& c, const BlockInput& in, ModalState& next,
                          bool restoring) const;
    void explicitGroups(const BlockInput& in, ModalState& next) const;
    bool scalars(const BlockContext& c, const BlockInput& in, BlockPlan& plan) const;
    /// The seed 001 ch. 3 caution: a "T.. ;GNE TOOL ..." block of a GNE
    /// cycle warns when the tool list differs from the data the cycle was
    /// programmed with (ToolCheck.h, docs/decisions/gne.md G-011).
    void checkGneTool(const BlockContext& c, const BlockInput& in) const;
    bool spindles(const BlockContext& c, const BlockInput& in, ModalState& next) const;
    /// max_speed (rpm) of spindle 1..3 in the configuration; 0 = none / not limited.
    double maxSpindleSpeed(int spindle) const;
    bool auxiliaries(const BlockContext& c, const BlockInput& in, const InterpreterState& state,
                     BlockPlan& plan) const;
    /// G74 (homing: to machine 0 within the travel range), G75 (hard stop: a
    /// G1 move to the programmed point) and G77 (REPOS) of the block.
    bool axisFunction(const BlockContext& c, const BlockInput& in, const InterpreterState& state,
                      BlockPlan& plan, const PlanningOptions& options) const;
    /// G77: programmed axes to state.reentry (the axis values are placeholders),
    /// programmed spindles back to spindle mode with their re-entry speed.
    bool reposition(const BlockContext& c, const BlockInput& in, const InterpreterState& state,
                    BlockPlan& plan) const;
    /// A straight move of the `moved` axes from current.machine to plan.next.machine
    /// (rapid when feed <= 0), with its simulated time.
    void machineMove(const ModalState& current, std::uint32_t moved, double feed,
                     BlockPlan& plan) const;

    Setup setup_;
    MotionPlanner motion_;
};

}  // namespace mtc::core
