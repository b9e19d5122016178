#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "cnc_core/afc/AfcTrendRecorder.h"
#include "cnc_core/cell/DiagnosticLog.h"
#include "cnc_core/cell/ManualJog.h"
#include "cnc_core/cell/QueuedBlockStates.h"
#include "cnc_core/compiler/NcOptions.h"
#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/machine/MachineConfig.h"
#include "cnc_core/machine/ProcessControl.h"
#include "cnc_core/machine/SimulatedMachine.h"
#include "cnc_core/mdi/MdiRun.h"
#include "cnc_core/mdi/MdiSession.h"
#include "cnc_core/removal/LiveCut.h"
#include "cnc_core/removal/ReentryCollisions.h"
#include "cnc_core/restart/RestartSequence.h"
#include "cnc_core/restart/SimulatedSps.h"
#include "cnc_core/toolpath/RunTrace.h"

namespace mtc::core {

class AdaptiveFeedControl;
class MachineDataStore;

/// Most blocks one advance() call interprets: keeps a panel tick well under
/// a frame; a station whose program computes without moving lags behind the
/// clock instead (its simulated time only goes on while the machine works).
inline constexpr std::uint64_t kBlocksPerAdvance = 20'000;

/// One process (channel) of the cell, everything it runs on: process control
/// (mode, M keys, alarm, interface signals), the interpreter on the simulated
/// machine, adaptive feed control and its trend, the simulated SPS and the
/// NC program restart sequence (which takes the M keys while it is active).
/// The panel, the CLI and the tests drive it the same way: machine keys
/// through press(), time through advance(). Not copyable; everything it is
/// given must outlive it.
///
/// Time (docs/decisions/station.md): the interpreter fills the machine's
/// queue while the machine wants more; the machine works it off in simulated
/// time; M00, single block, errors and the program end take effect when the
/// machine has finished what was queued before them. The block the station
/// shows is the block the machine executes.
class Station : private ProgramRunner {
  public:
    Station(const ProcessConfig& config, const ProgramStore& programs,
            const InterpreterServices& services, MachineDataStore& machineData);
    ~Station() override;
    Station(const Station&) = delete;
    Station& operator=(const Station&) = delete;

    const ProcessConfig& config() const { return config_; }
    int process() const { return config_.index; }
    ProcessControl& control() { return control_; }
    const ProcessControl& control() const { return control_; }
    Interpreter& interpreter() { return interpreter_; }
    const Interpreter& interpreter() const { return interpreter_; }
    SimulatedMachine& machine() { return machine_; }
    const SimulatedMachine& machine() const { return machine_; }
    /// Adaptive feed control (page 30, signals, errors 508-510).
    AdaptiveFeedControl& adaptiveFeed() { return *afc_; }
    /// The adaptive feed trend the machine records.
    const AfcTrendRecorder& afcTrend() const { return trend_; }
    /// Whether the machine records that trend (default: yes, page 61 shows
    /// it). A headless run that never reads it turns it off: the trend is
    /// the only reader of the torque observed on a move without G26, so
    /// times, positions, page 30 and the signals stay the same (MOT-019).
    void keepAfcTrend(bool keep) {
        machine_.attachAdaptiveFeed(afc_.get(), keep ? &trend_ : nullptr);
    }
    /// Whether the station keeps the interpreter's state after each queued
    /// block for executingBlockState() (default: yes, the base screen shows
    /// it). Only the screens read those records; a headless run turns them
    /// off (about 500 bytes written per block, MOT-020). Off, the function
    /// returns nullptr.
    void keepBlockStates(bool keep) {
        keepBlockStates_ = keep;
        if (!keep) queued_.clear();
    }
    /// Lets the interpreter run `entries` machine queue entries beyond the
    /// look-ahead depth, the machine working them off in one go (MOT-022;
    /// 0, the default: none). Only for a driver that gives every advance()
    /// all the simulated time it asks for and presses no key mid-run (the
    /// CLI without samples): when the machine's time is read during a
    /// block (adaptive feed control), the machine catches up within it.
    void batchMachineWork(std::size_t entries) { machine_.setBatch(entries); }

    /// A machine control key (M key), as the operator presses it. Returns
    /// false (the alarm says why) when it is not allowed now.
    bool press(ControlKey key);
    /// Selects program `number` (refused while a program is active). The
    /// runtime program is prepared at once (compile on demand, C-013); a
    /// refusal of the preparer becomes the alarm.
    bool selectProgram(int number);

    /// Moves the station on by `seconds` of simulated time: blocks are
    /// interpreted while the machine wants more (at most `maxBlocks`), the
    /// machine works in time. Returns the simulated time that passed; less
    /// than `seconds` when the block bound was reached first (the station
    /// lags; the next call goes on from there).
    double advance(double seconds, std::uint64_t maxBlocks = kBlocksPerAdvance);
    // ---- the operator's overrides (docs/decisions/motion.md MOT-006): they
    // act at once on the moving axes, whoever runs them.
    /// Feed override of G1/G2/G3 in percent, clamped to 0 ... feedOverrideMax().
    void setFeedOverride(int percent);
    int feedOverride() const;
    /// Largest feed override of the process (B074, 100 ... 200 %).
    int feedOverrideMax() const;
    /// Rapid traverse override of G0 in percent, clamped to 0 ... 100.
    void setRapidOverride(int percent);
    int rapidOverride() const;
    /// The panel's override switches: one position up (`direction` > 0) or
    /// down (< 0) (OverrideSwitch.h, MOT-016).
    void stepFeedOverride(int direction);
    void stepRapidOverride(int direction);

    /// A program or MDI entry runs (active, not held, not stopped).
    bool running() const { return run_ != Run::None && feeding_; }
    /// Something needs time: a run, or the machine working off its queue.
    bool busy() const { return run_ != Run::None || !machine_.idle(); }
    /// Grows with every change the screens show (blocks, positions, keys).
    std::uint64_t revision() const { return revision_; }
    /// The axis this process waits for (GAX, R-022), "" when none.
    const std::string& waitingAxis() const { return waitingAxis_; }
    /// Blocks interpreted since the last Start.
    std::uint64_t runBlocks() const { return runBlocks_; }
    /// Bound of interpreted blocks per run: past it the run ends with
    /// BLOCK_BUDGET (0 = none, the panel's machine may loop for ever; the
    /// CLI's --max-blocks).
    void setBlockBudget(std::uint64_t blocks) { budget_ = blocks; }
    /// Warnings and errors of the current (or last) run since Start.
    const DiagnosticList& runDiagnostics() const { return runDiagnostics_; }
    /// Every diagnostic of the station as it arose (runs, MDI, the restart),
    /// as data: the error window reads the records after the last it saw.
    const DiagnosticLog& diagnostics() const { return log_; }
    /// How the last run ended; Running while one runs or none ran yet.
    RunStatus runStatus() const { return runStatus_; }
    /// Held at M00 / M01 (or M01 with optional stop): Start continues.
    bool atProgrammedStop() const { return stoppedBy_ == Pending::ProgrammedStop; }
    /// Held after a block in single-block mode: Start runs the next block.
    bool atSingleBlockStop() const { return stoppedBy_ == Pending::SingleBlock; }
    /// The program and block index interpreted last (what the station shows
    /// while the machine stands); nullptr before the first block of a run.
    const ProgramPtr& lastInterpretedProgram() const { return lastProgram_; }
    std::uint32_t lastInterpretedBlock() const { return lastBlock_; }
    /// The interpreter's state after the block the machine executes now
    /// (the interpreter may be the look-ahead ahead); nullptr while the
    /// machine stands or runs a move no block of this run queued.
    const QueuedBlockState* executingBlockState() const { return queued_.executing(); }
    /// The backplot (TP-016): the moves of the program run since its Start
    /// (or since a restart was accepted) and how far the axes have travelled
    /// along them. MDI entries and manual jogs are not in it; Control reset
    /// ends it where the axes stopped. Empty unless tracing is on.
    const RunTrace& runTrace() const { return trace_; }
    /// Keeps the backplot of the runs from the next Start on (the panel; off
    /// by default: the CLI has no use for it, and it holds about 45 bytes per
    /// segment of a run).
    void setRunTracing(bool on) { tracing_ = on; }
    /// The part the program run cuts as the axes travel (TP-027): from the
    /// next Start on, the program's blank (its window, RAW contour or the
    /// configuration's stock, at the finest resolution within
    /// removal::kViewCells cells) is swept by the tool in working position.
    /// MDI entries, jogs and a restart's run do not cut it; Control reset
    /// stops it where the axes stopped. Off by default (the CLI's runs).
    void setLiveCutting(bool on) { liveCutting_ = on; }
    const removal::LiveCut& liveCut() const { return liveCut_; }
    /// The language of the alarms and the MDI message built from a
    /// diagnostic (the panel's; English by default: the CLI's texts).
    /// docs/DECISIONS.md D-024.
    void setLanguage(Language language);
    /// Sees everything the interpreter (and the restart's jogging) sends to
    /// the machine, as it is sent (the CLI's motion list, recording tests).
    /// Not owned; nullptr = none.
    void setOutputListener(MachineSink* listener) { output_.listener = listener; }

    /// Makes the runtime program of a number ready before it runs or returns
    /// an alarm that refuses Start ("" = ready); the diagnostics behind a
    /// refusal go to `diagnostics`.
    using ProgramPreparer = std::function<std::string(int number, DiagnosticList& diagnostics)>;
    /// Installs (empty function: removes) the preparer Start calls first.
    void setPreparer(ProgramPreparer preparer) { preparer_ = std::move(preparer); }
    /// Runs the preparer for `number` ("" when none is installed); its
    /// diagnostics go to the log.
    std::string prepare(int number);

    /// The NC options the station's MDI takes the global macros from (the
    /// cell's; not owned, nullptr = no global macros).
    void useNcOptions(const NcOptions* options) { ncOptions_ = options; }
    /// Manual data input: the input, its history and the operator's message;
    /// Start in MDI mode runs the input.
    const MdiSession& mdi() const { return mdiSession_; }
    /// The operator edited the MDI input.
    void setMdiInput(std::string text);
    /// Puts MDI history item `row` back into the input.
    bool recallMdi(std::size_t row);
    /// Checks the MDI input without running it (refusals go to the log).
    bool checkMdi();
    /// True while an MDI entry runs (or is held).
    bool mdiRunning() const { return run_ == Run::Mdi; }
    /// Diagnostics of the last MDI run (lines = lines of the MDI input).
    const DiagnosticList& lastMdiDiagnostics() const { return mdiDiagnostics_; }

    // ---- manual mode (issue 17 §2, MOT-017): jog keys and the handwheel
    // move machine axis `axis` through the machine in time. Between the
    // restart's subroutines (seed 000, 2.9) the restart's rules apply. A
    // refusal returns false and says why in the alarm line.
    /// One increment (or handwheel detents times their factor): `distance`.
    bool jogBy(int axis, double distance, bool rapid = false);
    /// A jog key held down: moves until jogRelease() or the travel limit.
    bool jogStart(int axis, int direction, bool rapid = false);
    void jogRelease();
    /// Manual spindle keys: `rotation` +1 M3, -1 M4, 0 M5 of spindle
    /// `spindle` at `rpm` (negative: the commanded speed stays).
    bool manualSpindle(int spindle, int rotation, double rpm = -1.0);
    /// A spindle key of manual mode (ManualJog::spindleKey).
    bool manualSpindleKey(int spindle, SpindleKey key);
    /// A jog move is queued or running.
    bool jogging() const { return jog_.moving(); }

    // ---- NC program restart (seed 000): the sequence takes the M keys while
    // it is active; advance() runs its computing process in block slices and
    // ADJUST / REPOS through the machine in time.
    /// Hands the operator's selection to the sequence (PxxSBPACT; the SPS
    /// starts the computing process). False with the reasons in
    /// `diagnostics` when the NC refuses it; then nothing changed.
    bool acceptRestart(const RestartSelection& selection, DiagnosticList& diagnostics,
                       std::uint64_t budget = kDefaultBlockBudget);
    /// Abort: the next advance() ends the restart as Control reset would.
    void abortRestart();
    /// Manual mode between the subroutines: jogs machine axis `axis` by
    /// `distance` (seed 000, 2.9). False when the sequence refuses it.
    bool jogRestart(int axis, double distance);
    const RestartSequence& restart() const { return restart_; }
    /// The sequence itself, for tests that step it without the station's time.
    RestartSequence& restartSequence() { return restart_; }
    SimulatedSps& sps() { return sps_; }
    /// A restart was accepted since the station came up.
    bool restartStarted() const { return restartStarted_; }
    /// The interpreter state when the restart was accepted ("machine now").
    const InterpreterState& restartBefore() const { return restartBefore_; }
    /// Wall-clock milliseconds the last computing process took (0 while it runs).
    double restartComputingMs() const { return restartComputingMs_; }
    /// False: a re-established state does not run on (the CLI reports the
    /// state at the re-entry); true (default): machining continues.
    void setRunOnAfterRestart(bool runOn) { runOnAfterRestart_ = runOn; }
    /// Checks the restart's way back against the part at its target
    /// (D-021, removal::checkRestartReentry; nullopt unless the restart
    /// stands between the target reached and the re-entry). With live
    /// cutting on and the restart still at its target, the part at the
    /// target becomes the live part that ADJUST, REPOS and the run after
    /// them cut on (TP-027).
    const std::optional<removal::ReentryCheck>& checkReentry();
    /// The computing process runs and is not waiting (held, GAX / FAX): it
    /// only needs processor time, the panel may give it back-to-back slices.
    bool computing() const;

  private:
    /// The interpreter's sink: the machine, and the listener when there is one.
    struct Output : MachineSink {
        explicit Output(SimulatedMachine& machine) : machine(machine) {}
        void motion(const Motion& m) override;
        void auxiliary(const AuxOutput& a) override;
        void dwell(const SourceLocation& where, double seconds) override;
        void command(const MachineCommand& command) override;
        void sent(const SourceLocation& where);
        SimulatedMachine& machine;
        MachineSink* listener = nullptr;
        RunTrace* trace = nullptr;        ///< the program run's backplot while one is traced
        removal::LiveCut* cut = nullptr;  ///< the part the program run cuts, while one is cut
        std::uint64_t outputs = 0;        ///< calls so far; `last` is the latest one's location
        SourceLocation last;
    };
    enum class Run { None, Program, Mdi };
    /// What happens once the machine has worked off its queue.
    enum class Pending { None, SingleBlock, ProgrammedStop, End };

    // ProgramRunner: what ProcessControl calls for Start, Stop, Reset.
    std::string start(int number) override;
    std::string startMdi() override;
    std::string resume() override;
    void hold() override;
    void reset() override;

    void beginRun(Run run);
    /// The restart's share of advance(): blocks of the computing process,
    /// ADJUST / REPOS while the machine wants more, one SPS scan.
    void advanceRestart(std::uint64_t& blocks, std::uint64_t maxBlocks);
    void followRestartPhase();
    void continueAfterRestart();
    void feed(std::uint64_t& blocks, std::uint64_t maxBlocks);
    /// Handles one step's result; false when feeding stops.
    bool handle(const RunResult& result);
    /// The block bound is used up: the run ends with BLOCK_BUDGET.
    RunResult budgetExceeded() const;
    void settle();
    bool waitForAxis();
    void finish(const RunResult& result);
    void showCurrentBlock();
    /// A jog's refusal ("" = none) goes to the alarm line; true when none.
    /// `moved`: the refusal is empty and the jog queued jog_.lastMove().
    bool jogDone(const std::string& refusal, bool moved = false);
    /// MDI and jog moves cut on the last run's part (TP-028): the output's
    /// cut is the live cut while it has a part.
    bool cutByHand();
    /// Puts a run's diagnostics into the log (MDI: with the input line).
    void logRunDiagnostics(const DiagnosticList& diagnostics);
    /// Logs the restart's diagnostics that arose since the last look.
    void logRestartDiagnostics();
    /// The MDI entry ended (`completed` false: error or reset).
    void endMdi(bool completed);
    /// Keeps the interpreter's state after a block that queued work.
    /// Records the interpreter's state after a block whose machine items
    /// begin at `firstItem` (QueuedBlockState).
    void recordQueuedBlock(const ProgramPtr& program, std::uint32_t index, int callLevel,
                           std::uint64_t firstItem);
    /// A run of program `number` starts (Start, a restart accepted): a new
    /// backplot.
    void beginTrace(int number);
    /// A run of program `number` starts from its first block: a new blank
    /// for the live cut (setLiveCutting).
    void beginLiveCut(int number);

    const ProcessConfig& config_;
    const ProgramStore& programs_;
    ProcessControl control_;
    std::shared_ptr<AdaptiveFeedControl> afc_;
    AfcTrendRecorder trend_;
    SimulatedMachine machine_;
    Output output_;
    Interpreter interpreter_;
    SimulatedSps sps_;
    RestartSequence restart_;
    RestartPhase restartPhase_ = RestartPhase::Idle;  ///< phase at the last look
    bool restartStarted_ = false;
    InterpreterState restartBefore_;
    double restartComputingMs_ = 0.0;
    std::chrono::steady_clock::time_point computingSince_;
    ProgramPreparer preparer_;
    const NcOptions* ncOptions_ = nullptr;
    MdiSession mdiSession_;
    Language language_ = Language::English;
    MdiRun mdi_;
    DiagnosticList mdiDiagnostics_;

    Run run_ = Run::None;
    bool feeding_ = false;  ///< the interpreter may give the machine the next block
    Pending pending_ = Pending::None;
    Pending stoppedBy_ = Pending::None;  ///< why the run is held (SingleBlock, ProgrammedStop)
    RunResult ending_;
    DiagnosticList runDiagnostics_;
    RunStatus runStatus_ = RunStatus::Running;
    std::uint64_t budget_ = 0;
    bool runOnAfterRestart_ =
        true;  ///< the step that ended the run (taken when the machine is idle)
    std::uint64_t runBlocks_ = 0;
    std::uint64_t revision_ = 0;
    std::string waitingAxis_;
    ProgramPtr lastProgram_;  ///< program and block interpreted last
    std::uint32_t lastBlock_ = 0;
    QueuedBlockStates queued_;
    bool keepBlockStates_ = true;  ///< keepBlockStates()
    RunTrace trace_;
    bool tracing_ = false;  ///< setRunTracing()
    removal::LiveCut liveCut_;
    std::optional<removal::ReentryCheck> reentryCheck_;  ///< the last checkReentry()
    bool liveCutting_ = false;                           ///< setLiveCutting()
    ManualJog jog_;
    DiagnosticLog log_;
    std::size_t restartLogged_ = 0;  ///< restart diagnostics already in log_
};

}  // namespace mtc::core
