#pragma once

namespace mtc::core {

/// The interpreter options that block planning (BlockExecutor, MotionPlanner)
/// reads. Passed with every plan() call rather than copied into the planners,
/// so a change of InterpreterOptions between two blocks needs no second copy
/// to be kept in step (InterpreterOptions derives from this).
struct PlanningOptions {
    double arcTolerance = 0.002;  ///< mm, radius difference allowed between start and end
    /// false: every block takes the general functions, none of the shortcuts
    /// of the usual block (docs/decisions/interpreter.md I-022) nor the
    /// planner's frame path (motion.md MOT-025). The same run either way;
    /// the reference the shortcuts are checked against (tests, the
    /// interpretation benchmark's check run).
    bool shortcuts = true;
};

}  // namespace mtc::core
