#include "cli/VerifyRestartCommand.h"

#include "cli/SetupDataCommand.h"

#include <cstdio>
#include <optional>
#include <string>

#include "cli/CliOutput.h"
#include "cli/CommandSetup.h"
#include "cli/JsonWriter.h"
#include "cli/MachineSetup.h"
#include "cli/ProgramMemory.h"
#include "cli/SetupDataCommand.h"
#include "cnc_core/restart/RestartVerifier.h"

namespace mtc::cli {

namespace {

/// Arrivals per advance(): the CLI has no screen to keep responsive.
constexpr std::uint64_t kArrivalsPerSlice = std::uint64_t{1} << 40;

const char* outcomeName(core::TargetOutcome outcome) {
    switch (outcome) {
        case core::TargetOutcome::Reestablished:
            return "reestablished";
        case core::TargetOutcome::Differs:
            return "differs";
        case core::TargetOutcome::Failed:
            return "failed";
        case core::TargetOutcome::NotSelectable:
            return "not_selectable";
    }
    return "failed";
}

std::string blockName(const core::VerifiedTarget& t) {
    return t.where.block.empty() ? "line " + std::to_string(t.where.line) : t.where.block;
}

void writeValue(JsonWriter& json, const char* key, const core::StateDifference& d, bool expected) {
    json.key(key);
    if (d.numeric)
        json.value(expected ? d.expected : d.actual);
    else
        json.value(expected ? d.expectedText : d.actualText);
}

void writeDifferences(JsonWriter& json, const core::VerifyReport& report) {
    json.key("differences");
    json.beginArray();
    for (const core::VerifiedTarget& t : report.problems)
        for (const auto* list : {&t.computed, &t.cutting})
            for (const core::StateDifference& d : *list) {
                json.beginObject();
                json.field("target", blockName(t));
                json.field("program", t.selection.target.program);
                json.field("line", t.where.line);
                json.field("pass", t.selection.runs);
                json.field("scope", list == &t.computed ? "computed" : "adjust");
                json.field("what", d.what);
                json.field("label", d.label);
                writeValue(json, "expected", d, true);
                writeValue(json, "actual", d, false);
                json.endObject();
            }
    json.endArray();
}

void writeFailures(JsonWriter& json, const core::VerifyReport& report) {
    json.key("failures");
    json.beginArray();
    for (const core::VerifiedTarget& t : report.problems) {
        if (t.outcome != core::TargetOutcome::Failed &&
            t.outcome != core::TargetOutcome::NotSelectable)
            continue;
        json.beginObject();
        json.field("target", blockName(t));
        json.field("program", t.selection.target.program);
        json.field("line", t.where.line);
        json.field("pass", t.selection.runs);
        json.field("outcome", outcomeName(t.outcome));
        writeDiagnosticsJson(json, t.diagnostics);
        json.endObject();
    }
    json.endArray();
}

bool passed(const core::VerifyReport& report) {
    return report.complete && report.targets == report.reestablished &&
           !report.diagnostics.hasErrors();
}

void writeJson(const core::VerifyReport& report, const CliOptions& options, int program) {
    JsonWriter json(stdout);
    beginStatusDocument(json, passed(report) ? "ok" : "error");
    json.field("program", program);
    json.field("adjust", options.adjust);
    json.field("max_passes", options.maxPasses);
    json.field("targets", report.targets);
    json.field("reestablished", report.reestablished);
    json.field("arrivals", report.arrivals);
    json.field("not_selectable", report.notSelectable);
    json.field("beyond_passes", report.beyondPasses);
    json.field("complete", report.complete);
    json.field("coverage", report.coverageLine());
    writeDifferences(json, report);
    writeFailures(json, report);
    endDocumentWithDiagnostics(json, report.diagnostics);
}

void printText(const core::VerifyReport& report) {
    for (const core::VerifiedTarget& t : report.problems) {
        const std::string name = "P" + std::to_string(t.selection.target.program) + " " +
                                 blockName(t) + " pass " + std::to_string(t.selection.runs);
        for (const auto* list : {&t.computed, &t.cutting})
            for (const core::StateDifference& d : *list)
                std::printf("%s %s: %s expected %s, got %s\n", name.c_str(),
                            list == &t.computed ? "computing process" : "after REPOS",
                            d.label.c_str(), d.expectedText.c_str(), d.actualText.c_str());
        if (t.outcome == core::TargetOutcome::Failed ||
            t.outcome == core::TargetOutcome::NotSelectable) {
            std::printf(
                "%s %s:\n", name.c_str(),
                t.outcome == core::TargetOutcome::Failed ? "restart failed" : "not a target");
            printDiagnosticsText(stdout, t.diagnostics);
        }
    }
    printDiagnosticsText(stdout, report.diagnostics);
    std::printf("verify-restart: %s\n", report.coverageLine().c_str());
    std::printf("status: %s\n", passed(report) ? "ok" : "error");
}

}  // namespace

int runVerifyRestartCommand(const CliOptions& options) {
    core::DiagnosticList failure;
    std::optional<CommandSetup> setup = prepareCommand(options, failure);
    if (!setup) return reportSetupFailure(failure, options.json);
    ProgramRequest request;
    if (!resolveProgram(options.arguments.front(), setup->programs, options.process,
                        options.processGiven, request, failure))
        return reportSetupFailure(failure, options.json);
    if (!setup->machine.process(request.process)) {
        checkProcessExists(setup->machine, request.process, failure);
        return reportSetupFailure(failure, options.json);
    }
    const core::ProgramStore store = storeWith(setup->programs.store, request);
    // The tool lists and zero offsets a `run` of the same program would use.
    std::optional<core::SetupData> setupData;
    if (!loadRunSetupData(setup->machine, options.machineData.dataFile, setupData, failure))
        return reportSetupFailure(failure, options.json);
    core::VerifyOptions verify;
    verify.tools = setupData->tools(request.process);
    verify.zeroOffsets = setupData->offsets(request.process);
    verify.adjust = options.adjust;
    verify.maxPasses = options.maxPasses;
    verify.budget = options.maxBlocks;
    core::RestartVerifier verifier(setup->machine, request.process, store, verify);
    core::DiagnosticList diagnostics = request.program->diagnostics;
    if (!diagnostics.hasErrors() && verifier.begin(request.number, diagnostics))
        verifier.advance(kArrivalsPerSlice);
    core::VerifyReport report = verifier.report();
    report.diagnostics.append(diagnostics);
    reportChangedFile(request.program, report.diagnostics);
    if (options.json)
        writeJson(report, options, request.number);
    else
        printText(report);
    return passed(report) ? 0 : 1;
}

}  // namespace mtc::cli
