#include "hmi/SimulationClock.h"

#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/machine/SimulatedMachine.h"
#include "cnc_core/mdi/MdiEntry.h"

namespace mtc::hmi {

namespace {
constexpr int kTickMs = 20;
constexpr int kMaxBlocksPerTick = 20000;  // keeps a tick well under a frame

std::string firstProblem(const mtc::core::DiagnosticList& diagnostics, const char* fallback) {
    for (const auto& d : diagnostics.items())
        if (d.severity == mtc::core::Severity::Error) return mtc::core::formatDiagnostic(d);
    return fallback;
}
}  // namespace

SimulationClock::SimulationClock(mtc::core::Interpreter& interpreter,
                                 mtc::core::SimulatedMachine& machine,
                                 mtc::core::ProcessControl& control, QObject* parent)
    : QObject(parent), interpreter_(interpreter), machine_(machine), control_(control) {
    timer_.setInterval(kTickMs);
    connect(&timer_, &QTimer::timeout, this, &SimulationClock::tick);
}

std::string SimulationClock::start(int number) {
    // Compile on demand / refuse a program with compiler errors: nothing
    // of the run below has been touched yet when the preparer refuses.
    if (std::string alarm = prepare(number); !alarm.empty()) return alarm;
    mtc::core::DiagnosticList diagnostics;
    if (!interpreter_.select(number, 0, &diagnostics))
        return firstProblem(diagnostics, "the program cannot be selected");
    machine_.reset();
    lastProgram_.reset();
    beginTiming();
    showCurrentBlock();
    return {};
}

std::string SimulationClock::startMdi() {
    if (!mdiSource_) return "Start refused: this station has no MDI input";
    mtc::core::ProgramPtr program;
    if (std::string alarm = mdiSource_(program); !alarm.empty()) return alarm;
    mtc::core::DiagnosticList diagnostics;
    if (!mdi_.begin(interpreter_, program, &diagnostics))
        return firstProblem(diagnostics, "the MDI entry cannot be selected");
    mdiRunning_ = true;
    mdiDiagnostics_.clear();
    lastProgram_.reset();
    beginTiming();
    showCurrentBlock();
    return {};
}

std::string SimulationClock::resume() {
    beginTiming();
    return {};
}

void SimulationClock::hold() {
    timer_.stop();
}

void SimulationClock::reset() {
    timer_.stop();
    interpreter_.controlReset();
    if (mdiRunning_) {  // the entry is abandoned; the automatic program comes back
        mdi_.abandon();
        mdiRunning_ = false;
        emit mdiEnded(false);
    }
    waitingAxis_.clear();
    machine_.reset();
    lastProgram_.reset();
    control_.setCurrentBlock({});
    emit changed();
}

void SimulationClock::beginTiming() {
    simulatedBase_ = machine_.seconds();
    realTime_.start();
    timer_.start();
}

void SimulationClock::tick() {
    using mtc::core::RunStatus;
    const double target = simulatedBase_ + realTime_.elapsed() / 1000.0 * speed_;
    for (int n = 0; n < kMaxBlocksPerTick && machine_.seconds() <= target; ++n) {
        const auto& state = interpreter_.state();
        lastProgram_ = state.program;
        lastBlock_ = state.block;
        auto result = mdiRunning_ ? mdi_.step() : interpreter_.step();
        if (!waitingAxis_.empty() && result.blocksInterpreted > 0) {
            waitingAxis_.clear();  // the GAX was granted
            control_.setAlarm({});
        }
        switch (result.status) {
            case RunStatus::Running:
                if (!control_.singleBlock()) continue;
                // Single-block mode: hold after the block until Start.
                timer_.stop();
                control_.programStopped("Single block: press Start for the next block");
                showCurrentBlock();
                return;
            case RunStatus::Ended:
                if (mdiRunning_) return finishMdi(result);
                return finish({});
            case RunStatus::Stopped:
                if (waitForAxis()) return;
                timer_.stop();
                control_.programStopped("Programmed stop: press Start to continue");
                showCurrentBlock();
                return;
            case RunStatus::TargetReached:
                return finish({});
            case RunStatus::BudgetExceeded:
            case RunStatus::Error:
                if (mdiRunning_) return finishMdi(result);
                return finish(
                    firstProblem(result.diagnostics, "the program stopped with an error"));
        }
    }
    showCurrentBlock();
}

bool SimulationClock::waitForAxis() {
    const std::string axis = interpreter_.waitingForAxis();
    if (axis.empty()) return false;
    // The timer keeps polling (one look per tick); the simulated clock of this
    // process stands still meanwhile, the other processes go on.
    beginTiming();
    if (axis != waitingAxis_) {
        waitingAxis_ = axis;
        control_.setAlarm("Waiting for axis " + axis + " (GAX: another process holds it)");
        showCurrentBlock();
    }
    return true;
}

void SimulationClock::finish(const std::string& alarm) {
    timer_.stop();
    showCurrentBlock();
    control_.programFinished(alarm);
    emit changed();
}

void SimulationClock::finishMdi(const mtc::core::RunResult& result) {
    mdiRunning_ = false;
    mdiDiagnostics_ = result.diagnostics;
    std::string alarm;
    for (const auto& d : mdiDiagnostics_.items())
        if (d.severity == mtc::core::Severity::Error) {
            alarm = mtc::core::formatMdiDiagnostic(d);
            break;
        }
    if (alarm.empty() && result.status != mtc::core::RunStatus::Ended)
        alarm = "MDI: the entry stopped with an error";
    finish(alarm);
    emit mdiEnded(alarm.empty());
}

void SimulationClock::showCurrentBlock() {
    // The block executed last is the one the operator sees as "current".
    control_.setCurrentBlock(lastProgram_ ? lastProgram_->blockId(lastBlock_) : std::string());
    emit changed();
}

}  // namespace mtc::hmi
