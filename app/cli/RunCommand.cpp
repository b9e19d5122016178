#include "cli/RunCommand.h"

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "cli/CliOutput.h"
#include "cli/CommandSetup.h"
#include "cli/JsonWriter.h"
#include "cli/MachineDataKeeper.h"
#include "cli/MachineSetup.h"
#include "cli/MotionOutput.h"
#include "cli/ProgramMemory.h"
#include "cli/SetupDataCommand.h"
#include "cli/StateOutput.h"
#include "cnc_core/afc/AdaptiveFeedControl.h"
#include "cnc_core/afc/AfcMotion.h"
#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/language/CompilerWords.h"
#include "cnc_core/machine/SimulatedMachine.h"
#include "cnc_core/machine_data/MachineDataFile.h"
#include "cnc_core/machine_data/MachineDataStore.h"

namespace mtc::cli {

namespace {

/// Everything a run needs once the files are read.
struct PreparedRun {
    CommandSetup setup;
    ProgramRequest request;
    const core::ProcessConfig* process = nullptr;
    core::ProgramStore store;
    core::ProgramPtr program;
    core::DiagnosticList diagnostics;  ///< warnings of the preparation, parse problems
};

/// What the run produced besides the streamed motion.
struct RunOutcome {
    core::RunStatus status = core::RunStatus::Ended;
    std::uint64_t blocks = 0;
    bool started = false;
};

/// Reads machine, program directory and program; false (diagnostics in
/// `failure`) on a file or configuration problem (exit 2).
bool prepareRun(const CliOptions& options, PreparedRun& run, core::DiagnosticList& failure) {
    std::optional<CommandSetup> setup = prepareCommand(options, failure);
    if (!setup) return false;
    run.setup = std::move(*setup);
    run.diagnostics.append(failure);  // warnings of the machine file
    failure.clear();
    if (!resolveProgram(options.arguments.front(), run.setup.programs, options.process,
                        options.processGiven, run.request, failure))
        return false;
    run.process = run.setup.machine.process(run.request.process);
    if (run.process == nullptr) {
        checkProcessExists(run.setup.machine, run.request.process, failure);
        return false;
    }
    run.program = run.request.program;
    run.store = storeWith(run.setup.programs.store, run.request);
    run.diagnostics.append(run.program->diagnostics);
    return true;
}

/// Runs the program to its end. M00 / M01 stops are continued as the
/// operator would with the Start key (noted as a warning); the block bound
/// covers the whole run.
RunOutcome execute(core::Interpreter& interpreter, const PreparedRun& run, std::uint64_t budget,
                   core::DiagnosticList& diagnostics) {
    RunOutcome outcome;
    core::Diagnostic keyword;  // the CLI runs sources: the compiler is off
    if (core::findCompilerWord(*run.program, keyword)) {
        diagnostics.add(std::move(keyword));
        outcome.status = core::RunStatus::Error;
        return outcome;
    }
    if (!interpreter.select(run.program, 0, &diagnostics)) {
        outcome.status = core::RunStatus::Error;
        return outcome;
    }
    outcome.started = true;
    while (true) {
        core::RunResult result = interpreter.run(budget - outcome.blocks);
        outcome.blocks += result.blocksInterpreted;
        diagnostics.append(result.diagnostics);
        outcome.status = result.status;
        if (result.status != core::RunStatus::Stopped) return outcome;
        const std::vector<core::StackLevel> levels = interpreter.callStack();
        const core::StackLevel where = levels.empty() ? core::StackLevel{} : levels.back();
        diagnostics.warning("RUN_PROGRAM_STOP", {where.program, where.block, where.line, 0},
                            "programmed stop: continued as with the Start key");
        if (outcome.blocks >= budget) {
            diagnostics.error("BLOCK_BUDGET", {where.program, where.block, where.line, 0},
                              "the run exceeded --max-blocks " + std::to_string(budget));
            outcome.status = core::RunStatus::BudgetExceeded;
            return outcome;
        }
    }
}

/// The cell's machine data (`--data FILE` loaded when given) and the
/// adaptive feed control of the process on a simulated machine.
struct RunCell {
    RunCell(const PreparedRun& run, const std::string& dataFile)
        : data(std::make_shared<core::MachineDataStore>(run.setup.machine)),
          keeper(dataFile),
          machine(*run.process) {}

    /// Loads the data file; its warnings go to `diagnostics`.
    void load(core::DiagnosticList& diagnostics) { keeper.load(*data, diagnostics); }
    /// Saves what the program changed (MTD writes, page 30 status).
    void save(core::DiagnosticList& diagnostics) { keeper.save(*data, diagnostics); }

    std::shared_ptr<core::MachineDataStore> data;
    MachineDataKeeper keeper;
    core::SimulatedMachine machine;
    core::SignalTable signals;
    std::shared_ptr<core::AdaptiveFeedControl> afc;
};

/// Page 30 status elements and the two signals after a run that used
/// adaptive feed control (text: one line; JSON: the "afc" object).
void writeAdaptiveFeed(const RunCell& cell, int process, JsonWriter* json) {
    if (!cell.afc || !cell.afc->used()) return;
    static constexpr int kElements[] = {1, 5, 7, 8, 11, 12, 14};
    static const char* const kNames[] = {"001_active",           "005_idle_torque",
                                         "007_machining_torque", "008_peak_machining_torque",
                                         "011_feed_reduction",   "012_peak_feed_reduction",
                                         "014_stall_torque"};
    char prefix[8];
    std::snprintf(prefix, sizeof prefix, "P%02dS", process);
    const int thmis = cell.signals.get(std::string(prefix) + "THMIS");
    const int excth = cell.signals.get(std::string(prefix) + "EXCTH");
    double values[7] = {};
    for (int i = 0; i < 7; ++i)
        cell.data->read({30, process, 0, kElements[i]}, values[i]);
    if (json) {
        json->key("afc");
        json->beginObject();
        for (int i = 0; i < 7; ++i) {
            json->key(kNames[i]);
            json->value(values[i]);
        }
        json->key("THMIS");
        json->value(thmis);
        json->key("EXCTH");
        json->value(excth);
        json->endObject();
        return;
    }
    std::printf(
        "afc: page 30 001=%g 005=%.1f 007=%.1f 008=%.1f 011=%.1f 012=%.1f 014=%.1f %%; "
        "%sTHMIS=%d %sEXCTH=%d\n",
        values[0], values[1], values[2], values[3], values[4], values[5], values[6], prefix, thmis,
        prefix, excth);
}

/// How the run ended: the interpreter's word, or "not_started" when the
/// program could not be started (parse errors, selection refused).
const char* runStatusText(const RunOutcome& outcome) {
    return outcome.started ? core::runStatusName(outcome.status) : "not_started";
}

void writeJsonTail(JsonWriter& json, const MotionOutput& sink, const RunOutcome& outcome,
                   const core::DiagnosticList& diagnostics, const StateView& view,
                   const RunCell& cell) {
    if (sink.reportsMotion()) {
        json.key("motion_count");
        json.value(static_cast<long long>(sink.motionCount()));
    }
    json.key("status");
    json.value(diagnostics.hasErrors() ? "error" : "ok");
    writeDiagnosticsJson(json, diagnostics);
    json.key("run_status");
    json.value(runStatusText(outcome));
    json.key("blocks_interpreted");
    json.value(static_cast<long long>(outcome.blocks));
    json.key("simulated_time");
    json.value(view.state.modal.time);
    json.key("final");
    writeStateJson(json, view);
    writeAdaptiveFeed(cell, view.process.index, &json);
    json.endObject();
    json.finish();
}

void writeTextTail(const MotionOutput& sink, const RunOutcome& outcome,
                   const core::DiagnosticList& diagnostics, const StateView& view,
                   const RunCell& cell) {
    std::fflush(stdout);
    printDiagnosticsText(stdout, diagnostics);
    std::string motions;
    if (sink.reportsMotion()) motions = ", " + std::to_string(sink.motionCount()) + " motions";
    std::printf("run: %s after %llu blocks%s, simulated time %.3f s\n", runStatusText(outcome),
                static_cast<unsigned long long>(outcome.blocks), motions.c_str(),
                view.state.modal.time);
    printStateText(stdout, view);
    writeAdaptiveFeed(cell, view.process.index, nullptr);
    std::printf("status: %s\n", diagnostics.hasErrors() ? "error" : "ok");
}

/// Writes everything after the motion list: the JSON tail (when `json` is
/// given) or the text summary, with the final state of `interpreter`.
void writeReport(core::Interpreter& interpreter, const PreparedRun& run, const MotionOutput& sink,
                 const RunOutcome& outcome, const core::DiagnosticList& diagnostics,
                 JsonWriter* json, const RunCell& cell) {
    const Page61Buffers page61 = readPage61(interpreter.machineData(), run.request.process);
    const std::vector<double> positions = programmedPositions(interpreter);
    const std::vector<std::string> names = reportedAxisNames(interpreter);
    const StateView view{
        interpreter.state(), *run.process, interpreter.axes(), page61, names, positions};
    if (json != nullptr) {
        writeJsonTail(*json, sink, outcome, diagnostics, view, cell);
    } else {
        writeTextTail(sink, outcome, diagnostics, view, cell);
    }
}

}  // namespace

int runRunCommand(const CliOptions& options) {
    PreparedRun run;
    core::DiagnosticList failure;
    if (!prepareRun(options, run, failure)) return reportSetupFailure(failure, options.json);

    JsonWriter json(stdout);
    const MotionMode mode = options.noMotion ? MotionMode::None
                            : options.json   ? MotionMode::Json
                                             : MotionMode::Text;
    MotionOutput sink(mode, &json, stdout);
    RunCell cell(run, options.machineData.dataFile);
    core::DiagnosticList diagnostics = run.diagnostics;
    cell.load(diagnostics);
    core::InterpreterServices services;
    services.machineData = cell.data;
    // The process runs alone: a GAX is granted at once, a FAX releases the
    // axis until the next GAX, a move of a released axis is an error.
    core::AxisTransfer axisOwnership;
    services.axisTransfer = &axisOwnership;
    // Tool list and zero offsets: beside the --data file when one is given.
    std::optional<core::SetupData> setup;
    if (!loadRunSetupData(run.setup.machine, options.machineData.dataFile, setup, failure))
        return reportSetupFailure(failure, options.json);
    services.tools = setup->tools(run.request.process);
    services.zeroOffsets = setup->offsets(run.request.process);
    core::Interpreter interpreter(*run.process, run.store, sink, services);
    cell.afc = std::make_shared<core::AdaptiveFeedControl>(
        *run.process, *cell.data, core::torqueModelFromConfig(*run.process), &cell.signals);
    diagnostics.append(cell.afc->parameterDiagnostics());
    interpreter.setAdaptiveFeed(cell.afc);
    cell.machine.attachAdaptiveFeed(cell.afc.get(), nullptr);
    sink.attachAdaptiveFeed(&cell.machine, cell.afc.get());
    if (interpreter.configurationDiagnostics().hasErrors()) {
        failure.error(
            "CLI_MACHINE_INVALID", {},
            "the machine configuration cannot run process " + std::to_string(run.request.process));
        failure.append(interpreter.configurationDiagnostics());
        return reportSetupFailure(failure, options.json);
    }
    sink.setAxisNames(reportedAxisNames(interpreter));
    // --no-motion changes the output only. Without adaptive feed control the
    // machine has no effect on the run, so the interpreter need not even
    // build the moves (about 10 % of a run of plain moves); with it, the
    // moves must reach the machine (G26 slows them, ITM measures, 508..510).
    interpreter.options().output.motion = !options.noMotion || cell.afc->available();
    if (options.json) json.beginObject();
    if (mode == MotionMode::Json) {
        json.key("motion");
        json.beginArray();
    }
    RunOutcome outcome;
    if (!run.program->diagnostics.hasErrors())
        outcome = execute(interpreter, run, options.maxBlocks, diagnostics);
    if (mode == MotionMode::Json) json.endArray();

    cell.save(diagnostics);
    writeReport(interpreter, run, sink, outcome, diagnostics, options.json ? &json : nullptr, cell);
    return exitCodeFor(false, diagnostics);
}

}  // namespace mtc::cli
