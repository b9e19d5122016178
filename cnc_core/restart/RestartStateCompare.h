#pragma once

#include <array>
#include <string>
#include <vector>

#include "cnc_core/interp/InterpreterState.h"
#include "cnc_core/machine/ProcessAxes.h"
#include "cnc_core/restart/FunctionBuffer.h"

namespace mtc::core {

/// What the machine itself executed, as opposed to what the NC remembers:
/// the last M function of each group 1..15 and the speed of each spindle
/// that reached the SPS and the drives outside the computing process (seed
/// 000, 3.1: the computing process outputs nothing the machine acts on).
struct MachineAuxState {
    std::array<int, 17> mGroups{};                     ///< index 1..15
    std::array<double, kSpindleSlots> spindleSpeed{};  ///< index 1..3
};

/// One side of a comparison: the NC's state, and optionally the page 61
/// buffers and the machine's own aux state.
struct RestartStateView {
    const InterpreterState* nc = nullptr;
    /// Page 61 sub 1 (M(16)) and sub 2 (Q), oldest first; nullptr = not compared.
    const std::array<int, FunctionBuffer::kLength>* m16Buffer = nullptr;
    const std::array<int, FunctionBuffer::kLength>* qBuffer = nullptr;
    /// The machine's M groups and spindle speeds; nullptr = the NC's memory
    /// stands for them (a normal run executes everything it outputs).
    const MachineAuxState* machine = nullptr;
    /// Where the axes stand with tool compensation applied (radius, cutting
    /// edge, length; compensation.md TC-013), compared in the Cutting scope
    /// when both sides have them; nullptr = not compared.
    const std::array<double, kMaxAxes>* axes = nullptr;
};

/// What a comparison covers (restart.md R-028).
enum class CompareScope {
    /// The computing process against a normal run at the same arrival: G
    /// groups, M groups 1..15 and the last M(16) / Q, page 60, page 61, S
    /// (and G92 limits), T, E, D, F, adaptive feed on/off, variables,
    /// commanded positions, call stack.
    Computed,
    /// After ADJUST and REPOS against the target: what matters for cutting —
    /// G groups (interpolation, plane, zero offset, dimension, ...), plane
    /// allocation and RI, T, E, D, the tools in the tool spindles, spindle
    /// modes and speeds, M groups 2..15 (spindles, gears, coolant, clamps)
    /// as the machine executed them, F, adaptive feed on/off, commanded
    /// positions and where the axes stand (tool compensation applied).
    Cutting,
};

/// One item that differs. `what` is a stable key ("g1", "m5", "s1", "t",
/// "tool_spindle1", "rotary_axis_mode1", "f", "@100", "position.X",
/// "page61.m16", "call_stack", "axis.X", ...); numbers when the item is a number.
struct StateDifference {
    std::string what;
    std::string label;  ///< for people: "G group 1 (interpolation)"
    bool numeric = true;
    double expected = 0.0;
    double actual = 0.0;
    std::string expectedText;  ///< the values as text (also for numbers)
    std::string actualText;
};

/// The one state comparison of NC program restart (the verifier, the CLI
/// and the result review screen use it): every item of `scope` where
/// `actual` differs from `expected`, in a fixed order. Positions and speeds
/// compare within 1e-6; the rest exactly.
std::vector<StateDifference> compareRestartStates(const RestartStateView& expected,
                                                  const RestartStateView& actual,
                                                  CompareScope scope, const ProcessAxes& axes);

/// "G group 1 (interpolation)", "M group 5", ... for a difference key.
std::string describeStateItem(const std::string& what);

}  // namespace mtc::core
