// RestartSequence, second half: ADJUST and REPOS on the process's own
// interpreter, the re-entry, and the way back to a consistent state.
#include "cnc_core/afc/AdaptiveFeedControl.h"
#include "cnc_core/interp/ProgramFlow.h"
#include "cnc_core/restart/RestartSequence.h"

namespace mtc::core {

void RestartSequence::auxiliary(const AuxOutput& output, bool forwarded) {
    if (forwarded) sps_.auxiliary(output);  // Q9500 / Q9501 change the mode
}

StopTarget RestartSequence::reentryTarget() const {
    return {computing_.route().targetProgram->number, computing_.selection().target.block, 1};
}

bool RestartSequence::beginAdjust() {
    std::uint32_t block = 0;
    if (!ProgramFlow(programs_, live_.config().index, nullptr)
             .findLabel(live_.state().selected, "ADJUST", adjustProgram_, block)) {
        const int program = live_.state().selected ? live_.state().selected->number : 0;
        fail("RESTART_ADJUST_MISSING",
             "the ADJUST subroutine (label .ADJUST) is neither in program " +
                 std::to_string(program) + ", nor in program 99, nor in the cycle memory");
        return false;
    }
    const long repos = adjustProgram_->findLabel("REPOS");
    reposBlock_.reset();
    if (repos > static_cast<long>(block)) {
        reposBlock_ = static_cast<std::uint32_t>(repos);
    } else {
        diagnostics_.warning("RESTART_REPOS_MISSING", locationOf(*adjustProgram_, block),
                             "no .REPOS label after .ADJUST in program " +
                                 std::to_string(adjustProgram_->number) +
                                 ": ADJUST runs up to its RTS and nothing is repositioned");
    }
    // ADJUST is called from the target block: its RTS (at the end of REPOS)
    // returns there.
    InterpreterState state = live_.state();
    state.callStack.push_back({state.program, state.block, state.block});
    adjustDepth_ = state.callStack.size();
    state.program = adjustProgram_;
    state.block = block;
    live_.restoreState(state);
    live_.setObserver(this);
    live_.setStopTarget(reposBlock_ ? StopTarget{adjustProgram_->number, *reposBlock_, 1}
                                    : reentryTarget());
    phase_ = RestartPhase::Adjusting;
    return true;
}

bool RestartSequence::returnBeforeRepos() const {
    if (phase_ != RestartPhase::Adjusting || !reposBlock_) return false;
    const InterpreterState& s = live_.state();
    if (s.callStack.size() != adjustDepth_ || !s.program) return false;
    if (s.program == adjustProgram_ && s.block == *reposBlock_) return false;  // REPOS begins
    if (s.block >= s.program->blocks.size()) return false;
    if ((s.program->blocks[s.block].flags & kBlockSkip) && live_.options().skipBlocks) return false;
    const std::optional<Word> word = jumpWordOf(*s.program, s.block);
    return word && word->jump == JumpKind::RTS;
}

void RestartSequence::runLive(std::uint64_t maxBlocks) {
    for (std::uint64_t i = 0; i < maxBlocks; ++i) {
        if (phase_ != RestartPhase::Adjusting && phase_ != RestartPhase::Repositioning) return;
        if (held_) return;
        if (returnBeforeRepos()) {  // seed 000, 5.3: ADJUST has no RTS before .REPOS
            fail("RESTART_ADJUST_RTS",
                 "ADJUST ends with RTS before .REPOS: it would return to the target block and "
                 "run the program as ADJUST; the block is not executed and nothing moves "
                 "(seed 000, 5.3: ADJUST falls through into REPOS without RTS)");
            return;
        }
        if (liveBlocks_ >= budget_) {
            fail("BLOCK_BUDGET", "ADJUST and REPOS were stopped after " + std::to_string(budget_) +
                                     " interpreted blocks (block budget)");
            return;
        }
        if (!handleLive(live_.step())) return;
    }
}

bool RestartSequence::handleLive(const RunResult& result) {
    liveBlocks_ += result.blocksInterpreted;
    diagnostics_.append(result.diagnostics);
    switch (result.status) {
        case RunStatus::Running:
        case RunStatus::BudgetExceeded:
            if (control_.mode() == OperatingMode::Manual) {  // Q9500: interrupted after the block
                resumePhase_ = phase_;
                phase_ = RestartPhase::ManualMode;
                return false;
            }
            if (control_.singleBlock() && result.blocksInterpreted > 0) {
                held_ = true;
                setSignal("SHOLD", 1);
                return false;
            }
            return true;
        case RunStatus::Stopped:
            held_ = true;
            setSignal("SHOLD", 1);
            return false;
        case RunStatus::TargetReached:
            return liveTarget();
        case RunStatus::Ended:
            fail("RESTART_ADJUST_ENDED",
                 "ADJUST / REPOS ended the program (BST, RET, M02, M30) instead of returning to "
                 "the target block with RTS");
            return false;
        case RunStatus::Error:
            resetAll(RestartPhase::Failed);
            return false;
    }
    return false;
}

bool RestartSequence::liveTarget() {
    const InterpreterState& state = live_.state();
    if (phase_ == RestartPhase::Adjusting && reposBlock_ && state.program == adjustProgram_ &&
        state.block == *reposBlock_) {
        phase_ = RestartPhase::Repositioning;  // ADJUST falls through into REPOS
        live_.setStopTarget(reentryTarget());
        return true;
    }
    const StopTarget target = reentryTarget();
    if (state.program && state.program->number == target.program && state.block == target.block &&
        atRouteLevel(state, computing_.route())) {
        reestablished();
        return false;
    }
    // The target block inside ADJUST / REPOS (e.g. in a shared subroutine): run it.
    live_.setStopTarget(std::nullopt);
    const RunResult result = live_.step();
    live_.setStopTarget(phase_ == RestartPhase::Adjusting && reposBlock_
                            ? StopTarget{adjustProgram_->number, *reposBlock_, 1}
                            : target);
    return handleLive(result);
}

void RestartSequence::reestablished() {
    restoreAdaptiveFeed();
    live_.setStopTarget(std::nullopt);
    live_.setObserver(nullptr);
    liveChanged_ = false;
    setSignal("SCREST", 1);
    phase_ = RestartPhase::Reestablished;
    sps_.cycle();
    react();
    control_.setKeyHandler(nullptr);
}

void RestartSequence::restoreAdaptiveFeed() {
    // G26 is a state of the NC the computing process determined (seed 000,
    // 2.8); ADJUST and REPOS run without it (G77 excludes it), the program
    // goes on with it.
    AdaptiveFeedControl* afc = live_.adaptiveFeed();
    const bool wanted = live_.state().modal.adaptiveFeed;
    if (!afc || afc->active() == wanted) return;
    if (!wanted) {
        afc->switchOff();
        return;
    }
    const int transformation = live_.state().modal.g[kGroupTransformation];
    std::vector<int> active;
    if (transformation != 30) active.push_back(transformation);
    if (afc->switchOn(active) != AfcStatus::Ok) {
        const std::vector<StackLevel> levels = live_.callStack();
        const StackLevel at = levels.empty() ? StackLevel{} : levels.back();
        diagnostics_.warning("RESTART_AFC_NOT_RESTORED", {at.program, at.block, at.line, 0},
                             "adaptive feed control (G26) of the target could not be switched "
                             "on again: " +
                                 afc->message());
    }
}

void RestartSequence::fail(const std::string& code, const std::string& message) {
    const std::vector<StackLevel> levels = live_.callStack();
    const StackLevel at = levels.empty() ? StackLevel{} : levels.back();
    diagnostics_.error(code, {at.program, at.block, at.line, 0}, message);
    const std::string alarm = messageLine(diagnostics_.items().back(), language_);
    resetAll(RestartPhase::Failed);
    control_.setAlarm(alarm);
}

void RestartSequence::resetAll(RestartPhase phase) {
    takeComputingDiagnostics();  // the warnings of its start and the error that ended it
    if (liveChanged_) {
        live_.setObserver(nullptr);
        live_.setStopTarget(std::nullopt);
        live_.controlReset();  // positions stay where the axes are
        liveChanged_ = false;
    }
    held_ = false;
    computing_.cancelTransfers();  // a waiting GAX / FAX is withdrawn
    setSignal("SBPACT", 0);
    setSignal("SREPOS", 0);
    setSignal("SCREST", 0);
    setSignal("SHOLD", 0);
    setSignal("CADV", 0);
    control_.setProgramActive(false);
    phase_ = phase;
    sps_.cycle();
    control_.setKeyHandler(nullptr);
}

}  // namespace mtc::core
