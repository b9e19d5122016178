#include "cnc_core/cell/Station.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "cnc_core/afc/AdaptiveFeedControl.h"
#include "cnc_core/afc/AfcMotion.h"
#include "cnc_core/compensation/ToolData.h"
#include "cnc_core/machine/OverrideSwitch.h"
#include "cnc_core/machine_data/MachineDataStore.h"
#include "cnc_core/mdi/MdiEntry.h"

namespace mtc::core {

namespace {

/// The axes of `config` (the interpreter reports their problems).
ProcessAxes axesOf(const ProcessConfig& config) {
    DiagnosticList ignored;
    return ProcessAxes::build(config, ignored);
}

constexpr const char* kSingleBlockPrompt = "Single block: press Start for the next block";

std::string firstProblem(const DiagnosticList& diagnostics, const char* fallback,
                         Language language) {
    for (const Diagnostic& d : diagnostics.items())
        if (d.severity == Severity::Error) return formatDiagnostic(d, language);
    return fallback;
}

}  // namespace

Station::Station(const ProcessConfig& config, const ProgramStore& programs,
                 const InterpreterServices& services, MachineDataStore& machineData)
    : config_(config),
      programs_(programs),
      control_(config.index),
      afc_(std::make_shared<AdaptiveFeedControl>(config, machineData, torqueModelFromConfig(config),
                                                 &control_.signalTable())),
      machine_(config),
      output_(machine_),
      interpreter_(config, programs, output_, services),
      sps_(control_),
      restart_(control_, sps_, interpreter_, programs, output_, services.otherProcesses),
      trace_(axesOf(config)),
      liveCut_(axesOf(config)),
      jog_(control_, interpreter_, machine_) {
    restart_.setAxisTransfer(services.axisTransfer);
    control_.setRunner(this);
    machine_.attachAdaptiveFeed(afc_.get(), &trend_);
    interpreter_.setAdaptiveFeed(afc_);
    // The tool in working position when the move is sent (TC-009).
    liveCut_.setToolSource(
        [this] { return activeToolData(interpreter_.tools(), interpreter_.state().modal); });
}

Station::~Station() {
    control_.setRunner(nullptr);
}

bool Station::press(ControlKey key) {
    const bool ok = control_.press(key);
    // Feed hold and Control reset act on the machine whoever runs it
    // (program, MDI, the restart's ADJUST / REPOS).
    if (ok && key == ControlKey::Stop && control_.programActive()) machine_.hold();
    if (ok && key == ControlKey::Start && machine_.held()) machine_.resume();
    if (ok && key == ControlKey::Start) machine_.continueAfterBlockStop();
    if (key == ControlKey::ControlReset) machine_.stop();
    ++revision_;
    return ok;
}

void Station::setFeedOverride(int percent) {
    machine_.setFeedOverride(percent);
    ++revision_;
}

int Station::feedOverride() const {
    return static_cast<int>(std::lround(machine_.feedOverride()));
}

void Station::stepFeedOverride(int direction) {
    setFeedOverride(feedOverrideStep(feedOverride(), direction, feedOverrideMax()));
}

void Station::stepRapidOverride(int direction) {
    setRapidOverride(rapidOverrideStep(rapidOverride(), direction));
}

int Station::feedOverrideMax() const {
    return static_cast<int>(std::lround(machine_.feedOverrideMax()));
}

void Station::setRapidOverride(int percent) {
    machine_.setRapidOverride(percent);
    ++revision_;
}

int Station::rapidOverride() const {
    return static_cast<int>(std::lround(machine_.rapidOverride()));
}

bool Station::selectProgram(int number) {
    const bool ok = control_.selectProgram(number);
    // The runtime program (compiled when the source has compiler keywords)
    // is what the station and its NC program restart work on (C-013).
    if (ok && number > 0) {
        const std::string alarm = prepare(number);
        if (!alarm.empty()) control_.setAlarm(alarm);
    }
    ++revision_;
    return ok;
}

void Station::setLanguage(Language language) {
    language_ = language;
    control_.setLanguage(language);
    mdiSession_.setLanguage(language);
    restart_.setLanguage(language);
}

std::string Station::prepare(int number) {
    if (!preparer_) return {};
    DiagnosticList diagnostics;
    std::string alarm = preparer_(number, diagnostics);
    log_.addAll(DiagnosticSource::Run, diagnostics);
    return alarm;
}

std::string Station::start(int number) {
    // Compile on demand / refuse a program with compiler errors: nothing
    // of the run below has been touched yet when the preparer refuses.
    if (std::string alarm = prepare(number); !alarm.empty()) return alarm;
    DiagnosticList diagnostics;
    if (!interpreter_.select(number, 0, &diagnostics)) {
        log_.addAll(DiagnosticSource::Run, diagnostics);
        return firstProblem(diagnostics, "the program cannot be selected", language_);
    }
    machine_.reset();
    beginRun(Run::Program);
    beginTrace(number);
    beginLiveCut(number);
    return {};
}

void Station::beginTrace(int number) {
    output_.trace = nullptr;
    if (!tracing_) return;
    trace_.begin(number);
    output_.trace = &trace_;
}

void Station::beginLiveCut(int number) {
    output_.cut = nullptr;
    if (!liveCutting_) return;
    // The blank with the zero offsets the run will use.
    liveCut_.begin(config_, programs_, number,
                   std::make_shared<const ZeroOffsetTable>(interpreter_.zeroOffsets()));
    output_.cut = &liveCut_;
}

std::string Station::startMdi() {
    static const std::vector<MacroDefinition> kNoMacros;
    DiagnosticList refused;
    ProgramPtr program;
    std::string alarm =
        mdiSession_.take(ncOptions_ ? ncOptions_->globalMacros : kNoMacros, program, refused);
    if (alarm.empty() && !mdi_.begin(interpreter_, program, &refused)) {
        alarm = firstProblem(refused, "the MDI entry cannot be selected", language_);
        mdiSession_.ended(false, refused);
    }
    log_.addAll(DiagnosticSource::Mdi, refused);
    if (!alarm.empty()) return alarm;
    mdiDiagnostics_.clear();
    output_.trace = nullptr;  // the last program's backplot stays as it was
    cutByHand();              // its part is cut on
    beginRun(Run::Mdi);
    return {};
}

bool Station::cutByHand() {
    const bool on = liveCutting_ && liveCut_.resume();
    output_.cut = on ? &liveCut_ : nullptr;
    return on;
}

void Station::setMdiInput(std::string text) {
    mdiSession_.setInput(std::move(text));
    ++revision_;
}

bool Station::recallMdi(std::size_t row) {
    ++revision_;
    return mdiSession_.recall(row);
}

bool Station::checkMdi() {
    static const std::vector<MacroDefinition> kNoMacros;
    DiagnosticList refused;
    const bool ok = mdiSession_.check(ncOptions_ ? ncOptions_->globalMacros : kNoMacros, refused);
    log_.addAll(DiagnosticSource::Mdi, refused);
    ++revision_;
    return ok;
}

void Station::endMdi(bool completed) {
    DiagnosticList diagnostics = mdiDiagnostics_;
    mdiSession_.ended(completed, diagnostics);
    mdiDiagnostics_ = std::move(diagnostics);
    ++revision_;
}

void Station::logRunDiagnostics(const DiagnosticList& diagnostics) {
    if (run_ != Run::Mdi) return log_.addAll(DiagnosticSource::Run, diagnostics);
    for (Diagnostic d : diagnostics.items()) {
        MdiSession::attachInputLine(
            d, mdiSession_.history().empty() ? std::string() : mdiSession_.history().back().text);
        log_.add(DiagnosticSource::Mdi, d);
    }
}

void Station::beginRun(Run run) {
    run_ = run;
    feeding_ = true;
    pending_ = Pending::None;
    stoppedBy_ = Pending::None;
    runBlocks_ = 0;
    runDiagnostics_.clear();
    runStatus_ = RunStatus::Running;
    lastProgram_.reset();
    showCurrentBlock();
}

std::string Station::resume() {
    // Single block switched off while held at a block: the run goes on.
    if (pending_ == Pending::SingleBlock && !control_.singleBlock()) pending_ = Pending::None;
    feeding_ = run_ != Run::None && pending_ == Pending::None;
    if (feeding_) stoppedBy_ = Pending::None;
    return {};
}

void Station::hold() {
    feeding_ = false;
    interpreter_.publishRotaryAxisModes();  // page 60 "upon program stop" (seed 000, 4.1)
}

void Station::reset() {
    interpreter_.controlReset();
    const bool mdi = run_ == Run::Mdi;
    if (mdi) mdi_.abandon();  // the automatic program comes back
    run_ = Run::None;
    feeding_ = false;
    pending_ = Pending::None;
    stoppedBy_ = Pending::None;
    waitingAxis_.clear();
    if (output_.trace) {  // the backplot ends where the axes stop
        trace_.follow(machine_.engine());
        trace_.cut();
        output_.trace = nullptr;
    }
    if (output_.cut) {  // the part stays as the tool left it
        liveCut_.follow(machine_.engine());
        liveCut_.stop();
        output_.cut = nullptr;
    }
    machine_.stop();
    machine_.reset();
    queued_.clear();
    // The axes stopped where they were, mid-block perhaps: the next move
    // starts there (the interpreter took the block end for granted).
    std::array<double, kMaxAxes> where{};
    for (int axis = 0; axis < kMaxAxes; ++axis)
        where[static_cast<std::size_t>(axis)] = machine_.position(axis);
    interpreter_.takeMachinePositions(where);
    lastProgram_.reset();
    control_.setCurrentBlock({});
    ++revision_;
    if (mdi) endMdi(false);
}

double Station::advance(double seconds, std::uint64_t maxBlocks) {
    std::uint64_t blocks = 0;
    double left = seconds > 0.0 ? seconds : 0.0;
    const double busyBefore = machine_.seconds();
    for (;;) {
        const std::uint64_t before = blocks;
        const RestartPhase phase = restartPhase_;
        advanceRestart(blocks, maxBlocks);
        // State re-established: the call ends at that instant, before the
        // program runs on, so the screens see the axes at the re-entry point.
        if (restartPhase_ != phase && restartPhase_ == RestartPhase::Reestablished) break;
        feed(blocks, maxBlocks);
        settle();
        // Out of blocks while the machine still wants more: the station
        // lags behind the clock rather than letting time pass without work.
        if ((running() || computing()) && machine_.wantsMore() && blocks >= maxBlocks) break;
        if (left <= 0.0) break;
        const double used = machine_.advance(left);
        left -= used;
        // Let go of the states of the blocks done meanwhile: a long call (the
        // CLI's) would otherwise keep thousands and write each to a cold slot.
        if (keepBlockStates_)
            queued_.follow(machine_.itemsDone(), machine_.atBlockStop(), machine_.idle());
        if (used <= 0.0 && blocks == before) break;  // nothing can go on
    }
    if (output_.trace) trace_.follow(machine_.engine());
    if (output_.cut) liveCut_.follow(machine_.engine());
    // A released continuous jog: its move ends where the cut has followed it.
    if (jog_.settle() && output_.cut) liveCut_.dropPending();
    if (blocks > 0 || machine_.seconds() != busyBefore) ++revision_;
    showCurrentBlock();
    return seconds > 0.0 ? seconds - left : 0.0;
}

bool Station::jogBy(int axis, double distance, bool rapid) {
    if (restart_.active()) return jogRestart(axis, distance);
    return jogDone(jog_.moveBy(axis, distance, rapid), true);
}

bool Station::jogStart(int axis, int direction, bool rapid) {
    if (restart_.active()) return false;  // the restart jogs by increments only
    return jogDone(jog_.start(axis, direction, rapid), true);
}

bool Station::manualSpindle(int spindle, int rotation, double rpm) {
    return jogDone(jog_.spindle(spindle, rotation, rpm));
}

bool Station::manualSpindleKey(int spindle, SpindleKey key) {
    return jogDone(jog_.spindleKey(spindle, key));
}

void Station::jogRelease() {
    jog_.release();
    ++revision_;
}

bool Station::jogDone(const std::string& refusal, bool moved) {
    ++revision_;
    if (refusal.empty()) {
        if (moved && cutByHand()) liveCut_.sentJog(jog_.lastMove());
        return true;
    }
    control_.setAlarm(refusal);
    return false;
}

void Station::feed(std::uint64_t& blocks, std::uint64_t maxBlocks) {
    while (running() && pending_ == Pending::None && machine_.wantsMore() && blocks < maxBlocks) {
        const InterpreterState& state = interpreter_.state();
        if (state.program.get() != lastProgram_.get()) lastProgram_ = state.program;
        lastBlock_ = state.block;
        const int callLevel = static_cast<int>(state.callStack.size());
        const std::uint64_t outputsBefore = output_.outputs;
        const std::uint64_t itemsBefore = machine_.itemsQueued();
        machine_.beginBlock();
        const RunResult result = budget_ > 0 && runBlocks_ >= budget_ ? budgetExceeded()
                                 : run_ == Run::Mdi                   ? mdi_.step()
                                                                      : interpreter_.step();
        blocks += result.blocksInterpreted;
        runBlocks_ += result.blocksInterpreted;
        if (keepBlockStates_ && output_.outputs != outputsBefore)
            recordQueuedBlock(lastProgram_, lastBlock_, callLevel, itemsBefore);
        if (!result.diagnostics.empty()) {
            runDiagnostics_.append(result.diagnostics);
            logRunDiagnostics(result.diagnostics);
        }
        if (!waitingAxis_.empty() && result.blocksInterpreted > 0) {
            waitingAxis_.clear();  // the GAX was granted
            control_.setAlarm({});
        }
        if (!handle(result)) return;
    }
}

RunResult Station::budgetExceeded() const {
    RunResult result;
    result.status = RunStatus::BudgetExceeded;
    const std::vector<StackLevel> levels = interpreter_.callStack();
    const StackLevel at = levels.empty() ? StackLevel{} : levels.back();
    result.diagnostics.error("BLOCK_BUDGET", {at.program, at.block, at.line, 0},
                             "the run was stopped after " + std::to_string(budget_) +
                                 " interpreted blocks (block budget); is the program an "
                                 "endless loop?");
    return result;
}

bool Station::handle(const RunResult& result) {
    switch (result.status) {
        case RunStatus::Running:
            if (!control_.singleBlock()) return true;
            pending_ = Pending::SingleBlock;  // hold after the block until Start
            return false;
        case RunStatus::Stopped:
            if (waitForAxis()) return false;
            pending_ = Pending::ProgrammedStop;
            return false;
        case RunStatus::Ended:
        case RunStatus::TargetReached:
        case RunStatus::BudgetExceeded:
        case RunStatus::Error:
            pending_ = Pending::End;
            ending_ = result;
            return false;
    }
    return false;
}

void Station::settle() {
    // Single block switched on while the look-ahead had queued more blocks:
    // the machine rests at the end of the block it was in.
    machine_.setStopAtBlockEnds(control_.singleBlock() && run_ != Run::None && !restart_.active());
    if (machine_.atBlockStop() && run_ != Run::None && stoppedBy_ == Pending::None) {
        feeding_ = false;
        stoppedBy_ = Pending::SingleBlock;
        ++revision_;
        interpreter_.publishRotaryAxisModes();
        control_.programStopped("PROMPT_SINGLE_BLOCK", kSingleBlockPrompt);
        return;
    }
    if (pending_ == Pending::None || !machine_.idle()) return;
    const Pending pending = pending_;
    pending_ = Pending::None;
    ++revision_;
    switch (pending) {
        case Pending::SingleBlock:
            feeding_ = false;
            stoppedBy_ = pending;
            interpreter_.publishRotaryAxisModes();
            control_.programStopped("PROMPT_SINGLE_BLOCK", kSingleBlockPrompt);
            return;
        case Pending::ProgrammedStop:
            feeding_ = false;
            stoppedBy_ = pending;
            control_.programStopped("PROMPT_PROGRAMMED_STOP",
                                    "Programmed stop: press Start to continue");
            return;
        case Pending::End:
            finish(ending_);
            return;
        case Pending::None:
            return;
    }
}

bool Station::waitForAxis() {
    const std::string axis = interpreter_.waitingForAxis();
    if (axis.empty()) return false;
    // The next advance() looks again; the machine stands meanwhile (its busy
    // time does not grow), the other processes go on.
    if (axis != waitingAxis_) {
        waitingAxis_ = axis;
        control_.raiseAlarm("ALARM_WAIT_AXIS",
                            "Waiting for axis %1 (GAX: another process holds it)", {axis});
        ++revision_;
    }
    return true;
}

void Station::finish(const RunResult& result) {
    const bool mdi = run_ == Run::Mdi;
    run_ = Run::None;
    feeding_ = false;
    runStatus_ = result.status;
    showCurrentBlock();
    std::string alarm;
    if (mdi) {
        mdiDiagnostics_ = result.diagnostics;
        for (const Diagnostic& d : mdiDiagnostics_.items())
            if (d.severity == Severity::Error) {
                alarm = formatMdiDiagnostic(d, language_);
                break;
            }
        if (alarm.empty() && result.status != RunStatus::Ended)
            alarm = "MDI: the entry stopped with an error";
    } else if (result.status == RunStatus::Error || result.status == RunStatus::BudgetExceeded) {
        alarm = firstProblem(result.diagnostics, "the program stopped with an error", language_);
    }
    control_.programFinished(alarm);
    if (mdi) endMdi(alarm.empty());
}

void Station::recordQueuedBlock(const ProgramPtr& program, std::uint32_t index, int callLevel,
                                std::uint64_t firstItem) {
    QueuedBlockState& entry = queued_.record();
    entry.firstItem = firstItem;
    entry.endItem = machine_.itemsQueued();
    if (entry.source != program) entry.source = program;  // a reused slot may hold it already
    entry.index = index;
    entry.callLevel = callLevel;
    const InterpreterState& state = interpreter_.state();
    assignModalState(entry.modal, state.modal);
    entry.mGroups = state.mGroups;
}

void Station::showCurrentBlock() {
    queued_.follow(machine_.itemsDone(), machine_.atBlockStop(), machine_.idle());
    // The block the machine executes; while it stands, the one interpreted last.
    if (!machine_.idle()) {
        const SourceLocation at = machine_.currentLocation();
        if (!at.block.empty()) {
            if (control_.currentBlock() != at.block) control_.setCurrentBlock(at.block);
            return;
        }
    }
    control_.setCurrentBlock(lastProgram_ ? lastProgram_->blockId(lastBlock_) : std::string());
}

}  // namespace mtc::core
