#include "cnc_core/restart/ComputingProcess.h"

#include <algorithm>
#include <string>

namespace mtc::core {

namespace {

/// Blocks between two looks at the abort flag (a few milliseconds).
constexpr std::uint64_t kSlice = std::uint64_t{1} << 16;

/// Output of the computing process: no motion, no dwell; an aux type only
/// when its process parameter Bxx.058..061 says Yes (seed 000, 3.1).
OutputOptions restartOutput(const ProcessConfig& config) {
    OutputOptions out;
    out.motion = false;
    out.dwell = false;
    out.m = config.flag("B058");
    out.q = config.flag("B059");
    out.s = config.flag("B060");
    out.te = config.flag("B061");
    out.commands = true;  // RestartOutputFilter holds back what is not performed
    return out;
}

}  // namespace

const char* computingStatusName(ComputingStatus status) {
    switch (status) {
        case ComputingStatus::Idle:
            return "idle";
        case ComputingStatus::Running:
            return "running";
        case ComputingStatus::Stopped:
            return "stopped";
        case ComputingStatus::TargetReached:
            return "target";
        case ComputingStatus::Failed:
            return "failed";
        case ComputingStatus::Aborted:
            return "aborted";
        case ComputingStatus::Waiting:
            return "waiting";
        case ComputingStatus::Ended:
            return "ended";
    }
    return "failed";
}

bool ComputingProcess::parametersAllowRestart(int program, DiagnosticList& diagnostics) const {
    // Seed 000, 2.1: both process parameters must be No for NC program restart (R-027).
    bool ok = true;
    const std::string process = std::to_string(config_.index);
    if (config_.flag("B033")) {
        diagnostics.error("RESTART_PARAMETER", {program, "", 0, 0},
                          "NC program restart needs process parameter B033 'reverse program "
                          "execution required' = No (process " +
                              process + " has Yes; seed 000, 2.1)");
        ok = false;
    }
    if (config_.flag("B036")) {
        diagnostics.error("RESTART_PARAMETER", {program, "", 0, 0},
                          "NC program restart needs process parameter B036 'manual axis jogging "
                          "causes reset' = No (process " +
                              process + " has Yes; seed 000, 2.1)");
        ok = false;
    }
    return ok;
}

ComputingProcess::ComputingProcess(const ProcessConfig& config, const ProgramStore& programs,
                                   MachineSink& sps, InterpreterServices services)
    : config_(config),
      programs_(programs),
      filter_(sps),
      collector_(config),
      interpreter_(config, programs, filter_, std::move(services)) {}

void ComputingProcess::setAxisTransfer(AxisTransfer* transfer) {
    filter_.setAxisTransfer(transfer, config_.index, [this] { interpreter_.requestHold(); });
}

bool ComputingProcess::begin(const RestartSelection& selection, const InterpreterState& current,
                             const InterpreterOptions& operatorOptions, std::uint64_t budget,
                             DiagnosticList& diagnostics) {
    DiagnosticList local;
    RestartRoute route;
    if (interpreter_.configurationDiagnostics().hasErrors()) {
        local.error(
            "RESTART_MACHINE_INVALID", {},
            "the machine configuration cannot run process " + std::to_string(config_.index));
        local.append(interpreter_.configurationDiagnostics());
    } else if (selection.process != config_.index) {
        local.error("RESTART_PROCESS", {},
                    "the selection is for process " + std::to_string(selection.process) +
                        ", this is process " + std::to_string(config_.index));
    } else if (!parametersAllowRestart(selection.mainProgram, local)) {
        // refused: Bxx.033 / Bxx.036 (seed 000, 2.1)
    } else {
        // The route and its warnings read the same analyses of the programs
        // (the main program's LevelReach is one pass over its words).
        RestartRouteCache once;
        RestartRouteCache& cache = routeCache_ ? *routeCache_ : once;
        if (planRestartRoute(selection, programs_, route, local, &cache))
            addStartWarnings(route, local, &cache);
    }
    for (const auto& [variable, value] : selection.variableChanges)
        if (variable < 0 || variable >= kVariableCount)
            local.error("RESTART_VARIABLE_RANGE", {selection.mainProgram, "", 0, 0},
                        "variable @" + std::to_string(variable) + " does not exist (0..999)");
    for (const auto& [event, value] : selection.eventChanges)
        if (!EventTable::valid(event.process, event.event))
            local.error("RESTART_EVENT_INVALID", {selection.mainProgram, "", 0, 0},
                        "event " + std::to_string(event.process) + ":" +
                            std::to_string(event.event) + " does not exist");
    diagnostics.append(local);
    if (local.hasErrors() || budget == 0) {
        progress_ = {};
        return false;
    }
    start(selection, std::move(route), current, operatorOptions, budget, std::move(local));
    const StopTarget target{route_.targetProgram->number, selection.target.block, 1};
    target_ = target;
    interpreter_.setStopTarget(target_);
    return true;
}

bool ComputingProcess::beginSurvey(int mainProgram, const InterpreterState& current,
                                   const InterpreterOptions& operatorOptions, std::uint64_t budget,
                                   DiagnosticList& diagnostics) {
    RestartRoute route;
    route.main = programs_.find(config_.index, mainProgram);
    if (interpreter_.configurationDiagnostics().hasErrors() || !route.main || budget == 0) {
        diagnostics.error("RESTART_PROGRAM_NOT_FOUND", {mainProgram, "", 0, 0},
                          "program " + std::to_string(mainProgram) + " cannot run in process " +
                              std::to_string(config_.index));
        progress_ = {};
        return false;
    }
    route.selected = route.startSelected = route.startProgram = route.targetProgram = route.main;
    RestartSelection selection;
    selection.process = config_.index;
    selection.mainProgram = mainProgram;
    start(selection, std::move(route), current, operatorOptions, budget, {});
    survey_ = true;
    interpreter_.setStopTarget(std::nullopt);
    return true;
}

void ComputingProcess::start(const RestartSelection& selection, RestartRoute route,
                             const InterpreterState& current,
                             const InterpreterOptions& operatorOptions, std::uint64_t budget,
                             DiagnosticList diagnostics) {
    selection_ = selection;
    route_ = std::move(route);
    budget_ = budget;
    diagnostics_ = std::move(diagnostics);
    progress_ = {ComputingStatus::Running, 0, 0};
    survey_ = false;
    resumedEntry_.reset();
    abortRequested_.store(false);
    blocksSoFar_.store(0);

    interpreter_.restoreState(current);
    interpreter_.controlReset();
    interpreter_.select(route_.startSelected, 0);  // program end and JMP resets as in a run
    InterpreterState start = interpreter_.state();
    for (const auto& [variable, value] : selection.variableChanges) {
        start.variables.values[static_cast<std::size_t>(variable)] = value;
        start.variables.written.set(static_cast<std::size_t>(variable));
    }
    start.program = route_.startProgram;
    start.block = route_.startBlock;
    start.callStack = route_.startFrames;
    interpreter_.restoreState(start);
    for (const auto& [event, value] : selection.eventChanges)
        interpreter_.events().set(event.process, event.event, value);

    InterpreterOptions options = operatorOptions;
    options.continueAfterError = false;
    options.output = restartOutput(config_);
    options.logicalAdaptiveFeed = true;  // G25 / G26 are remembered, nothing is measured (R-029)
    interpreter_.options() = options;
    collector_.clear();
    filter_.resetCounters();
    filter_.cancelTransfers();
    interpreter_.setObserver(&collector_);
    publishBuffers();  // zeroed at the start (seed 000, 4.2)
}

ComputingCheckpoint ComputingProcess::checkpoint() {
    return {interpreter_.state(),        collector_.m16(), collector_.q(), progress_.arrivals,
            progress_.blocksInterpreted, entry()};
}

CompensatedPosition ComputingProcess::entry() {
    if (resumedEntry_ && progress_.blocksInterpreted == resumedAt_) return *resumedEntry_;
    return interpreter_.entryOfNextBlock();
}

void ComputingProcess::resume(const ComputingCheckpoint& checkpoint) {
    interpreter_.restoreState(checkpoint.state);
    collector_.restore(checkpoint.m16, checkpoint.q);
    progress_.arrivals = checkpoint.arrivals;
    count(checkpoint.blocks - progress_.blocksInterpreted);
    resumedEntry_ = checkpoint.entry;
    resumedAt_ = progress_.blocksInterpreted;
}

ComputingProgress ComputingProcess::step() {
    if (progress_.status != ComputingStatus::Running &&
        progress_.status != ComputingStatus::Stopped)
        return progress_;
    progress_.status = ComputingStatus::Running;
    progress_.singleBlockStop = false;
    if (progress_.blocksInterpreted >= budget_) {
        budgetExhausted();
        return progress_;
    }
    const RunResult result = interpreter_.step();
    count(result.blocksInterpreted);
    handle(result);
    return progress_;
}

void ComputingProcess::budgetExhausted() {
    const std::vector<StackLevel> levels = interpreter_.callStack();
    const StackLevel at = levels.empty() ? StackLevel{} : levels.back();
    diagnostics_.error("BLOCK_BUDGET", {at.program, at.block, at.line, 0},
                       "the computing process was stopped after " + std::to_string(budget_) +
                           " interpreted blocks (block budget) before it reached the target "
                           "block");
    finish(ComputingStatus::Failed);
}

ComputingProgress ComputingProcess::advance(std::uint64_t maxBlocks) {
    if (progress_.status != ComputingStatus::Running &&
        progress_.status != ComputingStatus::Stopped &&
        progress_.status != ComputingStatus::Waiting)
        return progress_;
    if (progress_.status == ComputingStatus::Waiting && !abortRequested_.load()) {
        if (filter_.waiting()) return progress_;
        filter_.cancelTransfers();  // every request met its partner: forget them
    }
    progress_.status = ComputingStatus::Running;
    progress_.singleBlockStop = false;
    std::uint64_t left = maxBlocks;
    while (left > 0) {
        if (abortRequested_.load(std::memory_order_relaxed)) {
            finish(ComputingStatus::Aborted);
            return progress_;
        }
        if (progress_.blocksInterpreted >= budget_) {
            budgetExhausted();
            return progress_;
        }
        const bool single = singleBlock_.load(std::memory_order_relaxed);
        const std::uint64_t slice =
            single ? 1 : std::min({left, kSlice, budget_ - progress_.blocksInterpreted});
        const RunResult result = interpreter_.run(slice);
        left -= std::min(left, result.blocksInterpreted);
        count(result.blocksInterpreted);
        if (handle(result) == Next::Return) return progress_;
        if (single) return singleBlockStop();
    }
    return progress_;
}

ComputingProgress ComputingProcess::singleBlockStop() {
    // Single-block mode (seed 000, 2.7): held after every block as at M00;
    // Start (advance() again) interprets the next one. R-020.
    interpreter_.publishRotaryAxisModes();
    progress_.status = ComputingStatus::Stopped;
    progress_.singleBlockStop = true;
    return progress_;
}

ComputingProcess::Next ComputingProcess::handle(const RunResult& result) {
    for (const Diagnostic& d : result.diagnostics.items())
        if (!(result.status == RunStatus::BudgetExceeded && d.code == "BLOCK_BUDGET"))
            diagnostics_.add(d);
    switch (result.status) {
        case RunStatus::Running:
        case RunStatus::BudgetExceeded:  // end of a slice; the real budget is checked above
            return Next::Continue;
        case RunStatus::TargetReached:
            return targetArrival();
        case RunStatus::Stopped:
            if (filter_.waiting()) {  // GAX / FAX: not an M00 (R-021)
                progress_.status = ComputingStatus::Waiting;
                return Next::Return;
            }
            // M00 / M01: the interpreter updated page 60 el. 1..3 (program stop)
            progress_.status = ComputingStatus::Stopped;
            return Next::Return;
        case RunStatus::Ended: {
            if (survey_) {  // the verifier's run through the whole program is done
                finish(ComputingStatus::Ended);
                return Next::Return;
            }
            const Program& p = *route_.targetProgram;
            diagnostics_.error(
                "RESTART_TARGET_NOT_FOUND", locationOf(p, selection_.target.block),
                "target block cannot be found: the program ended (BST, RET, M02, M30 or its last "
                "block) before the target block was reached",
                {"arrivals with the selected call chain: " + std::to_string(progress_.arrivals) +
                 " of " + std::to_string(selection_.runs)});
            finish(ComputingStatus::Failed);
            return Next::Return;
        }
        case RunStatus::Error:
            finish(ComputingStatus::Failed);
            return Next::Return;
    }
    return Next::Return;
}

ComputingProcess::Next ComputingProcess::targetArrival() {
    if (atRouteLevel(interpreter_.state(), route_) && ++progress_.arrivals >= selection_.runs) {
        finish(ComputingStatus::TargetReached);
        return Next::Return;
    }
    // Not yet: the target block is executed this time, the next arrival counts.
    interpreter_.setStopTarget(std::nullopt);
    const RunResult result = interpreter_.step();
    count(result.blocksInterpreted);
    interpreter_.setStopTarget(target_);
    return handle(result);
}

void ComputingProcess::finish(ComputingStatus status) {
    progress_.status = status;
    filter_.cancelTransfers();
    if (status != ComputingStatus::TargetReached) return;
    interpreter_.publishPage60();
    publishBuffers();
}

void ComputingProcess::publishBuffers() {
    const std::array<int, FunctionBuffer::kLength> m16 = collector_.m16().elements();
    const std::array<int, FunctionBuffer::kLength> q = collector_.q().elements();
    MachineDataProvider& data = interpreter_.machineData();
    for (int element = 1; element <= FunctionBuffer::kLength; ++element) {
        const auto i = static_cast<std::size_t>(element - 1);
        data.write({61, config_.index, 1, element}, m16[i], MachineDataWriter::Nc);
        data.write({61, config_.index, 2, element}, q[i], MachineDataWriter::Nc);
    }
}

void ComputingProcess::count(std::uint64_t blocks) {
    progress_.blocksInterpreted += blocks;
    blocksSoFar_.store(progress_.blocksInterpreted, std::memory_order_relaxed);
}

}  // namespace mtc::core
