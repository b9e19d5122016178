#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/machine/MachineConfig.h"
#include "cnc_core/machine_data/MachineDataStore.h"
#include "cnc_core/restart/ComputingProcess.h"
#include "cnc_core/restart/RestartAuxCollector.h"
#include "cnc_core/restart/RestartRoute.h"
#include "cnc_core/restart/RestartSelection.h"
#include "cnc_core/restart/RestartStateCompare.h"

namespace mtc::core {

/// Passes per target block the verifier checks unless told otherwise.
inline constexpr std::uint32_t kDefaultVerifyPasses = 16;

struct VerifyOptions {
    bool adjust = false;  ///< also run ADJUST and REPOS and compare the cutting state
    std::uint32_t maxPasses = kDefaultVerifyPasses;  ///< 1..65536 arrivals per target
    std::uint64_t budget = kDefaultBlockBudget;      ///< bound of each run
    InterpreterOptions operatorOptions;              ///< skip blocks, optional stop
    bool keepEveryTarget = false;  ///< VerifyReport::every (tests, a target list on screen)
    /// The process's tool list and zero offsets (SetupData) every run of the
    /// verifier reads; nullptr = the machine configuration's.
    std::shared_ptr<const ToolList> tools;
    std::shared_ptr<const ZeroOffsetTable> zeroOffsets;
};

enum class TargetOutcome {
    Reestablished,  ///< every compared item equal
    Differs,        ///< differences listed
    Failed,         ///< the restart failed (diagnostics say why)
    NotSelectable,  ///< the seed forbids this target (a cycle, the 11th level)
};

/// One arrival checked as a restart target.
struct VerifiedTarget {
    RestartSelection selection;  ///< the path and runs that name this arrival
    SourceLocation where;        ///< the target block
    TargetOutcome outcome = TargetOutcome::Reestablished;
    std::vector<StateDifference> computed;  ///< computing process vs normal run
    std::vector<StateDifference> cutting;   ///< after ADJUST / REPOS vs the target
    DiagnosticList diagnostics;             ///< why it failed or is not selectable
};

struct VerifyReport {
    std::uint64_t arrivals = 0;            ///< block arrivals of the normal run
    std::uint64_t targets = 0;             ///< arrivals checked (pass <= maxPasses, selectable)
    std::uint64_t reestablished = 0;       ///< targets without any difference
    std::uint64_t notSelectable = 0;       ///< arrivals the seed forbids as targets
    std::uint64_t beyondPasses = 0;        ///< arrivals after the maxPasses-th of their block
    std::vector<VerifiedTarget> problems;  ///< targets that differ, failed, or are not selectable
    std::vector<VerifiedTarget> every;     ///< every checked target (keepEveryTarget)
    DiagnosticList diagnostics;            ///< of the runs (an error ends the verification)
    bool complete = false;                 ///< the normal run reached the program end
    /// "1,204 of 1,210 targets re-established; 6 leave G0 active: N0017, ...".
    std::string coverageLine() const;
};

/// The restart verifier (issue 15, restart.md R-028): for every arrival at
/// every block of a program tree (each pass up to maxPasses) the state the
/// computing process computes must equal the state of a normal run at that
/// arrival; with `adjust`, ADJUST and REPOS must leave the cutting state of
/// the target. One normal run and one computing process run side by side
/// through the program, block by block; at every arrival a real restart of
/// the cell (RestartSequence, signals, SPS, ADJUST, REPOS) goes on from the
/// computing process's checkpoint instead of computing the blocks before
/// again. Everything runs on private interpreters, machine data and events;
/// nothing of a station changes. Incremental: advance() in slices.
class RestartVerifier {
  public:
    /// `cell`, `programs` must outlive the verifier.
    RestartVerifier(const MachineConfig& cell, int process, const ProgramStore& programs,
                    VerifyOptions options = {});
    ~RestartVerifier();
    RestartVerifier(const RestartVerifier&) = delete;
    RestartVerifier& operator=(const RestartVerifier&) = delete;

    /// Starts the verification of program `mainProgram` from the machine
    /// state `current` (a station's interpreter state; default: power-on).
    /// False (diagnostics) when the program cannot run.
    bool begin(int mainProgram, DiagnosticList& diagnostics,
               const InterpreterState* current = nullptr);
    /// Checks at most `maxArrivals` arrivals. True when the verification is done.
    bool advance(std::uint64_t maxArrivals);
    bool done() const { return done_; }
    const VerifyReport& report() const { return report_; }

    /// One target as the operator chose it on the restart screen (its path,
    /// runs, variable and event changes): a normal run to that arrival and a
    /// full restart, compared the same way (the result review screen).
    VerifiedTarget verifySelection(const RestartSelection& selection,
                                   const InterpreterState* current = nullptr);

  private:
    struct NormalRun;
    struct TargetCell;

    bool arrival();
    bool stepBoth();
    /// After the normal run executed `block`: a JMP extends the path to the program of level 0.
    void trackJump(const ProgramPtr& program, std::uint32_t block);
    RestartSelection selectionAt(std::uint32_t pass) const;
    /// `entry`: where the normal run's axes stand before the target block.
    VerifiedTarget verify(const RestartSelection& selection, const NormalRun& normal,
                          const CompensatedPosition& entry, const ComputingCheckpoint* checkpoint,
                          const std::vector<MachineDataStore::Entry>* data);
    void record(VerifiedTarget target);
    void stop(const char* code, const SourceLocation& where, const std::string& message);

    const MachineConfig& cell_;
    const ProcessConfig& config_;
    const ProgramStore& programs_;
    VerifyOptions options_;
    InterpreterState start_;
    int main_ = 0;
    std::unique_ptr<NormalRun> normal_;
    std::shared_ptr<MachineDataStore> surveyData_;
    NullSink surveySink_;                                 ///< what the survey outputs goes nowhere
    std::uint64_t surveyRevision_ = 0;                    ///< of surveyData_ when last copied
    std::vector<MachineDataStore::Entry> surveyEntries_;  ///< its values then (empty: defaults)
    std::unique_ptr<ComputingProcess> survey_;
    RestartRouteCache routeCache_;  ///< the programs' analyses, for every target
    std::unordered_map<std::string, std::uint32_t> passes_;
    std::vector<BlockRef> jumps_;        ///< JMP blocks that led to the program of level 0
    std::vector<int> jumpDestinations_;  ///< the program each of them led to
    VerifyReport report_;
    bool done_ = true;
};

}  // namespace mtc::core
