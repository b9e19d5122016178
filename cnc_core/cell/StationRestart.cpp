// The station's share of the NC program restart (seed 000): accepting the
// operator's selection, the computing process in block slices, the phases
// of ADJUST / REPOS, and the way back checked against the part (D-021).
#include <chrono>

#include "cnc_core/cell/Station.h"

namespace mtc::core {

void Station::logRestartDiagnostics() {
    const auto& items = restart_.diagnostics().items();
    for (; restartLogged_ < items.size(); ++restartLogged_)
        log_.add(DiagnosticSource::Restart, items[restartLogged_]);
}

void Station::continueAfterRestart() {
    if (!runOnAfterRestart_) return;
    run_ = Run::Program;
    feeding_ = true;
    pending_ = Pending::None;
    ++revision_;
}

bool Station::acceptRestart(const RestartSelection& selection, DiagnosticList& diagnostics,
                            std::uint64_t budget) {
    const InterpreterState snapshot = interpreter_.state();
    if (!restart_.accept(selection, diagnostics, budget)) return false;
    restartLogged_ = 0;  // accept() began a new list
    logRestartDiagnostics();
    restartBefore_ = snapshot;
    restartStarted_ = true;
    beginTrace(control_.selectedProgram());
    // The part a restart's run cuts on is the one at its target block: it
    // is known once the way back is checked (checkReentry()).
    output_.cut = nullptr;
    if (liveCutting_) liveCut_.clear();
    reentryCheck_.reset();
    restartComputingMs_ = 0.0;
    computingSince_ = std::chrono::steady_clock::now();
    followRestartPhase();
    ++revision_;
    return true;
}

void Station::abortRestart() {
    if (!restart_.active()) return;
    restart_.requestAbort();
    std::uint64_t blocks = 0;
    advanceRestart(blocks, 0);
    machine_.stop();
}

bool Station::jogRestart(int axis, double distance) {
    if (axis < 0 || axis >= kMaxAxes) return false;
    // From where the last jog goes (the axis may still be on its way there).
    const double from = machine_.idle() ? machine_.position(axis)
                                        : machine_.lastMoveEnd()[static_cast<std::size_t>(axis)];
    const bool ok = restart_.jog(axis, from + distance);
    if (ok) ++revision_;
    return ok;
}

bool Station::computing() const {
    const RestartPhase phase = restart_.phase();
    return (phase == RestartPhase::Active || phase == RestartPhase::Computing) &&
           !restart_.held() && restart_.waitingFor().empty();
}

void Station::advanceRestart(std::uint64_t& blocks, std::uint64_t maxBlocks) {
    if (!restart_.active()) return followRestartPhase();
    const RestartPhase phase = restart_.phase();
    if (phase == RestartPhase::Active || phase == RestartPhase::Computing) {
        const std::uint64_t before = restart_.computing().blocksSoFar();
        restart_.advance(maxBlocks > blocks ? maxBlocks - blocks : 0);
        blocks += restart_.computing().blocksSoFar() - before;
    } else if (phase == RestartPhase::Adjusting || phase == RestartPhase::Repositioning) {
        // ADJUST and REPOS move the axes block by block, each when the
        // machine has finished the one before (no look-ahead): the sequence
        // sees its phase end (manual mode, state re-established) only when
        // the axes are really there.
        while (machine_.idle() && blocks < maxBlocks && !restart_.held() &&
               (restart_.phase() == RestartPhase::Adjusting ||
                restart_.phase() == RestartPhase::Repositioning)) {
            const std::uint64_t before = restart_.sequenceBlocks();
            restart_.advance(1);
            blocks += std::max<std::uint64_t>(1, restart_.sequenceBlocks() - before);
        }
    } else {
        restart_.advance(0);  // an SPS scan while the sequence waits for the operator
    }
    followRestartPhase();
}

void Station::followRestartPhase() {
    logRestartDiagnostics();
    const RestartPhase phase = restart_.phase();
    if (phase == restartPhase_) return;
    const auto computingPhase = [](RestartPhase p) {
        return p == RestartPhase::Active || p == RestartPhase::Computing;
    };
    if (computingPhase(restartPhase_) && !computingPhase(phase))
        restartComputingMs_ = std::chrono::duration<double, std::milli>(
                                  std::chrono::steady_clock::now() - computingSince_)
                                  .count();
    restartPhase_ = phase;
    ++revision_;
    // State re-established: machining continues at the target block in
    // simulated time, as after Start (seed 000, 2.9 step 9).
    if (phase == RestartPhase::Reestablished) continueAfterRestart();
}

const std::optional<removal::ReentryCheck>& Station::checkReentry() {
    reentryCheck_ = removal::checkRestartReentry(restart_, interpreter_, programs_);
    const removal::PartModel* part = reentryCheck_ ? reentryCheck_->partAtTarget.get() : nullptr;
    // The live part starts from the part at the target only before the way
    // back has moved (a check made later would miss its first moves), and
    // not finer than the view draws quickly (D-021 checks at 0.2 mm
    // whatever the stock).
    if (!liveCutting_ || !part || part->cells() > removal::kViewCells ||
        restart_.phase() != RestartPhase::TargetReached)
        return reentryCheck_;
    liveCut_.beginAt(control_.selectedProgram(), *part);
    output_.cut = &liveCut_;
    ++revision_;
    return reentryCheck_;
}

}  // namespace mtc::core
