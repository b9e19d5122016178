#include "cnc_core/mdi/MdiRun.h"

namespace mtc::core {

bool MdiRun::begin(Interpreter& interpreter, ProgramPtr program, DiagnosticList* diagnostics) {
    if (active()) abandon();
    ProgramPtr previous = interpreter.state().selected;
    if (!interpreter.select(program, 0, diagnostics)) return false;
    interpreter_ = &interpreter;
    program_ = std::move(program);
    previous_ = std::move(previous);
    return true;
}

bool MdiRun::entryDone() const {
    const InterpreterState& state = interpreter_->state();
    // A subroutine the entry called runs in another program: not done yet.
    return state.program == program_ && state.callStack.empty() &&
           state.block >= program_->blocks.size();
}

RunResult MdiRun::step() {
    RunResult result;
    if (!active()) {
        result.status = RunStatus::Error;
        result.diagnostics.error("MDI_NOT_ACTIVE", {}, "no MDI entry is running");
        return result;
    }
    if (entryDone()) {  // past the last block: no program end, the state stays
        abandon();
        result.status = RunStatus::Ended;
        return result;
    }
    result = interpreter_->step();
    if (result.status == RunStatus::Running && entryDone()) {
        abandon();  // the last block was executed: the entry ends with it
        result.status = RunStatus::Ended;
        return result;
    }
    if (result.status == RunStatus::Ended || result.status == RunStatus::Error ||
        result.status == RunStatus::BudgetExceeded)
        abandon();
    return result;
}

RunResult MdiRun::run(std::uint64_t budget) {
    RunResult total;
    for (;;) {
        if (total.blocksInterpreted >= budget) {
            total.diagnostics.error(
                "BLOCK_BUDGET", {},
                "the MDI entry did not end within " + std::to_string(budget) + " blocks");
            total.status = RunStatus::BudgetExceeded;
            abandon();
            return total;
        }
        RunResult one = step();
        total.blocksInterpreted += one.blocksInterpreted;
        total.diagnostics.append(one.diagnostics);
        total.status = one.status;
        if (one.status != RunStatus::Running) return total;
    }
}

void MdiRun::abandon() {
    if (!interpreter_) return;
    Interpreter& interpreter = *interpreter_;
    interpreter_ = nullptr;
    // Back to the program of the automatic mode (select() keeps the modal
    // state, positions and variables); without one the entry stays selected.
    if (previous_) interpreter.select(previous_, 0);
    previous_.reset();
}

}  // namespace mtc::core
