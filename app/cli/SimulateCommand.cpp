#include "cli/SimulateCommand.h"

#include <cstdio>
#include <optional>
#include <string>

#include "cli/CliOutput.h"
#include "cli/CommandSetup.h"
#include "cli/JsonWriter.h"
#include "cli/MachineSetup.h"
#include "cli/ProgramMemory.h"
#include "cli/SetupDataCommand.h"
#include "cnc_core/removal/PartStl.h"
#include "cnc_core/removal/RemovalRun.h"

namespace mtc::cli {

namespace {

/// What the command did, for its report.
struct SimulateReport {
    ProgramRequest request;
    core::removal::RemovalRunResult run;
    core::DiagnosticList diagnostics;  ///< preparation, parse and run, in order
    std::string stl;                   ///< the file written ("" = none)
    std::uint64_t triangles = 0;
    double resolution = 0.0;
};

const char* modelName(const core::removal::PartModel& part) {
    return part.heightField() != nullptr ? "height_field" : "turned_profile";
}

void writeJson(const SimulateReport& r) {
    JsonWriter json(stdout);
    beginStatusDocument(json, r.diagnostics.hasErrors() ? "error" : "ok");
    json.field("program", r.request.program->number);
    json.field("process", r.request.process);
    json.field("resolution", r.resolution);
    const core::removal::PartModel& part = *r.run.part;
    json.key("stock");
    json.beginObject();
    const core::removal::StockOrigin& stock = r.run.stock;
    json.field("source", stock.fromWindow ? "window" : "configuration");
    if (stock.fromWindow) {
        json.field("keyword", stock.keyword);
        json.field("program", stock.where.program);
        json.field("block", stock.where.block);
        json.field("line", stock.where.line);
        json.field("zero_offset", "G" + std::to_string(stock.zeroOffset));
        if (stock.rawContour != 0) {  // the blank inside the window (TP-021)
            json.field("raw_contour", stock.rawContour);
            json.field("raw_line", static_cast<long long>(stock.rawLine));
        }
    }
    json.endObject();
    json.field("model", modelName(part));
    json.field("cells", static_cast<long long>(part.cells()));
    json.field("stock_volume", part.blankVolume());
    json.field("removed_volume", part.removedVolume());
    // The jacket of the G32 cuts (D-027): its cells and what it took away.
    const core::removal::DevelopedSurface* jacket = part.jacket();
    json.field("developed_cells", jacket != nullptr
                                      ? static_cast<long long>(jacket->columns()) * jacket->rows()
                                      : 0LL);
    json.field("developed_volume", part.developedVolume());
    json.field("blocks_interpreted", static_cast<long long>(r.run.blocks));
    json.field("complete", r.run.complete);
    json.field("moves", static_cast<long long>(r.run.counts.moves));
    json.field("cutting_moves", static_cast<long long>(r.run.counts.cuttingMoves));
    json.field("rapid_cuts", static_cast<long long>(r.run.counts.rapidCuts));
    json.key("stl");
    if (r.stl.empty())
        json.null();
    else
        json.value(r.stl);
    json.field("triangles", static_cast<long long>(r.triangles));
    endDocumentWithDiagnostics(json, r.diagnostics);
}

void writeText(const SimulateReport& r) {
    printDiagnosticsText(stdout, r.diagnostics);
    const core::removal::PartModel& part = *r.run.part;
    std::printf("simulate: %s, process %d, %s at %g mm (%llu cells), %llu blocks%s\n",
                r.request.displayName.c_str(), r.request.process,
                part.heightField() != nullptr ? "height field" : "turned profile", r.resolution,
                static_cast<unsigned long long>(part.cells()),
                static_cast<unsigned long long>(r.run.blocks),
                r.run.complete ? "" : " (program end not reached)");
    if (r.run.stock.fromWindow)
        std::printf("stock: %s of P%d %s (line %d) in G%d\n", r.run.stock.keyword.c_str(),
                    r.run.stock.where.program, r.run.stock.where.block.c_str(),
                    r.run.stock.where.line, r.run.stock.zeroOffset);
    if (r.run.stock.rawContour != 0)
        std::printf("blank: RAW contour %d (line %u)\n", r.run.stock.rawContour,
                    r.run.stock.rawLine);
    if (!r.run.stock.fromWindow) std::printf("stock: machine configuration\n");
    std::printf("removed volume: %.3f mm3 of %.3f mm3 stock; %llu of %llu moves cut, %llu rapid\n",
                part.removedVolume(), part.blankVolume(),
                static_cast<unsigned long long>(r.run.counts.cuttingMoves),
                static_cast<unsigned long long>(r.run.counts.moves),
                static_cast<unsigned long long>(r.run.counts.rapidCuts));
    if (const core::removal::DevelopedSurface* jacket = part.jacket())
        std::printf("developed surface: %d x %d cells, %.3f mm3 of it cut under G32\n",
                    jacket->columns(), jacket->rows(), part.developedVolume());
    if (r.stl.empty())
        std::printf("stl: none written\n");
    else
        std::printf("stl: %s (%llu triangles)\n", r.stl.c_str(),
                    static_cast<unsigned long long>(r.triangles));
    std::printf("status: %s\n", r.diagnostics.hasErrors() ? "error" : "ok");
}

/// Machine, programs and the requested program; false (diagnostics in
/// `failure`) on a file or configuration problem.
bool prepare(const CliOptions& options, CommandSetup& setup, SimulateReport& report,
             core::ProgramStore& store, core::DiagnosticList& failure) {
    std::optional<CommandSetup> loaded = prepareCommand(options, failure);
    if (!loaded) return false;
    setup = std::move(*loaded);
    report.diagnostics.append(failure);  // warnings of the machine file
    failure.clear();
    if (!resolveProgram(options.arguments.front(), setup.programs, options.process,
                        options.processGiven, report.request, failure))
        return false;
    if (setup.machine.process(report.request.process) == nullptr) {
        checkProcessExists(setup.machine, report.request.process, failure);
        return false;
    }
    if (report.request.number == 0)  // a loose file: a free number, as run gives it
        report.request.number = freeProgramNumber(setup.programs.store, report.request.process);
    store = storeWith(setup.programs.store, report.request);
    report.diagnostics.append(report.request.program->diagnostics);
    return true;
}

}  // namespace

int runSimulateCommand(const CliOptions& options) {
    CommandSetup setup;
    SimulateReport report;
    core::ProgramStore store;
    core::DiagnosticList failure;
    if (!prepare(options, setup, report, store, failure))
        return reportSetupFailure(failure, options.json);
    std::optional<core::SetupData> tools;  // the tool list beside --data, as run reads it
    if (!loadRunSetupData(setup.machine, options.machineData.dataFile, tools, failure))
        return reportSetupFailure(failure, options.json);
    core::removal::RemovalSettings settings;
    settings.resolution = options.resolution;
    report.resolution = options.resolution;
    const core::ProcessConfig& process = *setup.machine.process(report.request.process);
    report.run =
        core::removal::simulateRemoval(process, store, report.request.number, settings,
                                       tools->tools(report.request.process), options.maxBlocks);
    if (!report.run.part) {  // no stock, or too many cells: the request cannot be served
        failure.append(report.run.diagnostics);
        return reportSetupFailure(failure, options.json);
    }
    report.diagnostics.append(report.run.diagnostics);
    if (!report.run.complete && !report.diagnostics.hasErrors())
        report.diagnostics.error("SIMULATE_INCOMPLETE", {report.request.program->number, "", 0, 0},
                                 "the program did not reach its end within --max-blocks " +
                                     std::to_string(options.maxBlocks));
    if (!options.stlPath.empty() && !report.diagnostics.hasErrors()) {
        std::string error;
        if (!core::removal::writePartStl(*report.run.part, options.stlPath, error)) {
            report.diagnostics.error("CLI_FILE_UNWRITABLE", {}, error);
            return reportSetupFailure(report.diagnostics, options.json);
        }
        report.stl = options.stlPath;
        report.triangles = core::removal::stlTriangleCount(*report.run.part);
    } else if (!options.stlPath.empty()) {
        report.diagnostics.warning("SIMULATE_NO_STL", {report.request.program->number, "", 0, 0},
                                   "no STL written: the program has errors");
    }
    reportChangedFile(report.request.program, report.diagnostics);
    if (options.json)
        writeJson(report);
    else
        writeText(report);
    return exitCodeFor(false, report.diagnostics);
}

}  // namespace mtc::cli
