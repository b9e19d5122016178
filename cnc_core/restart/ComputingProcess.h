#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>

#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/restart/RestartAuxCollector.h"
#include "cnc_core/restart/RestartOutputFilter.h"
#include "cnc_core/restart/RestartRoute.h"
#include "cnc_core/restart/RestartSelection.h"

namespace mtc::core {

/// Where a computing process stands.
enum class ComputingStatus {
    Idle,           ///< begin() not called (or it failed)
    Running,        ///< more blocks to interpret: call advance() again
    Stopped,        ///< M00 (M01 with optional stop) or single block: advance() again continues
    TargetReached,  ///< stopped before the target block on its N-th arrival: done
    Failed,         ///< an error ended it (diagnostics): target not found, rejected block, budget
    Aborted,        ///< requestAbort() (Control reset) ended it
    Waiting,        ///< GAX / FAX waits for another process: advance() again looks (R-021)
    Ended,          ///< beginSurvey(): the program ended (the verifier's run is complete)
};

/// "idle", "running", "stopped", "target", "failed", "aborted", "waiting", "ended".
const char* computingStatusName(ComputingStatus status);

struct ComputingProgress {
    ComputingStatus status = ComputingStatus::Idle;
    std::uint64_t blocksInterpreted = 0;  ///< since begin()
    std::uint32_t arrivals = 0;           ///< arrivals at the target with the selected call chain
    bool singleBlockStop = false;         ///< Stopped by single-block mode (not M00 / M01)
};

/// Where a computing process stands at one arrival, to go on from there in
/// another computing process of the same program (the restart verifier: one
/// run through the program instead of one per target, restart.md R-028).
struct ComputingCheckpoint {
    InterpreterState state;  ///< the program pointer on the block arrived at
    FunctionBuffer m16;      ///< page 61 buffers collected so far
    FunctionBuffer q;
    std::uint32_t arrivals = 0;  ///< arrivals at the target with its call chain before this one
    std::uint64_t blocks = 0;    ///< blocks interpreted so far
    /// Where the axes stand before the block arrived at (entry()); the tool
    /// compensation that found it is not part of `state`.
    CompensatedPosition entry;
};

/// The computing process of NC program restart (seed 000, 2.7, 2.8, 3.1, 4,
/// 5.2, 5.4): interprets the selected program from the start block to the
/// target block without motion and, unless Bxx.058..061 say Yes for the
/// function type, without auxiliary output, and collects the state the
/// machine must have at the target: modal G groups, M groups 1..15, the
/// M(16) and Q buffers of page 61, S/T/E, variables and page 60.
///
/// It runs on an interpreter of its own (same configuration, program memory,
/// machine data and event table as the process's interpreter), started from
/// a copy of the process's state, so an abort leaves the process untouched.
/// It runs in slices (advance) so that a screen stays responsive; abort from
/// any thread with requestAbort(). Never throws.
class ComputingProcess {
  public:
    /// `sps` receives what passes to the SPS (see RestartOutputFilter). The
    /// references must outlive this object. `services` should be those of the
    /// process's interpreter (machine data pages 60/61, events).
    ComputingProcess(const ProcessConfig& config, const ProgramStore& programs, MachineSink& sps,
                     InterpreterServices services);
    ComputingProcess(const ComputingProcess&) = delete;
    ComputingProcess& operator=(const ComputingProcess&) = delete;

    /// Prepares a computing process for `selection` from the process state
    /// `current` (variables and positions carry over; modal groups start as
    /// after a control reset). `operatorOptions` gives the skip-block and
    /// optional-stop switches. Checks the selection (planRestartRoute),
    /// applies the operator's variable and event changes, zeroes page 61 and
    /// puts the program pointer on the start block. Fails (false, errors in
    /// `diagnostics`, status Idle, nothing changed) on a bad selection.
    bool begin(const RestartSelection& selection, const InterpreterState& current,
               const InterpreterOptions& operatorOptions, std::uint64_t budget,
               DiagnosticList& diagnostics);
    /// The verifier's run: the computing process from N0000 of
    /// `mainProgram` without a target, through the whole program; step() goes
    /// one arrival further, status Ended at the program end. False (nothing
    /// started) when the program cannot run.
    bool beginSurvey(int mainProgram, const InterpreterState& current,
                     const InterpreterOptions& operatorOptions, std::uint64_t budget,
                     DiagnosticList& diagnostics);
    /// One arrival: interprets the block the pointer is on (a skipped block
    /// is passed over), with the handling of advance(). The verifier reads
    /// state() between two steps.
    ComputingProgress step();
    /// The state at the current arrival (see ComputingCheckpoint).
    ComputingCheckpoint checkpoint();
    /// Where the axes stand before the block the pointer is on in an
    /// uninterrupted run (compensation.md TC-013): the compensated re-entry
    /// point at TargetReached. After resume() and before any block, the
    /// checkpoint's.
    CompensatedPosition entry();
    /// After begin(): goes on from `checkpoint`, taken at an arrival of the
    /// same program and start by another computing process, as if the blocks
    /// before had been interpreted here (the machine data they wrote must
    /// already be in this process's pages).
    void resume(const ComputingCheckpoint& checkpoint);
    /// Interprets at most `maxBlocks` blocks (Running / Stopped continue).
    /// Ends with TargetReached (page 60 and 61 written), Failed (BST, RET,
    /// M02, M30 before the target: RESTART_TARGET_NOT_FOUND; a rejected block;
    /// the block budget), Aborted, or Stopped at M00. Returns the progress.
    ComputingProgress advance(std::uint64_t maxBlocks);
    /// advance() without a slice limit (the CLI): runs until the target, a
    /// failure, an abort or a programmed stop (Stopped: call it again to go on).
    ComputingProgress runToEnd() { return advance(~std::uint64_t{0}); }
    /// Asks a running advance() (any thread) to stop at its next check (every
    /// few thousand blocks); the status becomes Aborted. Pages 60/61 keep
    /// what begin() wrote; the process's interpreter was never touched.
    void requestAbort() { abortRequested_.store(true, std::memory_order_relaxed); }
    /// Single-block mode (seed 000, 2.7: selectable at any time during the
    /// computing process, any thread): advance() stops (Stopped,
    /// singleBlockStop) after each interpreted block; switched off, the next
    /// advance() runs on.
    void setSingleBlock(bool on) { singleBlock_.store(on, std::memory_order_relaxed); }
    bool singleBlock() const { return singleBlock_.load(std::memory_order_relaxed); }
    /// The cell's axis transfer handshake (not owned; nullptr = none, then GAX
    /// and FAX do not wait). With it, a GAX / FAX makes advance() return
    /// Waiting after its block until another process answers (seed 000, 5.4).
    void setAxisTransfer(AxisTransfer* transfer);
    /// Program analyses kept across selections (the verifier; not owned;
    /// nullptr = worked out for each begin()).
    void setRouteCache(RestartRouteCache* cache) { routeCache_ = cache; }
    /// Withdraws a waiting GAX / FAX (Control reset of the restart).
    void cancelTransfers() { filter_.cancelTransfers(); }

    /// Status, blocks and arrivals after the last begin() / advance().
    const ComputingProgress& progress() const { return progress_; }
    /// Blocks interpreted so far; safe to read from another thread.
    std::uint64_t blocksSoFar() const { return blocksSoFar_.load(std::memory_order_relaxed); }
    /// Diagnostics since begin() (warnings of the run, the error that ended it).
    const DiagnosticList& diagnostics() const { return diagnostics_; }
    /// The selection of the last successful begin().
    const RestartSelection& selection() const { return selection_; }
    /// Start block and call chain worked out by begin().
    const RestartRoute& route() const { return route_; }
    /// The state computed so far; at TargetReached the state at the target
    /// (program pointer on the target block, call stack as at the target).
    const InterpreterState& state() const { return interpreter_.state(); }
    /// The computing process's own interpreter (axes, positions, call stack).
    const Interpreter& interpreter() const { return interpreter_; }
    /// The M(16) / Q buffers as collected so far.
    const RestartAuxCollector& collector() const { return collector_; }
    /// Commands passed to and held back from the SPS.
    const RestartOutputFilter& filter() const { return filter_; }

  private:
    enum class Next { Continue, Return };

    /// Bxx.033 and Bxx.036 are No (seed 000, 2.1); else RESTART_PARAMETER errors.
    bool parametersAllowRestart(int program, DiagnosticList& diagnostics) const;
    /// Puts the interpreter on the route's start block (begin, beginSurvey).
    void start(const RestartSelection& selection, RestartRoute route,
               const InterpreterState& current, const InterpreterOptions& operatorOptions,
               std::uint64_t budget, DiagnosticList diagnostics);
    void budgetExhausted();

    Next handle(const RunResult& result);
    Next targetArrival();
    void publishBuffers();
    void finish(ComputingStatus status);
    void count(std::uint64_t blocks);
    ComputingProgress singleBlockStop();

    const ProcessConfig& config_;
    const ProgramStore& programs_;
    RestartOutputFilter filter_;
    RestartAuxCollector collector_;
    Interpreter interpreter_;
    RestartSelection selection_;
    RestartRoute route_;
    StopTarget target_;
    std::uint64_t budget_ = 0;
    ComputingProgress progress_;
    DiagnosticList diagnostics_;
    bool survey_ = false;  ///< beginSurvey(): no target, the program end is the end
    RestartRouteCache* routeCache_ = nullptr;
    std::atomic<bool> abortRequested_{false};
    std::atomic<bool> singleBlock_{false};
    std::atomic<std::uint64_t> blocksSoFar_{0};
    /// resume(): the checkpoint's entry, valid while no block was interpreted since.
    std::optional<CompensatedPosition> resumedEntry_;
    std::uint64_t resumedAt_ = 0;
};

}  // namespace mtc::core
