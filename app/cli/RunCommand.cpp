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
#include "cli/RunSamples.h"
#include "cli/SetupDataCommand.h"
#include "cli/StateOutput.h"
#include "cnc_core/afc/AdaptiveFeedControl.h"
#include "cnc_core/cell/Cell.h"
#include "cnc_core/machine_data/MachineDataStore.h"

namespace mtc::cli {

namespace {

/// Blocks per advance() call: the CLI has no screen to keep responsive.
constexpr std::uint64_t kCliBlocksPerAdvance = std::uint64_t{1} << 20;
/// Machine queue entries the interpreter runs ahead of the look-ahead, the
/// machine working them off in one go (MOT-022): the same results, less
/// alternation between interpreter and machine code per block. Measured in
/// CPU time on the 1,000,000-block bench (MOT-023): 56 entries take some 3 %
/// less than 8 (more simulated data cache misses, fewer instruction cache
/// misses, and the processor minds the latter more); 120 and 250 no less.
constexpr std::size_t kCliMachineBatch = 56;

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
    // The station starts a program by its number: a loose file (number 0)
    // gets a free one; its blocks keep reporting program 0.
    if (run.request.number == 0)
        run.request.number = freeProgramNumber(run.setup.programs.store, run.request.process);
    run.store = storeWith(run.setup.programs.store, run.request);
    run.diagnostics.append(run.program->diagnostics);
    return true;
}

/// The cell of the run: the machine and program memory of the command line
/// in the core's Cell (as the panel builds it), `--data` loaded into its
/// machine data.
struct RunCell {
    RunCell(PreparedRun& run, const std::string& dataFile)
        : cell(run.setup.machine), keeper(dataFile) {
        core::NcOptions nc;
        nc.globalMacros = run.setup.globalMacros;  // before the store: nothing to parse again
        cell.setNcOptions(std::move(nc));
        cell.store() = std::move(run.store);
        // The CLI prints no adaptive feed trend and no base screen: its
        // stations keep neither the trend (MOT-019) nor the block states (MOT-020).
        for (int slot = 0; slot < cell.stationCount(); ++slot) {
            cell.station(slot).keepAfcTrend(false);
            cell.station(slot).keepBlockStates(false);
        }
    }
    core::Station& station(int process) { return cell.station(cell.slotOfProcess(process)); }
    /// Loads the data file; its warnings go to `diagnostics`.
    void load(core::DiagnosticList& diagnostics) { keeper.load(cell.machineData(), diagnostics); }
    /// Saves what the program changed (MTD writes, page 30 status).
    void save(core::DiagnosticList& diagnostics) { keeper.save(cell.machineData(), diagnostics); }

    core::Cell cell;
    MachineDataKeeper keeper;
};

/// Where the station stands now (for the notes the CLI adds).
core::SourceLocation stationLocation(const core::Station& station) {
    const std::vector<core::StackLevel> levels = station.interpreter().callStack();
    const core::StackLevel at = levels.empty() ? core::StackLevel{} : levels.back();
    return {at.program, at.block, at.line, 0};
}

/// Runs the program on the station as fast as possible, exactly as the
/// panel's timer would: Start, then advance() until the station stands. M00
/// / M01 stops are continued as the operator would with the Start key
/// (noted as a warning); the station's block bound covers the whole run.
RunOutcome execute(core::Station& station, const PreparedRun& run, RunSamples& samples,
                   core::DiagnosticList& diagnostics) {
    RunOutcome outcome;
    std::size_t reported = 0;  // run diagnostics already in `diagnostics`
    const auto report = [&] {
        const auto& items = station.runDiagnostics().items();
        for (; reported < items.size(); ++reported)
            diagnostics.add(items[reported]);
    };
    // Start prepares the runtime program as on the panel (the cell's
    // ProgramCompilation; the CLI's compiler is off, so a compiler keyword
    // refuses the program): its refusal is in the station's log.
    // Samples cut the time into pieces: the machine then runs without a batch.
    if (!samples.enabled()) station.batchMachineWork(kCliMachineBatch);
    const bool selected = station.selectProgram(run.request.number);
    const std::uint64_t beforeStart = station.diagnostics().lastSerial();
    if (!selected || !station.press(core::ControlKey::Start)) {
        station.diagnostics().forEachAfter(beforeStart, [&](const core::LoggedDiagnostic& record) {
            diagnostics.add(record.diagnostic);
        });
        report();
        if (!diagnostics.hasErrors())
            diagnostics.error("RUN_START_REFUSED", {run.request.number, "", 0, 0},
                              station.control().alarm());
        outcome.status = core::RunStatus::Error;
        return outcome;
    }
    outcome.started = true;
    samples.take(station, diagnostics);
    while (station.busy()) {
        station.advance(samples.secondsToNextSample(station), kCliBlocksPerAdvance);
        report();
        samples.take(station, diagnostics);
        if (station.atProgrammedStop()) {
            diagnostics.warning("RUN_PROGRAM_STOP", stationLocation(station),
                                "programmed stop: continued as with the Start key");
            station.press(core::ControlKey::Start);
        } else if (!station.waitingAxis().empty()) {
            // Alone in the CLI nobody frees the axis: it would wait for ever.
            diagnostics.error("RUN_AXIS_WAIT", stationLocation(station),
                              "GAX waits for axis " + station.waitingAxis() +
                                  ", which no process of this run frees");
            station.press(core::ControlKey::ControlReset);
        }
    }
    report();
    samples.finish(station);
    outcome.status = station.runStatus();
    outcome.blocks = station.runBlocks();
    return outcome;
}

/// Page 30 status elements and the two signals after a run that used
/// adaptive feed control (text: one line; JSON: the "afc" object).
void writeAdaptiveFeed(core::Station& station, core::Cell& cell, JsonWriter* json) {
    if (!station.adaptiveFeed().used()) return;
    static constexpr int kElements[] = {1, 5, 7, 8, 11, 12, 14};
    static const char* const kNames[] = {"001_active",           "005_idle_torque",
                                         "007_machining_torque", "008_peak_machining_torque",
                                         "011_feed_reduction",   "012_peak_feed_reduction",
                                         "014_stall_torque"};
    const int process = station.process();
    char prefix[8];
    std::snprintf(prefix, sizeof prefix, "P%02dS", process);
    const core::SignalTable& signals = station.control().signalTable();
    const int thmis = signals.get(std::string(prefix) + "THMIS");
    const int excth = signals.get(std::string(prefix) + "EXCTH");
    double values[7] = {};
    for (int i = 0; i < 7; ++i)
        cell.machineData().read({30, process, 0, kElements[i]}, values[i]);
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

/// The figures of a run for its report.
struct RunReport {
    const MotionOutput& sink;
    const RunOutcome& outcome;
    const core::DiagnosticList& diagnostics;
    const StateView& view;
    double simulatedTime;
};

void writeJsonTail(JsonWriter& json, const RunReport& r, const RunSamples& samples) {
    if (r.sink.reportsMotion()) {
        json.key("motion_count");
        json.value(static_cast<long long>(r.sink.motionCount()));
    }
    samples.writeJson(json);
    json.key("status");
    json.value(r.diagnostics.hasErrors() ? "error" : "ok");
    writeDiagnosticsJson(json, r.diagnostics);
    json.key("run_status");
    json.value(runStatusText(r.outcome));
    json.key("blocks_interpreted");
    json.value(static_cast<long long>(r.outcome.blocks));
    json.key("simulated_time");
    json.value(r.simulatedTime);
    json.key("final");
    writeStateJson(json, r.view);
}

void writeTextTail(const RunReport& r, const RunSamples& samples) {
    std::fflush(stdout);
    samples.printText(stdout);
    printDiagnosticsText(stdout, r.diagnostics);
    std::string motions;
    if (r.sink.reportsMotion()) motions = ", " + std::to_string(r.sink.motionCount()) + " motions";
    std::printf("run: %s after %llu blocks%s, simulated time %.3f s\n", runStatusText(r.outcome),
                static_cast<unsigned long long>(r.outcome.blocks), motions.c_str(),
                r.simulatedTime);
    printStateText(stdout, r.view);
}

/// Writes everything after the motion list: the JSON tail (when `json` is
/// given) or the text summary, with the final state of the station.
void writeReport(RunCell& cell, core::Station& station, const MotionOutput& sink,
                 const RunOutcome& outcome, const core::DiagnosticList& diagnostics,
                 const RunSamples& samples, JsonWriter* json) {
    core::Interpreter& interpreter = station.interpreter();
    const Page61Buffers page61 = readPage61(interpreter.machineData(), station.process());
    const std::vector<double> positions = programmedPositions(interpreter);
    const std::vector<std::string> names = reportedAxisNames(interpreter);
    const std::vector<double> axisPositions = compensatedAxisPositions(interpreter);
    const StateView view{interpreter.state(), station.config(), interpreter.axes(), page61, names,
                         positions,           &axisPositions};
    // The machine's time; without motion the machine does not move and the
    // interpreter's own count of the programmed time is all there is.
    const double time = sink.reportsMotion() || station.machine().seconds() > 0
                            ? station.machine().seconds()
                            : interpreter.state().modal.time;
    const RunReport report{sink, outcome, diagnostics, view, time};
    if (json != nullptr) {
        writeJsonTail(*json, report, samples);
        writeAdaptiveFeed(station, cell.cell, json);
        json->endObject();
        json->finish();
    } else {
        writeTextTail(report, samples);
        writeAdaptiveFeed(station, cell.cell, nullptr);
        std::printf("status: %s\n", diagnostics.hasErrors() ? "error" : "ok");
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
    // Tool list and zero offsets: beside the --data file when one is given.
    std::optional<core::SetupData> setup;
    if (!loadRunSetupData(run.setup.machine, options.machineData.dataFile, setup, failure))
        return reportSetupFailure(failure, options.json);
    cell.cell.setupData().adopt(*setup);
    core::Station& station = cell.station(run.request.process);
    diagnostics.append(station.adaptiveFeed().parameterDiagnostics());
    core::Interpreter& interpreter = station.interpreter();
    if (interpreter.configurationDiagnostics().hasErrors()) {
        failure.error(
            "CLI_MACHINE_INVALID", {},
            "the machine configuration cannot run process " + std::to_string(run.request.process));
        failure.append(interpreter.configurationDiagnostics());
        return reportSetupFailure(failure, options.json);
    }
    sink.setAxisNames(reportedAxisNames(interpreter));
    sink.attachAdaptiveFeed(&station.machine(), &station.adaptiveFeed());
    station.setOutputListener(&sink);
    station.setBlockBudget(options.maxBlocks);
    // --no-motion changes the output only. Without adaptive feed control the
    // machine has no effect on the run, so the interpreter need not even
    // build the moves (about 10 % of a run of plain moves); with it, the
    // moves must reach the machine (G26 slows them, ITM measures, 508..510).
    interpreter.options().output.motion = !options.noMotion || station.adaptiveFeed().available();
    RunSamples samples(options.sampleMs, reportedAxisNames(interpreter));
    if (options.json) json.beginObject();
    if (mode == MotionMode::Json) {
        json.key("motion");
        json.beginArray();
    }
    RunOutcome outcome;
    if (!run.program->diagnostics.hasErrors())
        outcome = execute(station, run, samples, diagnostics);
    if (mode == MotionMode::Json) json.endArray();
    station.setOutputListener(nullptr);
    reportChangedFile(run.request.program, diagnostics);

    cell.save(diagnostics);
    writeReport(cell, station, sink, outcome, diagnostics, samples, options.json ? &json : nullptr);
    return exitCodeFor(false, diagnostics);
}

}  // namespace mtc::cli
