#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cnc_core/compensation/ToolCompensation.h"
#include "cnc_core/interp/BlockExecutor.h"
#include "cnc_core/interp/BlockInput.h"
#include "cnc_core/interp/BlockPlan.h"
#include "cnc_core/interp/ExpressionEvaluator.h"
#include "cnc_core/interp/InterpreterState.h"
#include "cnc_core/interp/MachineSink.h"
#include "cnc_core/interp/PlanningOptions.h"
#include "cnc_core/interp/ProgramFlow.h"
#include "cnc_core/interp/VariableAccess.h"
#include "cnc_core/language/Diagnostic.h"
#include "cnc_core/machine/AxisNameTable.h"
#include "cnc_core/machine/AxisTransfer.h"
#include "cnc_core/machine/EventTable.h"
#include "cnc_core/machine/MachineConfig.h"
#include "cnc_core/machine/MachineDataProvider.h"
#include "cnc_core/machine/ProcessAxes.h"
#include "cnc_core/machine/ZeroOffsetTable.h"
#include "cnc_core/program/ProgramStore.h"
#include "cnc_core/tooldata/ToolList.h"

namespace mtc::core {

class AdaptiveFeedControl;

/// Default bound of run(): 10,000,000 interpreted blocks (CLI-CONTRACT.md).
inline constexpr std::uint64_t kDefaultBlockBudget = 10'000'000;

/// How a run (or step) ended.
enum class RunStatus {
    Running,         ///< step(): the block was executed, the program goes on
    Ended,           ///< program end (BST, RET, M02, M30, or the last block)
    Stopped,         ///< M00, or M01 with optional stop on; run() again continues
    TargetReached,   ///< the stop target block was reached (it is NOT executed)
    BudgetExceeded,  ///< the block budget is used up (diagnostic BLOCK_BUDGET)
    Error,           ///< a block was rejected; state is as before that block
};

/// "running", "ended", "stopped", "target", "budget", "error".
const char* runStatusName(RunStatus status);

struct RunResult {
    RunStatus status = RunStatus::Ended;
    DiagnosticList diagnostics;           ///< errors and warnings of this run
    std::uint64_t blocksInterpreted = 0;  ///< blocks executed by this call
};

/// What leaves the interpreter. The restart computing process switches
/// motion off and the aux types off as its process parameters say
/// (Bxx.058..061); M groups, M(16), Q, S, T and E are collected regardless.
struct OutputOptions {
    bool motion = true;    ///< moves to MachineSink::motion
    bool dwell = true;     ///< G4 to MachineSink::dwell
    bool m = true;         ///< M functions to MachineSink::auxiliary
    bool q = true;         ///< Q functions
    bool s = true;         ///< S words
    bool te = true;        ///< T and E words
    bool commands = true;  ///< MTP, TCH, AXD, ... to MachineSink::command
};

/// Options of a run; the planning ones (arcTolerance, shortcuts) are in the
/// base, which the interpreter hands to BlockExecutor::plan with each block.
struct InterpreterOptions : PlanningOptions {
    OutputOptions output;
    bool optionalStop = false;        ///< M01 stops like M00
    bool skipBlocks = false;          ///< '/' blocks are skipped (the skip switch)
    bool continueAfterError = false;  ///< check mode: a rejected block is skipped, the run goes on
    /// Without an adaptive feed control (the restart computing process, which
    /// moves nothing): G25 / G26 only switch ModalState::adaptiveFeed, ITM and
    /// AXD P-7-3651 measure nothing, instead of AFC_NOT_AVAILABLE.
    bool logicalAdaptiveFeed = false;
};

/// Stop BEFORE block `block` (index into Program::blocks) of program
/// `program` when it is reached for the `pass`-th time (restart target).
struct StopTarget {
    int program = 0;
    std::uint32_t block = 0;
    std::uint32_t pass = 1;
};

/// Sees every M, Q, S, T and E the program issues, whether or not it was
/// forwarded to the sink (`forwarded` false = suppressed by OutputOptions).
class AuxObserver {
  public:
    virtual ~AuxObserver() = default;
    virtual void auxiliary(const AuxOutput& output, bool forwarded) = 0;
};

/// One program level of the call stack (level 0 = main program).
struct StackLevel {
    int program = 0;
    std::uint32_t blockIndex = 0;  ///< current block of the innermost level, call block otherwise
    std::string block;             ///< "N0012" or ""
    int line = 0;
};

/// Cell-wide services an interpreter uses. Left empty, the interpreter makes
/// its own event table and an InMemoryMachineData for its process.
struct InterpreterServices {
    std::shared_ptr<MachineDataProvider> machineData;
    std::shared_ptr<EventTable> events;
    VariableAccess* otherProcesses = nullptr;  ///< @p:n of other processes
    /// Axis ownership of the cell (GAX / FAX, R-022); nullptr = none: GAX /
    /// FAX only reach the sink and every axis may move (restart computing).
    AxisTransfer* axisTransfer = nullptr;
    /// The tool list and zero offsets of the process (cnc_core/tooldata
    /// SetupData, shared with the operator and the CLI): a change is seen by
    /// the next block. nullptr = the machine configuration's, fixed.
    std::shared_ptr<const ToolList> tools;
    std::shared_ptr<const ZeroOffsetTable> zeroOffsets;
};

/// Executes the NC programs of one process, block by block: decode (words,
/// expressions), plan (every rule checked, nothing changed), commit (state,
/// outputs through the sink, program flow). A rejected block changes
/// nothing. All state lives in InterpreterState (state(), restoreState()).
/// Never throws; every problem is a diagnostic with program, block, line.
class Interpreter {
  public:
    /// The references must outlive the interpreter. Configuration problems
    /// (bad axis definitions, zero offset columns) are reported by
    /// configurationDiagnostics(); the interpreter then refuses to run.
    Interpreter(const ProcessConfig& config, const ProgramStore& programs, MachineSink& sink,
                InterpreterServices services = {});
    Interpreter(const Interpreter&) = delete;
    Interpreter& operator=(const Interpreter&) = delete;

    const DiagnosticList& configurationDiagnostics() const { return configDiagnostics_; }

    /// Selects program `number` of this process and puts the program
    /// pointer on block `startBlock`. Returns false (diagnostic
    /// PROGRAM_NOT_FOUND / BLOCK_RANGE into `diagnostics`) when impossible;
    /// then nothing changes. The call stack is cleared.
    bool select(int number, std::uint32_t startBlock = 0, DiagnosticList* diagnostics = nullptr);
    /// Same with a program that is not (or not yet) in the store.
    bool select(ProgramPtr program, std::uint32_t startBlock = 0,
                DiagnosticList* diagnostics = nullptr);
    /// Executes one block (skipped '/' blocks are passed over). While tool
    /// radius compensation holds a move back for the next block's start, the
    /// following blocks are executed too until the machine gets a move.
    RunResult step();
    /// Executes blocks until program end, M00, the stop target, an error or
    /// `budget` blocks (then BLOCK_BUDGET). After Ended the program pointer
    /// is back on the first block of the selected program.
    RunResult run(std::uint64_t budget = kDefaultBlockBudget);
    /// Control reset: program end resets (M groups, base coordinate system,
    /// transformation off, G groups to their defaults), call stack cleared,
    /// program pointer on the first block of the selected program.
    void controlReset();

    const InterpreterState& state() const { return state_; }
    /// Replaces the whole state (e.g. a snapshot taken with state()).
    void restoreState(const InterpreterState& state);
    /// Writes variable @`index` from outside the program (another process's
    /// @p:n, the cell's VariableAccess). False (nothing written) out of range.
    bool writeVariable(int index, double value);
    /// Program levels from the main program to the current block.
    std::vector<StackLevel> callStack() const;

    InterpreterOptions& options() { return options_; }
    const InterpreterOptions& options() const { return options_; }
    /// Sets (or clears with std::nullopt) the block to stop before; resets the pass count.
    void setStopTarget(std::optional<StopTarget> target);
    /// How often the stop target block was reached so far.
    std::uint32_t targetArrivals() const { return targetArrivals_; }
    /// Asked from the sink while a block is committed (e.g. an axis transfer
    /// that has to wait for another process): run() / step() return Stopped
    /// after this block instead of going on.
    void requestHold() { holdRequested_ = true; }
    /// The GAX this process waits for ("X"), "" when it waits for none: step()
    /// and run() return Stopped without a block until the holder frees it.
    std::string waitingForAxis() const;
    /// Observer of every aux function (nullptr = none). Not owned.
    void setObserver(AuxObserver* observer) { observer_ = observer; }

    EventTable& events() { return *events_; }
    /// Adaptive feed control of this process (G25/G26, ITM, AXD
    /// P-7-3651/3652). Without one, G26, ITM and P-7-3651 are refused
    /// (AFC_NOT_AVAILABLE) and G25 does nothing.
    void setAdaptiveFeed(std::shared_ptr<AdaptiveFeedControl> afc);
    /// The adaptive feed control of this process, nullptr when none was given.
    AdaptiveFeedControl* adaptiveFeed() { return afc_.get(); }
    MachineDataProvider& machineData() { return *machineData_; }
    const MachineDataProvider& machineData() const { return *machineData_; }
    const ProcessAxes& axes() const { return axes_; }
    /// The tool list the interpreter checks T against (and the tool
    /// compensation reads radius and lengths from).
    const ToolList& tools() const { return *tools_; }
    /// The zero offsets G54..G59 in force.
    const ZeroOffsetTable& zeroOffsets() const { return *zeroOffsets_; }
    const ProcessConfig& config() const { return config_; }
    /// Name of machine axis `axis` as the JSON and transcripts show it: its
    /// designation 1 in programs ("X", "Z2", "C" for spindle S1 with rotary
    /// axis capability), or the configuration name of a plain spindle ("S2").
    std::string axisName(int axis) const { return axes_.axis(axis).displayName(); }
    /// Name the program addresses `axis` by now: its designation 2 (Cxx.075)
    /// while G31/G32 transforms it, else axisName() (seed 003, 4.5 and 5.2).
    std::string programmedAxisName(int axis) const;
    /// Where the moves sent so far put the axes: the commanded machine
    /// positions with the tool compensation (radius, edge, length) applied.
    /// A move held back by radius compensation is not in it yet.
    std::array<double, kMaxAxes> axisPositions() const {
        return compensation_.tracking() ? compensation_.axisPositions() : state_.modal.machine;
    }
    /// Where the axes stand when the block at the program pointer begins in
    /// an uninterrupted run (the restart's re-entry point, compensation.md
    /// TC-013): with tool compensation, a held move is joined to that
    /// block's move, which is planned for it (nothing changes). Without
    /// compensation: the commanded machine positions.
    CompensatedPosition entryOfNextBlock();
    /// Machine positions `machine` as the program would write them now: zero
    /// offsets and transformation undone, diameter and inch applied (the
    /// inverse of MotionPlanner). E.g. the runtime program's inserted blocks.
    std::array<double, kMaxAxes> programView(const std::array<double, kMaxAxes>& machine) const;
    /// The same under `modal` (zero offset, units, transformation) instead
    /// of the state now: a display of a block the interpreter has passed.
    std::array<double, kMaxAxes> programView(const std::array<double, kMaxAxes>& machine,
                                             const ModalState& modal) const;
    /// Workpiece coordinate of `axis` as the program sees it now (the
    /// inverse of the conversions of MotionPlanner: mm, degrees, diameter).
    double programmedPosition(int axis) const;
    /// The axes stand at `machine` (machine positions; e.g. after a restart
    /// computing process, which moves nothing): the commanded positions become
    /// these and the programmed coordinates are re-derived. Nothing else changes.
    void takeMachinePositions(const std::array<double, kMaxAxes>& machine);
    /// The operator jogged an axis by hand. With Bxx.036 = Yes ("manual axis
    /// jogging causes reset", seed 000, 2.1) that is a Control reset: the
    /// program-end resets, plane and transformation back to the base system
    /// (seed 003). Returns true when it reset. Every jog path calls it.
    bool manualJogPerformed();
    /// Writes the page 60 elements (rotary axis modes, transformation, tool
    /// spindles) of this process into the machine data (restart target reached).
    void publishPage60();
    /// Writes page 60 elements 1..3 (rotary axis mode of S1..S3): seed 000,
    /// 4.1 updates them "upon program stop" (M00 / M01 do it themselves; the
    /// Stop key and single-block holds call it) and at the restart target.
    void publishRotaryAxisModes();

  private:
    enum class Outcome { Continue, Ended, Stopped, Target, Error };

    Outcome executeNext(DiagnosticList& diagnostics, std::uint64_t& executed);
    bool checkedBlock(const Program& program, std::uint32_t index, DiagnosticList& diagnostics);
    /// BLOCK_SYNTAX for a block the parser rejected (cold); returns false.
    [[gnu::cold]] bool syntaxError(const BlockContext& context) const;
    /// Where the program pointer is (the last block when it is past the end).
    SourceLocation currentLocation() const;
    /// Location of the current block (block_) for the sink, without printf.
    SourceLocation sinkLocation(const Program& program, std::uint32_t index) const;
    Outcome commit(const Program& program, std::uint32_t index, DiagnosticList& diagnostics);
    /// commit() of a usual block (I-023).
    Outcome commitUsual(const Program& program, std::uint32_t index);
    /// The first step of both commits: the move's start (when `motion`) and
    /// the planned modal state. True when the transformation changed.
    [[gnu::always_inline]] bool commitModalState(bool motion) {
        const bool transformationChanged =
            plan_.next.transformation.kind() != state_.modal.transformation.kind();
        copyMoveStart(motion);
        assignModalState(state_.modal, plan_.next);
        planSynced_ = true;
        motionFrameCurrent_ = false;  // the frame's groups, plane or transformation may change
        return transformationChanged;
    }
    /// The move's start (when `motion`): the machine position before the commit.
    [[gnu::always_inline]] void copyMoveStart(bool motion) {
        if (motion)  // not `rep movs` (a plain assignment in this place)
            copyInSteps<16, sizeof motion_.start>(motion_.start.data(),
                                                  state_.modal.machine.data());
    }
    bool planFlow(const BlockContext& context);
    /// Tool radius and length compensation of the block (last plan step).
    bool planCompensation(const BlockContext& context);
    bool validateMachineData(const BlockContext& context);
    void emitAux(const Program& program, std::uint32_t index);
    void sendAux(AuxOutput& out, char type, int spindle, double value, bool forwarded);
    void emitMotion(const Program& program, std::uint32_t index);
    /// The modal state's frame G groups, plane and transformation are those the
    /// frame fields of motion_ were filled from (I-022).
    bool sameMotionFrame() const;
    /// The move's fields that follow from the frame (zero offset, plane,
    /// transformation, block transition, radius / diameter).
    void fillMotionFrame(Motion& m);
    /// The zero offset of each axis for m.zeroOffset (read from the table,
    /// which the operator may change between two blocks).
    void zeroOffsetValues(Motion& m) const;
    void runCommands(const Program& program, std::uint32_t index);
    Outcome applyFlow(const Program& program, std::uint32_t index, DiagnosticList& diagnostics);
    void programEnd(DiagnosticList* diagnostics = nullptr);
    /// G25/G26, ITM, AXD P-7-3651 of the block and, while G26 is active,
    /// the functions that exclude it (InterpreterAfc.cpp).
    bool planAdaptiveFeed(const BlockContext& context);
    /// Switches G26/G25, requests ITM, records the stall torque.
    void commitAdaptiveFeed();
    /// After the move: a runtime error of adaptive feed control (508, 509,
    /// 510) becomes an error of this block; the extra time joins the clock.
    bool adaptiveFeedAfterMotion(const Program& program, DiagnosticList& diagnostics);
    bool adaptiveFeedInvolved() const;
    /// GAX / FAX of the block name axes of this process; FAX only of held
    /// axes; the move only of held axes (InterpreterAxisOwnership.cpp).
    bool planAxisOwnership(const BlockContext& context);
    /// Carries out GAX / FAX of the current block on the cell's ownership.
    void commitAxisTransfer(const AxisTransferCommand& transfer);
    /// Axes of this process another process holds (or nobody), as a mask.
    std::uint32_t axesNotHeld();
    /// Index of this process's axis called `name` in a transfer, or -1.
    int transferAxisIndex(const std::string& name) const;
    /// Withdraws the GAX this process waits for (Control reset).
    void withdrawAxisRequests();
    void resetBaseSystem();
    void resetModal();
    void rebuildNames() { names_ = AxisNameTable::build(axes_, state_.modal.transformation); }
    /// Call after changing state_.modal outside commit(): plan_.next is stale.
    void modalChanged() {
        planSynced_ = false;
        motionFrameCurrent_ = false;
    }

    const ProcessConfig& config_;
    const ProgramStore& programs_;
    // Declared before compensation_, which keeps a reference to axes_: a
    // member is constructed in declaration order.
    DiagnosticList configDiagnostics_;
    ProcessAxes axes_;
    /// Tool compensation between the interpreter and the machine: the moves
    /// go through it, everything else through sink_ (its output queue).
    ToolCompensation compensation_;
    MachineSink& sink_;
    bool holdRequested_ = false;  ///< requestHold() during the current block
    std::shared_ptr<const ZeroOffsetTable> zeroOffsets_;
    std::shared_ptr<const ToolList> tools_;
    GGroupValues defaults_{};
    std::array<std::uint8_t, 1000> mGroupOf_{};
    std::shared_ptr<MachineDataProvider> machineData_;
    std::shared_ptr<EventTable> events_;
    VariableAccess* otherProcesses_ = nullptr;
    std::shared_ptr<AdaptiveFeedControl> afc_;
    AuxObserver* observer_ = nullptr;
    AxisTransfer* axisTransfer_ = nullptr;
    struct AxisWait {
        AxisTransfer::Ticket ticket;
        std::string axis;
    };
    std::vector<AxisWait> axisWaits_;          ///< GAX not granted yet
    std::uint64_t ownershipRevision_ = ~0ull;  ///< axisTransfer_ revision seen
    std::uint32_t axesNotHeld_ = 0;            ///< cached for that revision
    InterpreterOptions options_;
    std::optional<StopTarget> target_;
    std::uint32_t targetArrivals_ = 0;

    InterpreterState state_;
    AxisNameTable names_;
    Block block_;  ///< copy of the block being executed
    BlockInput input_;
    BlockPlan plan_;
    bool planSynced_ = false;   ///< plan_.next == state_.modal (saves a copy per block)
    bool afcInvolved_ = false;  ///< adaptiveFeedInvolved() of the block being executed
    FlowPlan flow_;
    Motion motion_;
    /// What the frame fields of motion_ were filled from (emitMotion).
    struct MotionFrame {
        bool valid = false;
        std::uint64_t groups = 0;  ///< frameGroups() of the G groups
        PlaneSelection plane;
        std::array<std::uint64_t, 2> transformation{};  ///< transformationKey()
    };
    MotionFrame motionFrame_;
    /// The frame fields of motion_ were filled from, or found equal to, the
    /// modal state as it is now: set by emitMotion(); only a usual block's
    /// commit (assignUsualBlock, which writes no frame field) keeps it, every
    /// other change of the modal state clears it (saves sameMotionFrame()).
    bool motionFrameCurrent_ = false;
    ExpressionEvaluator evaluator_;
    BlockExecutor executor_;
    ProgramFlow programFlow_;
};

}  // namespace mtc::core
