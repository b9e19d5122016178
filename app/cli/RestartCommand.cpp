#include "cli/RestartCommand.h"

#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "cli/CliOutput.h"
#include "cli/CommandSetup.h"
#include "cli/MachineDataKeeper.h"
#include "cli/MachineSetup.h"
#include "cli/ProgramMemory.h"
#include "cli/RestartRecorder.h"
#include "cli/RestartReport.h"
#include "cli/SetupDataCommand.h"
#include "cnc_core/cell/Cell.h"
#include "cnc_core/machine_data/MachineDataStore.h"
#include "cnc_core/restart/TargetPath.h"

namespace mtc::cli {

namespace {

/// Work per advance() call: the CLI has no screen to keep responsive.
constexpr std::uint64_t kSlice = std::uint64_t{1} << 40;
/// Simulated time per advance() call: as far as the work goes.
constexpr double kStep = 1e9;
/// Operator actions (Start after a stop, Automatic after manual mode) before
/// the CLI gives up; every one needs interpreted blocks, so the block bound
/// ends a runaway first.
constexpr int kMaxOperatorActions = 100000;

/// Machine, program memory and the program of the command line.
struct PreparedRestart {
    CommandSetup setup;
    ProgramRequest request;
    const core::ProcessConfig* process = nullptr;
    core::ProgramStore store;
    core::DiagnosticList diagnostics;          ///< warnings of the preparation, parse problems
    std::optional<core::SetupData> setupData;  ///< tool list and zero offsets (--data)
};

bool prepare(const CliOptions& options, PreparedRestart& p, core::DiagnosticList& failure) {
    std::optional<CommandSetup> setup = prepareCommand(options, failure);
    if (!setup) return false;
    p.setup = std::move(*setup);
    p.diagnostics.append(failure);
    failure.clear();
    if (!resolveProgram(options.arguments.front(), p.setup.programs, options.process,
                        options.processGiven, p.request, failure))
        return false;
    p.process = p.setup.machine.process(p.request.process);
    if (p.process == nullptr) {
        checkProcessExists(p.setup.machine, p.request.process, failure);
        return false;
    }
    p.store = storeWith(p.setup.programs.store, p.request);
    p.diagnostics.append(p.request.program->diagnostics);
    return loadRunSetupData(p.setup.machine, options.machineData.dataFile, p.setupData, failure);
}

/// The cell as the operator finds it, in the core's Cell (as the panel
/// builds it): the station of the process with its machine control keys,
/// SPS and restart sequence; the recorder sees what the station sends to
/// its machine. Time runs as fast as possible.
class RestartDriver {
  public:
    RestartDriver(const CliOptions& options, PreparedRestart& prepared)
        : options_(options),
          prepared_(prepared),
          cell_(prepared.setup.machine),
          station_(cell_.station(cell_.slotOfProcess(prepared.request.process))),
          dataKeeper_(options.machineData.dataFile) {
        core::NcOptions nc;
        nc.globalMacros = prepared.setup.globalMacros;  // before the store: nothing to parse again
        cell_.setNcOptions(std::move(nc));
        cell_.store() = prepared.store;
        if (prepared.setupData) cell_.setupData().adopt(*prepared.setupData);  // --data
        recorder_.setSequence(&station_.restart());
        station_.setOutputListener(&recorder_);
        station_.setRunOnAfterRestart(false);  // the report shows the state at the re-entry
        // One process restarts alone here: no other process answers a GAX / FAX
        // of its computing process (in the panel both stations take part).
        station_.restartSequence().setAxisTransfer(nullptr);
        station_.selectProgram(prepared.request.number);
    }
    ~RestartDriver() { station_.setOutputListener(nullptr); }

    const core::Interpreter& live() const { return station_.interpreter(); }

    /// Resolves the path, runs the restart; fills `report`. Returns false on
    /// a usage problem (malformed PATH: exit 2, diagnostics in `report`).
    bool run(RestartReport& report) {
        report.process = prepared_.process;
        report.interpreter = &station_.interpreter();
        report.sequence = &station_.restart();
        report.recorder = &recorder_;
        report.signals = &station_.control().signalTable();
        report.adjust = options_.adjust;
        report.checkCollisions = options_.checkCollisions;
        report.diagnostics = prepared_.diagnostics;
        dataKeeper_.load(cell_.machineData(), report.diagnostics);
        if (prepared_.request.program->diagnostics.hasErrors()) return true;
        core::TargetPathResult path =
            core::resolveTargetPath(options_.target, cell_.store(), prepared_.request.process,
                                    prepared_.request.number, &station_.interpreter().state());
        report.diagnostics.append(path.diagnostics);
        if (path.syntaxError) return false;
        if (!path.ok) return true;
        path.selection.runs = options_.runs;
        path.selection.fromLastPrimary = options_.fromPrimary;
        station_.press(core::ControlKey::ProgramRestart);  // the restart screen
        core::DiagnosticList accepted;
        report.accepted = station_.acceptRestart(path.selection, accepted, options_.maxBlocks);
        if (!report.accepted) {
            report.diagnostics.append(accepted);
            return true;
        }
        computingProcess();
        report.computed = takeSnapshot(station_.restart().computing().interpreter(),
                                       cell_.machineData(), prepared_.request.process);
        if (options_.checkCollisions) checkCollisions(report);
        if (options_.adjust && station_.restart().phase() == core::RestartPhase::TargetReached) {
            adjustAndRepos();
            report.final = takeSnapshot(station_.interpreter(), cell_.machineData(),
                                        prepared_.request.process);
        }
        report.diagnostics.append(station_.restart().diagnostics());
        report.diagnostics.append(operatorNotes_);
        return true;
    }

    /// Keeps what the restart changed in the `--data` file (page 60 at the
    /// target, MTD writes of ADJUST / REPOS).
    void saveData(core::DiagnosticList& diagnostics) {
        dataKeeper_.save(cell_.machineData(), diagnostics);
    }

  private:
    const core::RestartSequence& sequence() const { return station_.restart(); }

    /// At the target, before Start: the moves ADJUST and REPOS will make
    /// against the part cut up to the target (D-021), as the panel's review.
    void checkCollisions(RestartReport& report) {
        if (sequence().phase() != core::RestartPhase::TargetReached) return;
        core::removal::RemovalSettings settings;
        settings.resolution = options_.resolution;
        report.collisions = core::removal::checkRestartReentry(sequence(), station_.interpreter(),
                                                               cell_.store(), settings);
        if (!report.collisions) return;
        // What the removal run says about the part (no stock, target not
        // reached, rapid cuts); the program's own problems the computing
        // process reported already.
        for (const core::Diagnostic& d : report.collisions->diagnostics.items())
            if (d.code.rfind("REMOVAL_", 0) == 0) report.diagnostics.add(d);
        if (!report.collisions->checked)
            report.diagnostics.warning("REENTRY_NOT_CHECKED", {},
                                       "the ADJUST/REPOS moves were not checked against the part: "
                                       "no collision list (see the diagnostics before)");
    }

    bool continueAfterStop() {
        const std::vector<core::StackLevel> levels =
            sequence().phase() == core::RestartPhase::Computing
                ? sequence().computing().interpreter().callStack()
                : station_.interpreter().callStack();
        const core::StackLevel at = levels.empty() ? core::StackLevel{} : levels.back();
        operatorNotes_.warning("RESTART_PROGRAM_STOP", {at.program, at.block, at.line, 0},
                               "programmed stop: continued as with the Start key");
        return press(core::ControlKey::Start);
    }

    bool press(core::ControlKey key) {
        if (++actions_ > kMaxOperatorActions) return false;
        if (station_.press(key)) return true;
        if (!sequence().active()) return false;  // the sequence failed: its diagnostic says why
        operatorNotes_.error(
            "RESTART_KEY_REFUSED", {},
            std::string(core::keyName(key)) + " refused: " + station_.control().alarm());
        return false;
    }

    /// Time for the station: the computing process in slices, ADJUST and
    /// REPOS through the machine. Returns the phase afterwards.
    core::RestartPhase advance() {
        station_.advance(kStep, kSlice);
        return sequence().phase();
    }

    void computingProcess() {
        while (true) {
            const core::RestartPhase phase = advance();
            if (phase != core::RestartPhase::Computing && phase != core::RestartPhase::Active)
                return;
            if (sequence().held() && !continueAfterStop()) return;
        }
    }

    /// As the operator: Start (ADJUST), Automatic when the SPS selected
    /// manual mode, Start again (REPOS), until the re-entry.
    void adjustAndRepos() {
        if (!press(core::ControlKey::Start)) return;
        while (sequence().active()) {
            const core::RestartPhase phase = advance();
            bool ok = true;
            if (sequence().held())
                ok = continueAfterStop();
            else if (phase == core::RestartPhase::ManualMode)
                ok = press(core::ControlKey::Automatic);
            else if (phase == core::RestartPhase::AutomaticAgain)
                ok = press(core::ControlKey::Start);
            if (!ok) return;
        }
        while (station_.busy() && !station_.running())
            station_.advance(kStep);  // last REPOS move
    }

    const CliOptions& options_;
    PreparedRestart& prepared_;
    core::Cell cell_;
    core::Station& station_;
    RestartRecorder recorder_;
    MachineDataKeeper dataKeeper_;  ///< --data FILE
    core::DiagnosticList operatorNotes_;
    int actions_ = 0;
};

}  // namespace

int runRestartCommand(const CliOptions& options) {
    PreparedRestart prepared;
    core::DiagnosticList failure;
    if (!prepare(options, prepared, failure)) return reportSetupFailure(failure, options.json);
    RestartDriver driver(options, prepared);
    if (driver.live().configurationDiagnostics().hasErrors()) {
        failure.error("CLI_MACHINE_INVALID", {},
                      "the machine configuration cannot run process " +
                          std::to_string(prepared.request.process));
        failure.append(driver.live().configurationDiagnostics());
        return reportSetupFailure(failure, options.json);
    }
    RestartReport report;
    if (!driver.run(report)) return reportSetupFailure(report.diagnostics, options.json);
    driver.saveData(report.diagnostics);
    reportChangedFile(prepared.request.program, report.diagnostics);
    if (options.json) {
        JsonWriter json(stdout);
        writeRestartJson(json, report);
    } else {
        printRestartText(report);
    }
    return exitCodeFor(false, report.diagnostics);
}

}  // namespace mtc::cli
