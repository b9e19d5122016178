#include "cnc_core/restart/RestartVerifier.h"

#include <algorithm>

#include "cnc_core/afc/AdaptiveFeedControl.h"
#include "cnc_core/machine/ProcessControl.h"
#include "cnc_core/restart/MachineAuxTracker.h"
#include "cnc_core/restart/RestartRoute.h"
#include "cnc_core/restart/RestartSequence.h"
#include "cnc_core/restart/SimulatedSps.h"

namespace mtc::core {

namespace {

/// Work of one advance() of a restart sequence: no screen to keep responsive.
constexpr std::uint64_t kSlice = std::uint64_t{1} << 40;
/// Operator actions (Start after a stop, Automatic after manual mode) per target.
constexpr int kMaxOperatorActions = 10000;

/// Program, call frames and block of an arrival: what the passes count.
std::string arrivalKey(const InterpreterState& s) {
    std::string key;
    const auto put = [&key](std::int64_t value) {
        key.append(reinterpret_cast<const char*>(&value), sizeof value);
    };
    put(s.selected ? s.selected->number : -1);
    for (const CallFrame& frame : s.callStack) {
        put(frame.program ? frame.program->number : -1);
        put(frame.callBlock);
    }
    put(s.program ? s.program->number : -1);
    put(s.block);
    return key;
}

bool sameArrival(const InterpreterState& a, const InterpreterState& b) {
    return a.program == b.program && a.block == b.block && a.selected == b.selected &&
           arrivalKey(a) == arrivalKey(b);
}

/// True when the pointer stands on a block the next step interprets or skips.
bool onBlock(const InterpreterState& s) {
    return s.program && s.block < s.program->blocks.size() &&
           !(s.program->blocks[s.block].flags & kBlockProgramEnd);
}

std::array<int, FunctionBuffer::kLength> readBuffer(const MachineDataProvider& data, int process,
                                                    int sub) {
    std::array<int, FunctionBuffer::kLength> out{};
    for (int element = 1; element <= FunctionBuffer::kLength; ++element) {
        double value = 0.0;
        data.read({61, process, sub, element}, value);
        out[static_cast<std::size_t>(element - 1)] = static_cast<int>(value);
    }
    return out;
}

bool notSelectableCode(const std::string& code) {
    return code == "RESTART_IN_CYCLE" || code == "RESTART_PATH_DEPTH" ||
           code == "RESTART_RUNS_RANGE";
}

/// Machine data and events of one run of the verifier, the tool list and
/// zero offsets of the options (the same for every run).
InterpreterServices servicesOf(std::shared_ptr<MachineDataStore> data,
                               std::shared_ptr<EventTable> events, const VerifyOptions& options) {
    InterpreterServices services;
    services.machineData = std::move(data);
    services.events = std::move(events);
    services.tools = options.tools;
    services.zeroOffsets = options.zeroOffsets;
    return services;
}

}  // namespace

/// The normal run the computing process is compared with: full output into a
/// sink that keeps nothing, adaptive feed control as the panel and `run` have it.
struct RestartVerifier::NormalRun {
    NormalRun(const MachineConfig& cell, const ProcessConfig& config, const ProgramStore& programs,
              const VerifyOptions& options)
        : data(std::make_shared<MachineDataStore>(cell)),
          events(std::make_shared<EventTable>()),
          collector(config),
          interpreter(config, programs, sink, servicesOf(data, events, options)),
          afc(std::make_shared<AdaptiveFeedControl>(config, *data)) {
        interpreter.setAdaptiveFeed(afc);
        interpreter.setObserver(&collector);
    }
    std::shared_ptr<MachineDataStore> data;
    std::shared_ptr<EventTable> events;
    NullSink sink;
    RestartAuxCollector collector;  ///< what page 61 would hold if the run were a restart
    Interpreter interpreter;
    std::shared_ptr<AdaptiveFeedControl> afc;
    std::uint64_t blocks = 0;
};

/// One process of the cell as the operator restarts it: machine data,
/// events, the machine (tracking what it executes), the process's
/// interpreter, the machine control keys, the SPS and the restart sequence.
struct RestartVerifier::TargetCell {
    TargetCell(const MachineConfig& cell, const ProcessConfig& config, const ProgramStore& programs,
               const VerifyOptions& options)
        : data(std::make_shared<MachineDataStore>(cell)),
          events(std::make_shared<EventTable>()),
          tracker(config),
          live(config, programs, tracker, servicesOf(data, events, options)),
          afc(std::make_shared<AdaptiveFeedControl>(config, *data)),
          control(config.index),
          sps(control),
          sequence(control, sps, live, programs, tracker) {
        live.setAdaptiveFeed(afc);
    }
    bool press(ControlKey key) { return ++actions <= kMaxOperatorActions && control.press(key); }

    std::shared_ptr<MachineDataStore> data;
    std::shared_ptr<EventTable> events;
    MachineAuxTracker tracker;
    Interpreter live;
    std::shared_ptr<AdaptiveFeedControl> afc;
    ProcessControl control;
    SimulatedSps sps;
    RestartSequence sequence;
    int actions = 0;
};

RestartVerifier::RestartVerifier(const MachineConfig& cell, int process,
                                 const ProgramStore& programs, VerifyOptions options)
    : cell_(cell),
      config_(*cell.process(process)),
      programs_(programs),
      options_(std::move(options)) {
    options_.maxPasses = std::clamp<std::uint32_t>(options_.maxPasses, kMinRuns, kMaxRuns);
    NullSink sink;
    start_ = Interpreter(config_, programs_, sink).state();  // the machine at power-on
}

RestartVerifier::~RestartVerifier() = default;

bool RestartVerifier::begin(int mainProgram, DiagnosticList& diagnostics,
                            const InterpreterState* current) {
    report_ = {};
    passes_.clear();
    jumps_.clear();
    jumpDestinations_.clear();
    done_ = true;
    if (current) start_ = *current;
    main_ = mainProgram;
    normal_ = std::make_unique<NormalRun>(cell_, config_, programs_, options_);
    Interpreter& n = normal_->interpreter;
    n.restoreState(start_);
    n.controlReset();
    n.options() = options_.operatorOptions;
    if (!n.select(mainProgram, 0, &diagnostics)) return false;
    surveyData_ = std::make_shared<MachineDataStore>(cell_);
    survey_ = std::make_unique<ComputingProcess>(
        config_, programs_, surveySink_,
        servicesOf(surveyData_, std::make_shared<EventTable>(), options_));
    if (!survey_->beginSurvey(mainProgram, start_, options_.operatorOptions, options_.budget,
                              diagnostics))
        return false;
    surveyRevision_ = surveyData_->revision();  // page 61 zeroed: the defaults of every target
    surveyEntries_.clear();
    done_ = false;
    return true;
}

bool RestartVerifier::advance(std::uint64_t maxArrivals) {
    for (std::uint64_t i = 0; i < maxArrivals && !done_; ++i) {
        if (!arrival() || !stepBoth()) done_ = true;
    }
    return done_;
}

bool RestartVerifier::arrival() {
    const InterpreterState& computed = survey_->state();
    const InterpreterState& normal = normal_->interpreter.state();
    if (!sameArrival(computed, normal)) {
        const std::vector<StackLevel> levels = survey_->interpreter().callStack();
        const StackLevel at = levels.empty() ? StackLevel{} : levels.back();
        stop("RESTART_VERIFY_DIVERGED", {at.program, at.block, at.line, 0},
             "the computing process and the normal run no longer interpret the same block");
        return false;
    }
    if (!onBlock(normal)) return true;  // the next step ends the program
    ++report_.arrivals;
    const std::uint32_t pass = ++passes_[arrivalKey(normal)];
    if (pass > options_.maxPasses) {
        ++report_.beyondPasses;
        return true;
    }
    ComputingCheckpoint checkpoint = survey_->checkpoint();
    checkpoint.arrivals = pass - 1;  // the earlier arrivals with this call chain
    // The machine data the blocks before wrote (MTD): only when there are any.
    if (surveyData_->revision() != surveyRevision_) {
        surveyRevision_ = surveyData_->revision();
        surveyEntries_ = surveyData_->entries();
    }
    record(verify(selectionAt(pass), *normal_, normal_->interpreter.entryOfNextBlock(), &checkpoint,
                  surveyEntries_.empty() ? nullptr : &surveyEntries_));
    return true;
}

bool RestartVerifier::stepBoth() {
    Interpreter& n = normal_->interpreter;
    const ProgramPtr program = n.state().program;
    const std::uint32_t block = n.state().block;
    const RunResult normal = n.step();
    normal_->blocks += normal.blocksInterpreted;
    const ComputingProgress computed = survey_->step();
    if (normal.status == RunStatus::Error) {
        report_.diagnostics.append(normal.diagnostics);
        return false;
    }
    if (normal.blocksInterpreted > 0) trackJump(program, block);
    if (computed.status == ComputingStatus::Failed) {
        for (const Diagnostic& d : survey_->diagnostics().items())
            if (d.severity == Severity::Error) report_.diagnostics.add(d);
        stop("RESTART_VERIFY_DIVERGED", locationOf(*program, block),
             "the computing process failed where the normal run did not");
        return false;
    }
    if (normal.status == RunStatus::Ended || computed.status == ComputingStatus::Ended) {
        report_.complete =
            normal.status == RunStatus::Ended && computed.status == ComputingStatus::Ended;
        if (!report_.complete)
            stop("RESTART_VERIFY_DIVERGED", locationOf(*program, block),
                 "only one of the normal run and the computing process ended here");
        return false;
    }
    if (normal_->blocks >= options_.budget) {
        stop("BLOCK_BUDGET", locationOf(*program, block),
             "the verification was stopped after " + std::to_string(options_.budget) +
                 " interpreted blocks (block budget)");
        return false;
    }
    return true;
}

void RestartVerifier::trackJump(const ProgramPtr& program, std::uint32_t block) {
    const std::optional<Word> word = jumpWordOf(*program, block);
    if (!word || word->jump != JumpKind::JMP) return;
    const ProgramPtr& to = normal_->interpreter.state().selected;
    const int destination = to ? to->number : -1;
    if (destination == main_) {  // back in the main program: no JMP needed on the path
        jumps_.clear();
        jumpDestinations_.clear();
        return;
    }
    const auto again = std::find(jumpDestinations_.begin(), jumpDestinations_.end(), destination);
    if (again != jumpDestinations_.end()) {  // a cycle of JMPs: the first way there will do
        const auto keep = static_cast<std::size_t>(again - jumpDestinations_.begin()) + 1;
        jumps_.resize(keep);
        jumpDestinations_.resize(keep);
        return;
    }
    jumps_.push_back({program->number, block});
    jumpDestinations_.push_back(destination);
}

RestartSelection RestartVerifier::selectionAt(std::uint32_t pass) const {
    const InterpreterState& s = normal_->interpreter.state();
    RestartSelection selection;
    selection.process = config_.index;
    selection.mainProgram = main_;
    selection.path = jumps_;
    for (const CallFrame& frame : s.callStack)
        selection.path.push_back({frame.program->number, frame.callBlock});
    selection.target = {s.program->number, s.block};
    selection.runs = pass;
    return selection;
}

VerifiedTarget RestartVerifier::verify(const RestartSelection& selection, const NormalRun& normal,
                                       const CompensatedPosition& entry,
                                       const ComputingCheckpoint* checkpoint,
                                       const std::vector<MachineDataStore::Entry>* data) {
    VerifiedTarget result;
    result.selection = selection;
    result.where = locationOf(*normal.interpreter.state().program, selection.target.block);
    TargetCell cell(cell_, config_, programs_, options_);
    cell.sequence.setRouteCache(&routeCache_);
    if (data) cell.data->restore(*data);
    cell.live.restoreState(start_);
    cell.live.options() = options_.operatorOptions;
    cell.tracker.reset(start_);
    cell.tracker.setExecuting(false);  // the SPS only collects during the computing process
    cell.control.selectProgram(selection.mainProgram);
    DiagnosticList accepted;
    if (!cell.sequence.accept(selection, accepted, options_.budget)) {
        result.diagnostics = accepted;
        bool forbidden = false;
        for (const Diagnostic& d : accepted.items())
            forbidden = forbidden || notSelectableCode(d.code);
        result.outcome = forbidden ? TargetOutcome::NotSelectable : TargetOutcome::Failed;
        return result;
    }
    if (checkpoint) cell.sequence.resumeComputing(*checkpoint);
    for (RestartPhase phase = cell.sequence.advance(kSlice);
         phase == RestartPhase::Computing || phase == RestartPhase::Active;
         phase = cell.sequence.advance(kSlice))
        if (cell.sequence.held() && !cell.press(ControlKey::Start)) break;
    if (cell.sequence.phase() != RestartPhase::TargetReached) {
        result.outcome = TargetOutcome::Failed;
        result.diagnostics = cell.sequence.diagnostics();
        return result;
    }
    const auto m16 = readBuffer(*cell.data, config_.index, 1);
    const auto q = readBuffer(*cell.data, config_.index, 2);
    const auto expectedM16 = normal.collector.m16().elements();
    const auto expectedQ = normal.collector.q().elements();
    const RestartStateView expected{&normal.interpreter.state(), &expectedM16, &expectedQ, nullptr};
    const RestartStateView computed{&cell.sequence.computing().state(), &m16, &q, nullptr};
    result.computed =
        compareRestartStates(expected, computed, CompareScope::Computed, cell.live.axes());
    if (options_.adjust) {
        cell.tracker.setExecuting(true);
        bool ok = cell.press(ControlKey::Start);
        while (ok && cell.sequence.active()) {
            const RestartPhase phase = cell.sequence.advance(kSlice);
            const bool held = cell.sequence.held();
            if (held || phase == RestartPhase::AutomaticAgain)
                ok = cell.press(ControlKey::Start);
            else if (phase == RestartPhase::ManualMode)
                ok = cell.press(ControlKey::Automatic);
        }
        if (cell.sequence.phase() != RestartPhase::Reestablished) {
            result.outcome = TargetOutcome::Failed;
            result.diagnostics = cell.sequence.diagnostics();
            if (!ok && cell.sequence.active())
                result.diagnostics.error("RESTART_KEY_REFUSED", result.where,
                                         "the operator's key was refused: " + cell.control.alarm());
            return result;
        }
        const std::array<double, kMaxAxes> standing = cell.live.axisPositions();
        const RestartStateView target{&normal.interpreter.state(), nullptr, nullptr, nullptr,
                                      &entry.axes};
        const RestartStateView after{&cell.live.state(), nullptr, nullptr, &cell.tracker.state(),
                                     &standing};
        result.cutting =
            compareRestartStates(target, after, CompareScope::Cutting, cell.live.axes());
    }
    result.outcome = result.computed.empty() && result.cutting.empty()
                         ? TargetOutcome::Reestablished
                         : TargetOutcome::Differs;
    return result;
}

void RestartVerifier::record(VerifiedTarget target) {
    if (options_.keepEveryTarget && target.outcome != TargetOutcome::NotSelectable)
        report_.every.push_back(target);
    if (target.outcome == TargetOutcome::NotSelectable) {
        ++report_.notSelectable;
        report_.problems.push_back(std::move(target));
        return;
    }
    ++report_.targets;
    if (target.outcome == TargetOutcome::Reestablished) {
        ++report_.reestablished;
        return;
    }
    report_.problems.push_back(std::move(target));
}

void RestartVerifier::stop(const char* code, const SourceLocation& where,
                           const std::string& message) {
    report_.diagnostics.error(code, where, message);
}

VerifiedTarget RestartVerifier::verifySelection(const RestartSelection& selection,
                                                const InterpreterState* current) {
    VerifiedTarget failed;
    failed.selection = selection;
    failed.outcome = TargetOutcome::Failed;
    RestartRoute route;
    if (!planRestartRoute(selection, programs_, route, failed.diagnostics)) return failed;
    failed.where = locationOf(*route.targetProgram, selection.target.block);
    const InterpreterState begin = current ? *current : start_;
    NormalRun normal(cell_, config_, programs_, options_);
    Interpreter& n = normal.interpreter;
    n.restoreState(begin);
    n.controlReset();
    n.options() = options_.operatorOptions;
    n.select(route.main, 0);
    for (const auto& [variable, value] : selection.variableChanges) {
        InterpreterState s = n.state();
        s.variables.values[static_cast<std::size_t>(variable)] = value;
        s.variables.written.set(static_cast<std::size_t>(variable));
        n.restoreState(s);
    }
    for (const auto& [event, value] : selection.eventChanges)
        normal.events->set(event.process, event.event, value);
    std::uint32_t arrivals = 0;
    std::uint64_t blocks = 0;
    while (blocks < options_.budget) {
        const InterpreterState& s = n.state();
        if (s.program == route.targetProgram && s.block == selection.target.block &&
            atRouteLevel(s, route) && ++arrivals >= selection.runs)
            break;
        const RunResult r = n.step();
        blocks += r.blocksInterpreted + 1;
        if (r.status == RunStatus::Error || r.status == RunStatus::Ended) {
            failed.diagnostics.append(r.diagnostics);
            failed.diagnostics.error("RESTART_TARGET_NOT_FOUND", failed.where,
                                     "the normal run does not reach the target");
            return failed;
        }
    }
    if (blocks >= options_.budget) {
        failed.diagnostics.error("BLOCK_BUDGET", failed.where,
                                 "the normal run did not reach the target within the budget");
        return failed;
    }
    const InterpreterState saved = start_;
    start_ = begin;
    VerifiedTarget result = verify(selection, normal, n.entryOfNextBlock(), nullptr, nullptr);
    start_ = saved;
    return result;
}

}  // namespace mtc::core
