// Batching of the simulated machine (docs/decisions/motion.md MOT-022): the
// interpreter runs a batch of blocks ahead, the machine works them off in
// one go, and everything the interpreter's side reads of the machine's
// progress (the trend clock) comes out as without the batch.
#include <algorithm>

#include "cnc_core/afc/AdaptiveFeedControl.h"
#include "cnc_core/machine/SimulatedMachine.h"

namespace mtc::core {

namespace {
/// Seconds one engine call may take while catching up: a move that needs
/// longer stands for good (feed hold, override 0 %), nothing to catch up.
constexpr double kCatchUpSeconds = 1e9;
/// Taken clock steps kept before they are dropped (dropTakenClockSteps()).
constexpr std::size_t kClockStepsKept = 256;

/// The trend clock after a step of `seconds` taken at busy time `busy`.
double clockAfter(double clock, double busy, double seconds) {
    return std::max(clock, busy) + seconds;
}
}  // namespace

void SimulatedMachine::setBatch(std::size_t entries) {
    engine_.setBatch(entries);
    blockDue_ = 0;
    if (afc_)
        afc_->setClockSync(entries > 0 ? std::function<void()>([this] { catchUp(); })
                                       : std::function<void()>());
}

void SimulatedMachine::beginBlock() {
    engine_.beginBlock();
    if (engine_.batch() == 0) return;
    // Without a batch the block would be queued the moment fewer than the
    // look-ahead depth were queued: once item (start - depth) is done.
    const std::uint64_t start = engine_.blockStart();
    const std::uint64_t depth = engine_.lookAhead();
    blockDue_ = start >= depth ? start - depth + 1 : 0;
}

void SimulatedMachine::queueClock(double seconds) {
    if (engine_.itemsDone() < blockDue_) {
        clockSteps_.push_back({blockDue_, seconds});
        return;
    }
    applyClockSteps();
    stepClock(seconds, this->seconds());
}

void SimulatedMachine::stepClock(double seconds, double busy) {
    afcClock_ = clockAfter(afcClock_, busy, seconds);
    if (afc_) afc_->setClock(afcClock_);
}

void SimulatedMachine::applyClockSteps() {
    for (; clockStepsDone_ < clockSteps_.size(); ++clockStepsDone_) {
        const ClockStep& step = clockSteps_[clockStepsDone_];
        if (step.itemsDone > engine_.itemsDone()) return dropTakenClockSteps();
        stepClock(step.seconds, seconds());
    }
    clockSteps_.clear();  // all taken: the storage is used again from its start
    clockStepsDone_ = 0;
}

void SimulatedMachine::applyClockStepsAfter(std::uint64_t doneBefore) {
    // A driver returning after every entry took each step at the busy time
    // of the first return with the step's items done: the end of item
    // `itemsDone`, or (a step due before the call) the first return's.
    const std::uint64_t done = engine_.itemsDone();
    const std::size_t first = clockStepsDone_;
    for (; clockStepsDone_ < clockSteps_.size(); ++clockStepsDone_) {
        const ClockStep& step = clockSteps_[clockStepsDone_];
        if (step.itemsDone > done) break;
        const std::uint64_t at = step.itemsDone > doneBefore ? step.itemsDone - doneBefore : 1;
        const double busy = at <= finishedAt_.size() ? finishedAt_[at - 1] : seconds();
        afcClock_ = clockAfter(afcClock_, busy, step.seconds);
    }
    // Adaptive feed control reads its clock after this call, not between
    // the steps: the last one's is the one to give it.
    if (afc_ && clockStepsDone_ != first) afc_->setClock(afcClock_);
    if (clockStepsDone_ < clockSteps_.size()) return dropTakenClockSteps();
    clockSteps_.clear();
    clockStepsDone_ = 0;
}

void SimulatedMachine::dropTakenClockSteps() {
    // A batch keeps some steps waiting at all times: the taken ones go in
    // chunks, the few waiting ones move to the front.
    if (clockStepsDone_ < kClockStepsKept) return;
    clockSteps_.erase(clockSteps_.begin(),
                      clockSteps_.begin() + static_cast<std::ptrdiff_t>(clockStepsDone_));
    clockStepsDone_ = 0;
}

void SimulatedMachine::catchUp() {
    // The engine returns after every finished entry: each clock step is
    // taken at the busy time the machine had when it would have been queued.
    while (engine_.itemsDone() < blockDue_ && !engine_.idle()) {
        const std::uint64_t before = engine_.itemsDone();
        engine_.advance(kCatchUpSeconds);
        collectReached();
        applyClockSteps();
        if (engine_.itemsDone() == before) break;
    }
    applyClockSteps();
}

}  // namespace mtc::core
