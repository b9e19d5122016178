#pragma once

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>

#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/machine/ProcessControl.h"
#include "cnc_core/restart/ComputingProcess.h"
#include "cnc_core/restart/SimulatedSps.h"
#include "cnc_core/text/Messages.h"

namespace mtc::core {

/// Where an NC program restart stands (seed 000, Fig. 6-8).
enum class RestartPhase {
    Idle,            ///< nothing selected
    Active,          ///< PxxSBPACT = 1, waiting for PxxCBPSTR from the SPS
    Computing,       ///< the computing process runs (advance())
    TargetReached,   ///< retrace possible; Start runs ADJUST (needs PxxCREPOS, automatic)
    Adjusting,       ///< the ADJUST subroutine runs
    ManualMode,      ///< the SPS selected manual mode (Q9500): jog, then Automatic
    AutomaticAgain,  ///< automatic again: Start continues (REPOS)
    Repositioning,   ///< the REPOS subroutine runs (G77)
    Reestablished,   ///< state re-established: the program continues at the target block
    Failed,          ///< an error ended the restart; every signal is reset
    Aborted,         ///< Control reset ended the restart; every signal is reset
};

/// "idle", "active", "computing", "target_reached", "adjusting", "manual",
/// "automatic_again", "repositioning", "reestablished", "failed", "aborted".
const char* restartPhaseName(RestartPhase phase);

/// NC program restart of one process from the accepted selection to the
/// re-entry at the target block (seed 000, 2.7 to 2.9, 6.3, 7): the computing
/// process, then ADJUST and REPOS on the process's own interpreter, with the
/// interface signals in the order of Fig. 6-8 (PxxSBPACT, PxxCBPSTR, PxxSACTIV,
/// PxxSREPOS "multi-block retrace possible", PxxCREPOS, PxxCADV, PxxSAUTO /
/// PxxSMANU, PxxSCREST "state re-established"). While a restart is active it
/// takes the machine control keys of the process (ControlKeyHandler): Start,
/// Stop (hold), Control reset (abort, every signal back to 0), Manual and
/// Automatic. Work happens only in advance(), in bounded slices.
class RestartSequence : public ControlKeyHandler, private AuxObserver {
  public:
    /// `live` is the process's interpreter (its sink is the machine, `machine`
    /// is that same sink for the computing process's SPS output and jogging).
    /// Everything must outlive the sequence. `otherProcesses` serves @p:n.
    RestartSequence(ProcessControl& control, SimulatedSps& sps, Interpreter& live,
                    const ProgramStore& programs, MachineSink& machine,
                    VariableAccess* otherProcesses = nullptr);
    ~RestartSequence() override;
    RestartSequence(const RestartSequence&) = delete;
    RestartSequence& operator=(const RestartSequence&) = delete;

    /// The operator leaves the restart screen with `selection` (seed 000, 2.4,
    /// 6.1): needs PxxSREADY, automatic mode, no program active and a valid
    /// selection (else false, RESTART_* errors, nothing changed). Sets
    /// PxxSBPACT; the SPS answers with PxxCBPSTR and the computing process is
    /// ready to run. `budget` bounds the computing process and ADJUST/REPOS each.
    bool accept(const RestartSelection& selection, DiagnosticList& diagnostics,
                std::uint64_t budget = kDefaultBlockBudget);
    /// Does at most `maxBlocks` blocks of work of the current phase (computing
    /// process, ADJUST, REPOS) and one SPS scan. Returns the phase afterwards.
    RestartPhase advance(std::uint64_t maxBlocks);
    /// Machine control keys while a restart is active (else std::nullopt).
    std::optional<bool> handleKey(ControlKey key) override;
    /// Manual mode before ADJUST or after Q9500: moves machine axis `axis` to
    /// `machinePosition` (a jog; the machine sink sees the move). False when
    /// not in manual mode, not between subroutines, or outside the travel range.
    bool jog(int axis, double machinePosition);
    /// The restart verifier: right after accept(), before the
    /// computing process interpreted a block, it goes on from `checkpoint`
    /// (taken by the verifier's own run through the program at the arrival
    /// the selection names) instead of interpreting the blocks before again.
    /// False (nothing changed) in any other phase.
    bool resumeComputing(const ComputingCheckpoint& checkpoint);
    /// Asks for an abort from any thread; the next advance() performs it as
    /// Control reset would.
    void requestAbort();

    /// The cell's axis transfer handshake for GAX / FAX in the computing
    /// process (not owned; nullptr = none: they do not wait). R-021.
    void setAxisTransfer(AxisTransfer* transfer) { computing_.setAxisTransfer(transfer); }
    /// Program analyses kept across restarts (the verifier; not owned).
    void setRouteCache(RestartRouteCache* cache) { computing_.setRouteCache(cache); }
    /// The language of the alarm that a failed restart raises (the panel's;
    /// English by default, docs/DECISIONS.md D-024).
    void setLanguage(Language language) { language_ = language; }
    /// "GAX X1" while the computing process waits for another process, else "".
    std::string waitingFor() const { return computing_.filter().waitingFor(); }
    /// Where the restart stands.
    RestartPhase phase() const { return phase_; }
    /// Stop key or M00 / M01: Start continues.
    bool held() const { return held_; }
    /// Between accept() and the end (re-established, failed or aborted).
    bool active() const;
    /// Warnings and the error that ended the restart, since accept().
    const DiagnosticList& diagnostics() const { return diagnostics_; }
    /// The computing process (progress, route, the state at the target).
    const ComputingProcess& computing() const { return computing_; }
    /// The commanded state at the target (valid from TargetReached on).
    const ReentryPoint& reentry() const { return reentry_; }
    /// Multi-block retrace is possible and the state is not re-established yet
    /// (PxxSREPOS = 1, PxxSCREST = 0): from the target block to re-entry.
    bool reposPhase() const;
    /// Blocks of ADJUST and REPOS interpreted so far.
    std::uint64_t sequenceBlocks() const { return liveBlocks_; }

  private:
    void auxiliary(const AuxOutput& output, bool forwarded) override;
    /// Motion announcement AxxSMCPOS / AxxSMCNEG of every axis to 0 at the
    /// start of the computing process (seed 000, 6.4; R-033).
    void resetMotionAnnouncement();
    void react();
    void advanceComputing(std::uint64_t maxBlocks);
    void targetReached();
    /// Appends the computing process's diagnostics to the sequence's, once.
    void takeComputingDiagnostics();
    bool start();
    bool repositionKey();
    void stop();
    bool changeMode(OperatingMode mode);
    bool beginAdjust();
    void runLive(std::uint64_t maxBlocks);
    /// The next ADJUST block would return to the target with RTS before .REPOS.
    bool returnBeforeRepos() const;
    bool handleLive(const RunResult& result);
    bool liveTarget();
    void reestablished();
    /// Switches the process's adaptive feed control as the target had it.
    void restoreAdaptiveFeed();
    void fail(const std::string& code, const std::string& message);
    void resetAll(RestartPhase phase);
    void setSignal(const char* name, int value);
    int signal(const char* name) const;
    StopTarget reentryTarget() const;

    ProcessControl& control_;
    SimulatedSps& sps_;
    Interpreter& live_;
    const ProgramStore& programs_;
    MachineSink& machine_;
    ComputingProcess computing_;
    RestartPhase phase_ = RestartPhase::Idle;
    RestartPhase resumePhase_ = RestartPhase::Adjusting;  ///< continued after manual mode
    bool held_ = false;
    bool liveChanged_ = false;       ///< the live interpreter holds restart state
    bool computingReported_ = true;  ///< computing_.diagnostics() are in diagnostics_
    std::atomic<bool> abortRequested_{false};
    std::uint64_t budget_ = kDefaultBlockBudget;
    std::uint64_t liveBlocks_ = 0;
    std::array<double, kMaxAxes> actual_{};  ///< machine positions when the restart began
    std::array<std::int8_t, kSpindleSlots> actualSpindleModes_{};  ///< spindle modes then
    std::array<int, kToolSpindles> actualTools_{};                 ///< tools in the spindles then
    ReentryPoint reentry_;
    ProgramPtr adjustProgram_;
    std::optional<std::uint32_t> reposBlock_;
    std::size_t adjustDepth_ = 0;  ///< call stack size inside ADJUST (its own level)
    DiagnosticList diagnostics_;
    Language language_ = Language::English;
};

}  // namespace mtc::core
