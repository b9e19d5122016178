#include "cnc_core/interp/Interpreter.h"

#include "cnc_core/interp/AuxFunctionGroups.h"
#include "cnc_core/machine/InMemoryMachineData.h"

namespace mtc::core {
namespace {

std::shared_ptr<MachineDataProvider> ownMachineData(const InterpreterServices& services,
                                                    const ProcessConfig& config) {
    if (services.machineData) return services.machineData;
    MachineConfig cell;
    cell.processes.push_back(config);
    return std::make_shared<InMemoryMachineData>(cell);
}

std::shared_ptr<EventTable> ownEvents(const InterpreterServices& services) {
    return services.events ? services.events : std::make_shared<EventTable>();
}

}  // namespace

const char* runStatusName(RunStatus status) {
    switch (status) {
        case RunStatus::Running:
            return "running";
        case RunStatus::Ended:
            return "ended";
        case RunStatus::Stopped:
            return "stopped";
        case RunStatus::TargetReached:
            return "target";
        case RunStatus::BudgetExceeded:
            return "budget";
        case RunStatus::Error:
            return "error";
    }
    return "error";
}

namespace {

/// The shared zero offsets of `services`, else the configuration's. The
/// configuration's entries are checked either way (a bad column refuses the run).
std::shared_ptr<const ZeroOffsetTable> offsetsFor(const InterpreterServices& services,
                                                  const ProcessConfig& config,
                                                  DiagnosticList& diagnostics) {
    auto own = std::make_shared<const ZeroOffsetTable>(ZeroOffsetTable::build(config, diagnostics));
    return services.zeroOffsets ? services.zeroOffsets : own;
}

/// A usual block (BlockInput::special false) with no G word but G0..G3, no
/// axis written twice and no transformation in force: BlockExecutor::plan
/// plans it itself, and it can change nothing of the modal state but what
/// assignUsualBlock() copies (I-028).
bool changesOnlyMotionFields(const BlockInput& in, const ModalState& next) {
    constexpr std::uint32_t kOtherGroups = ~(1u << kGroupInterpolation);
    return !in.special && in.repeatedAxisColumn == 0 && (in.gMask & kOtherGroups) == 0 &&
           !next.transformation.active();
}

/// `to = from` for such a block, whose plan wrote into `from` only: the
/// interpolation group, F, the programmed axes' work and machine positions
/// (MotionPlanner: no transformation, so no other axis), the rotary axis
/// modes (a spindle moved as an axis) and the simulated time. Each axis pair
/// is copied as the 16-byte unit of assignModalState(), so that the move's
/// `end`, copied next, reads every 16 bytes from one store (I-026).
/// InterpShortcuts.* compare every field with the general path, which copies all.
[[gnu::always_inline]] inline void assignUsualBlock(ModalState& to, const ModalState& from,
                                                    std::uint32_t axisMask) {
    to.g[kGroupInterpolation] = from.g[kGroupInterpolation];
    for (std::uint32_t rest = axisMask; rest != 0;) {
        const auto pair = static_cast<std::size_t>(__builtin_ctz(rest)) & ~std::size_t{1};
        std::memcpy(&to.work[pair], &from.work[pair], 16);
        std::memcpy(&to.machine[pair], &from.machine[pair], 16);
        rest &= ~(3u << pair);
    }
    to.rotaryAxisMode = from.rotaryAxisMode;
    static_assert(offsetof(ModalState, time) == offsetof(ModalState, feed) + 8, "feed, time");
    copyInEightByteMoves<16>(&to.feed, &from.feed);
}

}  // namespace

Interpreter::Interpreter(const ProcessConfig& config, const ProgramStore& programs,
                         MachineSink& sink, InterpreterServices services)
    : config_(config),
      programs_(programs),
      axes_(ProcessAxes::build(config, configDiagnostics_)),
      compensation_(sink, config, axes_),
      sink_(compensation_.output()),
      zeroOffsets_(offsetsFor(services, config, configDiagnostics_)),
      tools_(services.tools ? services.tools
                            : std::make_shared<const ToolList>(ToolList::fromConfig(config))),
      defaults_(defaultGGroups(config)),
      machineData_(ownMachineData(services, config)),
      events_(ownEvents(services)),
      otherProcesses_(services.otherProcesses),
      axisTransfer_(services.axisTransfer),
      evaluator_(
          {&state_, &input_, machineData_.get(), services.otherProcesses, config.index, nullptr}),
      executor_({&config_, &axes_, zeroOffsets_.get(), tools_.get(), &defaults_, &mGroupOf_}),
      programFlow_(programs, config.index, events_.get()) {
    compensation_.useTools(tools_.get());  // radius, lengths, edges of the process's tool list
    const int plane = config.defaultPlane();
    if (plane < 17 || plane > 19)
        configDiagnostics_.error("CFG_DEFAULT_PLANE", {},
                                 "process " + std::to_string(config.index) +
                                     ": B004 default plane must be 17, 18 or 19");
    mGroupOf_ = AuxFunctionGroups(config).table();
    state_.modal.plane = PlaneSelection::base(axes_, defaults_[kGroupPlane]);
    resetModal();
    state_.mGroups.fill(-1);
    for (const auto& group : config.mGroups)
        if (group.number >= 1 && group.number <= 15)
            state_.mGroups[static_cast<size_t>(group.number)] = group.resetValue;
    rebuildNames();
}

bool Interpreter::select(int number, std::uint32_t startBlock, DiagnosticList* diagnostics) {
    ProgramPtr program = programs_.find(config_.index, number);
    if (!program) {
        if (diagnostics)
            diagnostics->error("PROGRAM_NOT_FOUND", {number, "", 0, 0},
                               "program " + std::to_string(number) + " does not exist in process " +
                                   std::to_string(config_.index));
        return false;
    }
    return select(std::move(program), startBlock, diagnostics);
}

bool Interpreter::select(ProgramPtr program, std::uint32_t startBlock,
                         DiagnosticList* diagnostics) {
    if (!program || (startBlock > 0 && startBlock >= program->blocks.size())) {
        if (diagnostics)
            diagnostics->error("BLOCK_RANGE", {program ? program->number : 0, "", 0, 0},
                               "the start block lies outside the program");
        return false;
    }
    state_.selected = program;
    state_.program = std::move(program);
    state_.block = startBlock;
    state_.callStack.clear();
    state_.ended = false;
    programFlow_.clearCache();
    withdrawAxisRequests();
    return true;
}

SourceLocation Interpreter::currentLocation() const {
    const Program& program = *state_.program;
    // Past the last block: point at the last block (or line 1 of an empty program).
    const std::uint32_t index = state_.block < program.blocks.size() || program.blocks.empty()
                                    ? state_.block
                                    : static_cast<std::uint32_t>(program.blocks.size() - 1);
    SourceLocation where = blockLocation(program, index);
    if (where.line == 0) where.line = 1;
    return where;
}

void Interpreter::setStopTarget(std::optional<StopTarget> target) {
    target_ = target;
    targetArrivals_ = 0;
}

void Interpreter::restoreState(const InterpreterState& state) {
    state_ = state;
    compensation_.restart();
    modalChanged();
    programFlow_.clearCache();
    rebuildNames();
}

bool Interpreter::writeVariable(int index, double value) {
    if (index < 0 || index >= kVariableCount) return false;
    state_.variables.values[static_cast<std::size_t>(index)] = value;
    state_.variables.written.set(static_cast<std::size_t>(index));
    return true;
}

RunResult Interpreter::step() {
    RunResult result;
    // One object returned on every path: the caller's result is built in
    // place (returning run(0) directly would cost a move and a destructor
    // of `result` on every block).
    if (configDiagnostics_.hasErrors() || !state_.program) {
        result = run(0);
        return result;
    }
    const std::uint64_t released = compensation_.released();
    Outcome outcome = executeNext(result.diagnostics, result.blocksInterpreted);
    // A held move (radius compensation) goes out with the next block that
    // moves in the plane; the look-ahead bounds how many blocks that takes.
    while (outcome == Outcome::Continue && compensation_.holding() &&
           compensation_.released() == released)
        outcome = executeNext(result.diagnostics, result.blocksInterpreted);
    switch (outcome) {
        case Outcome::Continue:
            result.status = RunStatus::Running;
            break;
        case Outcome::Ended:
            result.status = RunStatus::Ended;
            break;
        case Outcome::Stopped:
            result.status = RunStatus::Stopped;
            break;
        case Outcome::Target:
            result.status = RunStatus::TargetReached;
            break;
        case Outcome::Error:
            result.status = RunStatus::Error;
            break;
    }
    return result;
}

RunResult Interpreter::run(std::uint64_t budget) {
    RunResult result;
    if (configDiagnostics_.hasErrors()) {
        result.diagnostics.append(configDiagnostics_);
        result.status = RunStatus::Error;
        return result;
    }
    if (!state_.program) {
        result.diagnostics.error("NO_PROGRAM", {}, "no program is selected");
        result.status = RunStatus::Error;
        return result;
    }
    state_.ended = false;
    for (;;) {
        if (result.blocksInterpreted >= budget) {
            result.diagnostics.error(
                "BLOCK_BUDGET", currentLocation(),
                "the run was stopped after " + std::to_string(budget) +
                    " interpreted blocks (block budget); is the program an endless loop?");
            result.status = RunStatus::BudgetExceeded;
            return result;
        }
        switch (executeNext(result.diagnostics, result.blocksInterpreted)) {
            case Outcome::Continue:
                continue;
            case Outcome::Ended:
                result.status = RunStatus::Ended;
                return result;
            case Outcome::Stopped:
                result.status = RunStatus::Stopped;
                return result;
            case Outcome::Target:
                result.status = RunStatus::TargetReached;
                return result;
            case Outcome::Error:
                result.status = RunStatus::Error;
                return result;
        }
    }
}

bool Interpreter::syntaxError(const BlockContext& context) const {
    std::vector<std::string> details;
    const auto line = block_.line;
    for (const auto& d : context.program.diagnostics.items())
        if (d.where.line == static_cast<int>(line)) details.push_back(d.message);
    return context.error("BLOCK_SYNTAX", "the block has syntax errors and cannot be executed", 0,
                         details);
}

// Inline in executeNext (one call less per block); the error path is out of line.
[[gnu::always_inline]] inline bool Interpreter::checkedBlock(const Program& program,
                                                             std::uint32_t index,
                                                             DiagnosticList& diagnostics) {
    const BlockContext context{program, index, diagnostics};
    if (block_.flags & kBlockHasError) return syntaxError(context);
    if (!planSynced_) plan_.next = state_.modal;
    planSynced_ = false;
    const BlockDecoder decoder(axes_, names_, evaluator_,
                               {program, index, input_, diagnostics, options_.shortcuts});
    if (!decoder.decode(block_)) return false;
    // I-023: a usual block has no jump, MTD, variable or AFC word, so the
    // tests of those words are skipped (they would find nothing).
    const bool usual = options_.shortcuts && !input_.special;
    // Asked once per block (the commit asks again); without a control and
    // its words in the block the answer is no.
    afcInvolved_ = (afc_ || (!usual && (input_.adaptiveFeed != 0 || input_.idleMeasurement ||
                                        input_.stallRecording))) &&
                   adaptiveFeedInvolved();
    if (usual) flow_.kind = FlowPlan::Kind::Next;
    return executor_.plan(context, input_, state_, plan_, options_) &&
           (usual || planFlow(context)) &&
           (usual || (input_.mtdCount == 0 && input_.writeCount == 0) ||
            validateMachineData(context)) &&
           (!afcInvolved_ || planAdaptiveFeed(context)) &&
           (axisTransfer_ == nullptr || planAxisOwnership(context)) &&
           (!compensation_.involved(state_.modal, plan_.next) || planCompensation(context));
}

// A usual block (BlockInput::special false) without tool compensation or
// adaptive feed control in the block: commit() without what such a block
// cannot have (variables, MTD, aux functions, dwell, commands, program
// control, a jump; I-023). InterpShortcuts.* compare it with commit().
// Inline in executeNext: one call and one frame less per block.
[[gnu::always_inline]] inline Interpreter::Outcome Interpreter::commitUsual(const Program& program,
                                                                            std::uint32_t index) {
    const bool motion = plan_.hasMotion && options_.output.motion;
    if (changesOnlyMotionFields(input_, plan_.next)) {
        copyMoveStart(motion);
        assignUsualBlock(state_.modal, plan_.next, input_.axisMask);
        planSynced_ = true;
    } else if (commitModalState(motion)) {
        rebuildNames();
    }
    if (motion) emitMotion(program, index);
    ++state_.block;
    return Outcome::Continue;
}

// Inline in run() and step(): one call and one frame less per block (I-023).
[[gnu::always_inline]] inline Interpreter::Outcome Interpreter::executeNext(
    DiagnosticList& diagnostics, std::uint64_t& executed) {
    if (!axisWaits_.empty()) {  // a GAX waits for the holder's FAX (R-022)
        if (!waitingForAxis().empty()) return Outcome::Stopped;
        axisWaits_.clear();
    }
    const Program& program = *state_.program;
    const std::uint32_t index = state_.block;
    if (index < program.blocks.size()) program.blocks.read(index, block_);
    if (index >= program.blocks.size() || (block_.flags & kBlockProgramEnd)) {
        const SourceLocation where = currentLocation();
        if (!state_.callStack.empty()) {
            diagnostics.error("SUBROUTINE_WITHOUT_RTS", where,
                              "the end of program " + std::to_string(program.number) +
                                  " was reached inside a subroutine (RTS missing)");
            return Outcome::Error;
        }
        diagnostics.warning("PROGRAM_END_MISSING", where,
                            "the program ended without BST, RET, M02 or M30");
        programEnd(&diagnostics);
        return Outcome::Ended;
    }
    if (target_ && program.number == target_->program && index == target_->block &&
        ++targetArrivals_ >= target_->pass) {
        target_.reset();
        return Outcome::Target;
    }
    if ((block_.flags & kBlockSkip) && options_.skipBlocks) {
        ++state_.block;
        return Outcome::Continue;
    }
    ++executed;
    if (!checkedBlock(program, index, diagnostics)) {
        if (!options_.continueAfterError) return Outcome::Error;
        ++state_.block;
        return Outcome::Continue;
    }
    // The usual block's commit is inline; commit() (its frame is large) is a call.
    const bool usual = options_.shortcuts && !input_.special && !compensation_.planned() &&
                       !afcInvolved_ && flow_.kind == FlowPlan::Kind::Next;
    const Outcome outcome =
        usual ? commitUsual(program, index) : commit(program, index, diagnostics);
    if (holdRequested_) {
        holdRequested_ = false;
        if (outcome == Outcome::Continue) return Outcome::Stopped;
    }
    return outcome;
}

bool Interpreter::planCompensation(const BlockContext& context) {
    const CompensationBlock block{
        state_.modal,       plan_.next,
        plan_.hasMotion,    plan_.motionType,
        input_.axisMask,    input_.axisFunction != 0,
        plan_.planeCenter1, plan_.planeCenter2,
        plan_.fullCircle,   input_.axisFunction == 77 ? &state_.reentry : nullptr};
    return compensation_.plan(context, block);
}

CompensatedPosition Interpreter::entryOfNextBlock() {
    bool planned = false;
    if (compensation_.tracking() && compensation_.holding() && state_.program) {
        const Program& program = *state_.program;
        const std::uint32_t index = state_.block;
        if (index < program.blocks.size()) program.blocks.read(index, block_);
        const bool executes = index < program.blocks.size() && !(block_.flags & kBlockProgramEnd) &&
                              !((block_.flags & kBlockSkip) && options_.skipBlocks);
        DiagnosticList ignored;  // a block that cannot run: the held move ends as at a stop
        if (executes) planned = checkedBlock(program, index, ignored);
    }
    const CompensatedPosition entry = compensation_.entryOfPlannedBlock(state_.modal, planned);
    compensation_.discardPlan();
    return entry;
}

bool Interpreter::planFlow(const BlockContext& context) {
    if (input_.jumpWord < 0) {
        flow_.kind = FlowPlan::Kind::Next;
        return true;
    }
    return programFlow_.plan(context, input_, state_, plan_.next, flow_);
}

bool Interpreter::validateMachineData(const BlockContext& context) {
    for (int i = 0; i < input_.mtdCount; ++i) {
        const auto& w = input_.mtdWrites[static_cast<size_t>(i)];
        const MachineDataStatus status =
            machineData_->check(w.address, w.value, MachineDataWriter::Nc);
        if (status != MachineDataStatus::Ok)
            return context.error(
                machineDataStatusCode(status),
                "MTD(" + std::to_string(w.address.page) + "," + std::to_string(w.address.process) +
                    "," + std::to_string(w.address.sub) + "," + std::to_string(w.address.element) +
                    ") cannot take the value " + std::to_string(w.value),
                w.column);
    }
    for (int i = 0; i < input_.writeCount; ++i) {
        const auto& w = input_.writes[static_cast<size_t>(i)];
        double probe = 0;
        if (w.process >= 0 && w.process != config_.index &&
            (!otherProcesses_ || !otherProcesses_->read(w.process, w.index, probe)))
            return context.error("VARIABLE_PROCESS", "variable @" + std::to_string(w.process) +
                                                         ":" + std::to_string(w.index) +
                                                         " cannot be written: no such process");
    }
    return true;
}

}  // namespace mtc::core
