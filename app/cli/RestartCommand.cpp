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
#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/machine/ProcessControl.h"
#include "cnc_core/machine_data/MachineDataStore.h"
#include "cnc_core/restart/RestartSequence.h"
#include "cnc_core/restart/SimulatedSps.h"
#include "cnc_core/restart/TargetPath.h"

namespace mtc::cli {

namespace {

/// Work per advance() call: the CLI has no screen to keep responsive.
constexpr std::uint64_t kSlice = std::uint64_t{1} << 40;
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

/// The live interpreter's services: the cell's machine data, an event
/// table, the tool list and zero offsets of the process.
core::InterpreterServices servicesOf(const PreparedRestart& prepared,
                                     std::shared_ptr<core::MachineDataStore> machineData) {
    core::InterpreterServices services;
    services.machineData = std::move(machineData);
    services.events = std::make_shared<core::EventTable>();
    services.tools = prepared.setupData->tools(prepared.request.process);
    services.zeroOffsets = prepared.setupData->offsets(prepared.request.process);
    return services;
}

/// The cell of one process as the operator finds it: interpreter on the
/// recording machine, machine control keys, SPS, and the restart sequence.
class RestartDriver {
  public:
    RestartDriver(const CliOptions& options, PreparedRestart& prepared)
        : options_(options),
          prepared_(prepared),
          machineData_(std::make_shared<core::MachineDataStore>(prepared.setup.machine)),
          dataKeeper_(options.machineData.dataFile),
          live_(*prepared.process, prepared.store, recorder_, servicesOf(prepared, machineData_)),
          control_(prepared.request.process),
          sps_(control_),
          sequence_(control_, sps_, live_, prepared.store, recorder_) {
        recorder_.setSequence(&sequence_);
        control_.selectProgram(prepared.request.number);
    }

    const core::Interpreter& live() const { return live_; }

    /// Resolves the path, runs the restart; fills `report`. Returns false on
    /// a usage problem (malformed PATH: exit 2, diagnostics in `report`).
    bool run(RestartReport& report) {
        report.process = prepared_.process;
        report.interpreter = &live_;
        report.sequence = &sequence_;
        report.recorder = &recorder_;
        report.signals = &control_.signalTable();
        report.adjust = options_.adjust;
        report.diagnostics = prepared_.diagnostics;
        dataKeeper_.load(*machineData_, report.diagnostics);
        if (prepared_.request.program->diagnostics.hasErrors()) return true;
        core::TargetPathResult path =
            core::resolveTargetPath(options_.target, prepared_.store, prepared_.request.process,
                                    prepared_.request.number, &live_.state());
        report.diagnostics.append(path.diagnostics);
        if (path.syntaxError) return false;
        if (!path.ok) return true;
        path.selection.runs = options_.runs;
        path.selection.fromLastPrimary = options_.fromPrimary;
        control_.press(core::ControlKey::ProgramRestart);  // the restart screen
        core::DiagnosticList accepted;
        report.accepted = sequence_.accept(path.selection, accepted, options_.maxBlocks);
        if (!report.accepted) {
            report.diagnostics.append(accepted);
            return true;
        }
        computingProcess();
        report.computed = takeSnapshot(sequence_.computing().interpreter(), *machineData_,
                                       prepared_.request.process);
        if (options_.adjust && sequence_.phase() == core::RestartPhase::TargetReached) {
            adjustAndRepos();
            report.final = takeSnapshot(live_, *machineData_, prepared_.request.process);
        }
        report.diagnostics.append(sequence_.diagnostics());
        report.diagnostics.append(operatorNotes_);
        return true;
    }

    /// Keeps what the restart changed in the `--data` file (page 60 at the
    /// target, MTD writes of ADJUST / REPOS).
    void saveData(core::DiagnosticList& diagnostics) {
        dataKeeper_.save(*machineData_, diagnostics);
    }

  private:
    bool continueAfterStop() {
        const std::vector<core::StackLevel> levels =
            sequence_.phase() == core::RestartPhase::Computing
                ? sequence_.computing().interpreter().callStack()
                : live_.callStack();
        const core::StackLevel at = levels.empty() ? core::StackLevel{} : levels.back();
        operatorNotes_.warning("RESTART_PROGRAM_STOP", {at.program, at.block, at.line, 0},
                               "programmed stop: continued as with the Start key");
        return press(core::ControlKey::Start);
    }

    bool press(core::ControlKey key) {
        if (++actions_ > kMaxOperatorActions) return false;
        if (control_.press(key)) return true;
        if (!sequence_.active()) return false;  // the sequence failed: its diagnostic says why
        operatorNotes_.error("RESTART_KEY_REFUSED", {},
                             std::string(core::keyName(key)) + " refused: " + control_.alarm());
        return false;
    }

    void computingProcess() {
        while (true) {
            const core::RestartPhase phase = sequence_.advance(kSlice);
            if (phase != core::RestartPhase::Computing && phase != core::RestartPhase::Active)
                return;
            if (sequence_.held() && !continueAfterStop()) return;
        }
    }

    /// As the operator: Start (ADJUST), Automatic when the SPS selected
    /// manual mode, Start again (REPOS), until the re-entry.
    void adjustAndRepos() {
        if (!press(core::ControlKey::Start)) return;
        while (sequence_.active()) {
            const core::RestartPhase phase = sequence_.advance(kSlice);
            bool ok = true;
            if (sequence_.held())
                ok = continueAfterStop();
            else if (phase == core::RestartPhase::ManualMode)
                ok = press(core::ControlKey::Automatic);
            else if (phase == core::RestartPhase::AutomaticAgain)
                ok = press(core::ControlKey::Start);
            if (!ok) return;
        }
    }

    const CliOptions& options_;
    PreparedRestart& prepared_;
    RestartRecorder recorder_;
    std::shared_ptr<core::MachineDataStore> machineData_;  ///< the cell's pages, as in the panel
    MachineDataKeeper dataKeeper_;                         ///< --data FILE
    core::Interpreter live_;
    core::ProcessControl control_;
    core::SimulatedSps sps_;
    core::RestartSequence sequence_;
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
    if (options.json) {
        JsonWriter json(stdout);
        writeRestartJson(json, report);
    } else {
        printRestartText(report);
    }
    return exitCodeFor(false, report.diagnostics);
}

}  // namespace mtc::cli
