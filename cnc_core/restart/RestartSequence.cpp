#include "cnc_core/restart/RestartSequence.h"

#include <memory>

#include "cnc_core/interp/ProgramFlow.h"

namespace mtc::core {

namespace {

/// The live interpreter's machine data and events, shared without ownership
/// (the interpreter outlives the sequence): the computing process must read
/// and write the same pages 60/61 and events.
InterpreterServices servicesOf(Interpreter& live, VariableAccess* otherProcesses) {
    InterpreterServices services;
    services.machineData =
        std::shared_ptr<MachineDataProvider>(std::shared_ptr<void>(), &live.machineData());
    services.events = std::shared_ptr<EventTable>(std::shared_ptr<void>(), &live.events());
    services.otherProcesses = otherProcesses;
    // The same tool list and zero offsets as the live run.
    services.tools = std::shared_ptr<const ToolList>(std::shared_ptr<void>(), &live.tools());
    services.zeroOffsets =
        std::shared_ptr<const ZeroOffsetTable>(std::shared_ptr<void>(), &live.zeroOffsets());
    return services;
}

}  // namespace

const char* restartPhaseName(RestartPhase phase) {
    switch (phase) {
        case RestartPhase::Idle:
            return "idle";
        case RestartPhase::Active:
            return "active";
        case RestartPhase::Computing:
            return "computing";
        case RestartPhase::TargetReached:
            return "target_reached";
        case RestartPhase::Adjusting:
            return "adjusting";
        case RestartPhase::ManualMode:
            return "manual";
        case RestartPhase::AutomaticAgain:
            return "automatic_again";
        case RestartPhase::Repositioning:
            return "repositioning";
        case RestartPhase::Reestablished:
            return "reestablished";
        case RestartPhase::Failed:
            return "failed";
        case RestartPhase::Aborted:
            return "aborted";
    }
    return "failed";
}

RestartSequence::RestartSequence(ProcessControl& control, SimulatedSps& sps, Interpreter& live,
                                 const ProgramStore& programs, MachineSink& machine,
                                 VariableAccess* otherProcesses)
    : control_(control),
      sps_(sps),
      live_(live),
      programs_(programs),
      machine_(machine),
      computing_(live.config(), programs, machine, servicesOf(live, otherProcesses)) {}

RestartSequence::~RestartSequence() {
    if (control_.keyHandler() == this) control_.setKeyHandler(nullptr);
    computing_.cancelTransfers();
    if (liveChanged_) {
        live_.setObserver(nullptr);
        live_.setStopTarget(std::nullopt);
    }
}

bool RestartSequence::active() const {
    return phase_ != RestartPhase::Idle && phase_ != RestartPhase::Reestablished &&
           phase_ != RestartPhase::Failed && phase_ != RestartPhase::Aborted;
}

void RestartSequence::setSignal(const char* name, int value) {
    control_.signalTable().set(control_.signalPrefix() + name, value);
}

int RestartSequence::signal(const char* name) const {
    return control_.signalTable().get(control_.signalPrefix() + name);
}

bool RestartSequence::accept(const RestartSelection& selection, DiagnosticList& diagnostics,
                             std::uint64_t budget) {
    const SourceLocation where{selection.mainProgram, "", 0, 0};
    std::string refusal;
    if (active())
        refusal = "an NC program restart is already active";
    else if (signal("SREADY") != 1)
        refusal = "the process is not ready to start (PxxSREADY = 0)";
    else if (control_.mode() != OperatingMode::Automatic)
        refusal = "select automatic mode first";
    else if (control_.programActive())
        refusal = "a program is active (PxxSACTIV = 1)";
    if (!refusal.empty()) {
        diagnostics.error("RESTART_NOT_READY", where,
                          "NC program restart cannot be selected: " + refusal);
        return false;
    }
    DiagnosticList local;
    if (!computing_.begin(selection, live_.state(), live_.options(), budget, local)) {
        diagnostics.append(local);
        return false;
    }
    ProgramPtr adjust;
    std::uint32_t block = 0;
    if (!ProgramFlow(programs_, live_.config().index, nullptr)
             .findLabel(computing_.route().selected, "ADJUST", adjust, block))
        local.warning("RESTART_ADJUST_MISSING", where,
                      "there is no ADJUST subroutine in program " +
                          std::to_string(selection.mainProgram) +
                          ", program 99 or the cycle memory: the restart will stop after the "
                          "computing process");
    diagnostics.append(local);
    // The computing process's own diagnostics (begin() and the run) join when
    // it ends; keeping them here too reported them twice.
    diagnostics_ = DiagnosticList{};
    for (const Diagnostic& d : local.items())
        if (d.code == "RESTART_ADJUST_MISSING") diagnostics_.add(d);
    computingReported_ = false;
    abortRequested_.store(false);
    budget_ = budget;
    liveBlocks_ = 0;
    held_ = false;
    reentry_ = {};
    actual_ = live_.state().modal.machine;
    actualSpindleModes_ = live_.state().modal.rotaryAxisMode;
    actualTools_ = live_.state().modal.toolSpindle;
    control_.setKeyHandler(this);
    control_.signalTable().set("mBPREP", 0);  // the restart screen is closed
    setSignal("SBPACT", 1);
    phase_ = RestartPhase::Active;
    sps_.cycle();
    react();
    return true;
}

void RestartSequence::react() {
    if (phase_ == RestartPhase::Active && signal("CBPSTR") == 1) {
        control_.setProgramActive(true);
        resetMotionAnnouncement();
        phase_ = RestartPhase::Computing;
    }
    if (signal("SCREST") == 1 && signal("CREPOS") == 0) setSignal("SREPOS", 0);
}

RestartPhase RestartSequence::advance(std::uint64_t maxBlocks) {
    if (abortRequested_.exchange(false) && active()) {
        resetAll(RestartPhase::Aborted);
        return phase_;
    }
    sps_.cycle();
    react();
    if (held_) return phase_;
    if (phase_ == RestartPhase::Computing) advanceComputing(maxBlocks);
    if (phase_ == RestartPhase::Adjusting || phase_ == RestartPhase::Repositioning)
        runLive(maxBlocks);
    return phase_;
}

void RestartSequence::advanceComputing(std::uint64_t maxBlocks) {
    computing_.setSingleBlock(control_.singleBlock());
    const ComputingProgress progress = computing_.advance(maxBlocks);
    switch (progress.status) {
        case ComputingStatus::Stopped:
            held_ = true;
            setSignal("SHOLD", 1);
            return;
        case ComputingStatus::TargetReached:
            takeComputingDiagnostics();
            targetReached();
            return;
        case ComputingStatus::Failed:
        case ComputingStatus::Ended:  // only a survey ends without a target (never here)
            resetAll(RestartPhase::Failed);
            return;
        case ComputingStatus::Aborted:
            resetAll(RestartPhase::Aborted);
            return;
        case ComputingStatus::Idle:
        case ComputingStatus::Running:
        case ComputingStatus::Waiting:  // GAX / FAX: the next advance() looks again
            return;
    }
}

void RestartSequence::resetMotionAnnouncement() {
    // Axis signals are named A<process><axis>: "A00XSMCPOS", "A01Z2SMCNEG".
    const std::string prefix = "A" + control_.signalPrefix().substr(1);
    for (int axis = 0; axis < live_.axes().count(); ++axis) {
        const AxisModel& model = live_.axes().axis(axis);
        if (model.spindle && !model.rotary) continue;
        const std::string name = prefix + model.displayName();
        control_.signalTable().set(name + "SMCPOS", 0);
        control_.signalTable().set(name + "SMCNEG", 0);
    }
}

void RestartSequence::takeComputingDiagnostics() {
    if (computingReported_) return;
    computingReported_ = true;
    diagnostics_.append(computing_.diagnostics());
}

void RestartSequence::targetReached() {
    InterpreterState state = computing_.state();
    reentry_.valid = true;
    reentry_.machine = state.modal.machine;
    reentry_.spindleSpeed = state.modal.spindleSpeed;
    reentry_.rotaryAxisMode = state.modal.rotaryAxisMode;
    // With tool compensation the axes stood elsewhere than the programmed
    // point when the target block began: REPOS goes there (TC-013).
    const CompensatedPosition entry = computing_.entry();
    reentry_.compensated = entry.compensated;
    reentry_.axes = entry.axes;
    reentry_.lengthOffsets = entry.lengthOffsets;
    if (entry.interrupted)
        diagnostics_.warning(
            "RESTART_COMP_INTERRUPTED",
            locationOf(*computing_.route().targetProgram, computing_.selection().target.block),
            "the target block does not move in the working plane while radius compensation "
            "holds the element before it: REPOS goes to the perpendicular of that element's end "
            "(as after a programmed stop), not to the corner of the uninterrupted tool path; "
            "choose the next block that moves in the plane as the target");
    state.reentry = reentry_;
    // G31 / G32 is selected again by ADJUST from page 60 element 4 (seed 000,
    // 4.1 and 5.4): the NC leaves the computing process with G30; the other
    // groups (plane, zero offset) stay as computed. R-008.
    state.modal.transformation.deselect();
    state.modal.g[kGroupTransformation] = 30;
    // Nothing moved and no spindle command was executed: the spindles keep
    // their mode and the tool spindles their tools; page 60 says what ADJUST
    // and REPOS must establish (seed 000, 4.1, 5.4; R-030).
    state.modal.rotaryAxisMode = actualSpindleModes_;
    state.modal.toolSpindle = actualTools_;
    live_.restoreState(state);
    live_.takeMachinePositions(actual_);  // the computing process moved nothing
    liveChanged_ = true;
    setSignal("SBPACT", 0);
    setSignal("SREPOS", 1);
    phase_ = RestartPhase::TargetReached;
    sps_.cycle();
    react();
}

std::optional<bool> RestartSequence::handleKey(ControlKey key) {
    if (!active()) return std::nullopt;
    switch (key) {
        case ControlKey::Start:
            return start();
        case ControlKey::Stop:
            stop();
            return true;
        case ControlKey::ControlReset:
            setSignal("CRESET", 1);
            resetAll(RestartPhase::Aborted);
            control_.setAlarm("");
            setSignal("CRESET", 0);
            return true;
        case ControlKey::Manual:
            return changeMode(OperatingMode::Manual);
        case ControlKey::Automatic:
            return changeMode(OperatingMode::Automatic);
        case ControlKey::Repos:
            return repositionKey();
        case ControlKey::Mdi:  // MDI-005: no MDI inside an NC program restart
            control_.raiseAlarm(
                "ALARM_MDI_RESTART_ACTIVE",
                "MDI refused: an NC program restart is active (Control reset first)");
            return false;
        case ControlKey::ProgramRestart:
        case ControlKey::SingleBlock:  // ProcessControl switches it; advance() reads it
            return std::nullopt;
    }
    return std::nullopt;
}

bool RestartSequence::reposPhase() const {
    return signal("SREPOS") == 1 && signal("SCREST") == 0;
}

bool RestartSequence::repositionKey() {
    if (!reposPhase()) {
        control_.raiseAlarm(
            "ALARM_REPOS_NOT_YET",
            "REPOS refused: multi-block retrace is not possible yet (PxxSREPOS = 0, the "
            "computing process has not reached the target block)");
        return false;
    }
    // The M key sets the GUI flag mREPOS for one SPS scan: the SPS requests
    // multi-block retrace (PxxCREPOS, rung 4 of seed 000 Fig. 7-14) and resets
    // the flag again (rung 11). PxxCREPOS is what brings up the screen (rung 6).
    control_.signalTable().set("mREPOS", 1);
    sps_.cycle();
    control_.signalTable().set("mREPOS", 0);
    react();
    return signal("CREPOS") == 1;
}

bool RestartSequence::start() {
    if (control_.mode() != OperatingMode::Automatic) {
        control_.raiseAlarm("ALARM_START_NOT_AUTOMATIC",
                            "Start refused: select automatic mode first");
        return false;
    }
    const bool canStart =
        held_ || phase_ == RestartPhase::TargetReached || phase_ == RestartPhase::AutomaticAgain;
    if (!canStart) return true;  // already running (or waiting for the SPS)
    if (phase_ == RestartPhase::TargetReached && signal("CREPOS") != 1) {
        control_.raiseAlarm("ALARM_START_NO_REPOS",
                            "Start refused: multi-block retrace (PxxCREPOS) is not active");
        return false;
    }
    setSignal("CADV", 1);
    control_.setAlarm("");
    bool ok = true;
    if (held_) {
        held_ = false;
        setSignal("SHOLD", 0);
    } else if (phase_ == RestartPhase::TargetReached) {
        ok = beginAdjust();
    } else {
        phase_ = resumePhase_;
    }
    setSignal("CADV", 0);
    return ok;
}

void RestartSequence::stop() {
    setSignal("CSTOP", 1);
    const bool running = phase_ == RestartPhase::Computing || phase_ == RestartPhase::Adjusting ||
                         phase_ == RestartPhase::Repositioning;
    if (running && !held_) {
        held_ = true;
        setSignal("SHOLD", 1);
    }
    setSignal("CSTOP", 0);
}

bool RestartSequence::changeMode(OperatingMode mode) {
    const bool interrupted =
        held_ && (phase_ == RestartPhase::Adjusting || phase_ == RestartPhase::Repositioning);
    const bool between = phase_ == RestartPhase::TargetReached ||
                         phase_ == RestartPhase::ManualMode ||
                         phase_ == RestartPhase::AutomaticAgain;
    if (!interrupted && !between) {
        control_.raiseAlarm("ALARM_MODE_RESTART_RUNNING",
                            "Mode change refused: the NC program restart is running (Stop first)");
        return false;
    }
    if (interrupted && mode == OperatingMode::Manual) {
        held_ = false;
        setSignal("SHOLD", 0);
        resumePhase_ = phase_;
        phase_ = RestartPhase::ManualMode;
    }
    sps_.requestMode(mode);
    if (mode == OperatingMode::Automatic && phase_ == RestartPhase::ManualMode)
        phase_ = RestartPhase::AutomaticAgain;
    if (mode == OperatingMode::Manual && phase_ == RestartPhase::AutomaticAgain)
        phase_ = RestartPhase::ManualMode;
    return true;
}

bool RestartSequence::jog(int axis, double machinePosition) {
    const bool between =
        phase_ == RestartPhase::TargetReached || phase_ == RestartPhase::ManualMode;
    if (!between || control_.mode() != OperatingMode::Manual || axis < 0 ||
        axis >= live_.axes().count())
        return false;
    const AxisModel& model = live_.axes().axis(axis);
    if (model.limited() &&
        (machinePosition < model.minPosition || machinePosition > model.maxPosition))
        return false;
    Motion move;
    move.type = MotionType::Rapid;
    move.axisCount = live_.axes().count();
    move.start = live_.state().modal.machine;
    move.end = move.start;
    move.end[static_cast<std::size_t>(axis)] = machinePosition;
    live_.takeMachinePositions(move.end);
    machine_.motion(move);
    live_.manualJogPerformed();  // Bxx.036 = No for a restart (refused otherwise): no reset
    return true;
}

bool RestartSequence::resumeComputing(const ComputingCheckpoint& checkpoint) {
    if (phase_ != RestartPhase::Computing || computing_.progress().blocksInterpreted != 0)
        return false;
    computing_.resume(checkpoint);
    return true;
}

void RestartSequence::requestAbort() {
    abortRequested_.store(true);
    computing_.requestAbort();
}

}  // namespace mtc::core
