#include "cli/CheckCommand.h"

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "cli/CliOutput.h"
#include "cli/CommandSetup.h"
#include "cli/JsonWriter.h"
#include "cli/ProgramMemory.h"
#include "cnc_core/compiler/ProgramCheck.h"
#include "cnc_core/program/ProgramStore.h"

namespace mtc::cli {

namespace {

/// What `check` found for one program argument.
struct CheckedProgram {
    std::string argument;
    std::string name;
    int process = 0;
    int number = 0;
    bool found = false;
    std::size_t blocks = 0;
    std::size_t errors = 0;
    std::size_t warnings = 0;
};

void countSeverities(const core::DiagnosticList& diagnostics, CheckedProgram& checked) {
    for (const core::Diagnostic& d : diagnostics.items())
        (d.severity == core::Severity::Error ? checked.errors : checked.warnings) += 1;
}

/// The options of the compiler a check asks (the process's axes and
/// parameters, the global macros of the program directory).
core::CompilerOptions checkOptions(const CommandSetup& setup, const ProgramRequest& request) {
    core::CompilerOptions options;
    options.compilerActive = true;
    options.process = setup.machine.process(request.process);
    options.programNumber = request.number;
    options.programName = request.displayName;
    options.globalMacros = setup.globalMacros;
    return options;
}

CheckedProgram checkOne(const std::string& argument, const CommandSetup& setup,
                        const CliOptions& options, core::DiagnosticList& all) {
    CheckedProgram checked;
    checked.argument = argument;
    core::DiagnosticList found;
    ProgramRequest request;
    if (!resolveProgram(argument, setup.programs, options.process, options.processGiven, request,
                        found)) {
        all.append(found);
        checked.errors = 1;
        return checked;
    }
    checked.found = true;
    checked.name = request.displayName;
    checked.process = request.process;
    checked.number = request.number;
    const core::ProgramStore store = storeWith(setup.programs.store, request);
    const core::ProgramPtr& program = request.program;
    checked.blocks = program->blocks.size();
    found.append(core::checkProgram(*program, checkOptions(setup, request)));
    found.append(checkProgramReferences(*program, store, request.process));
    reportChangedFile(program, found);
    countSeverities(found, checked);
    all.append(found);
    return checked;
}

void writeJson(const std::vector<CheckedProgram>& checked, const core::DiagnosticList& all) {
    JsonWriter json(stdout);
    beginStatusDocument(json, all.hasErrors() ? "error" : "ok");
    writeDiagnosticsJson(json, all);
    json.key("programs");
    json.beginArray();
    for (const CheckedProgram& c : checked) {
        json.beginObject();
        json.field("argument", c.argument);
        json.field("name", c.name);
        json.field("found", c.found);
        json.field("process", c.process);
        json.field("program", c.number);
        json.field("blocks", c.blocks);
        json.field("errors", c.errors);
        json.field("warnings", c.warnings);
        json.endObject();
    }
    json.endArray();
    json.endObject();
    json.finish();
}

void writeText(const std::vector<CheckedProgram>& checked, const core::DiagnosticList& all) {
    printDiagnosticsText(stdout, all);
    for (const CheckedProgram& c : checked) {
        if (!c.found) {
            std::printf("%s: not checked (cannot be read)\n", c.argument.c_str());
            continue;
        }
        std::printf("%s: program %d, process %d, %zu blocks, %zu error(s), %zu warning(s)\n",
                    c.name.c_str(), c.number, c.process, c.blocks, c.errors, c.warnings);
    }
    std::printf("check: %s\n", all.hasErrors() ? "errors found" : "ok");
}

}  // namespace

int runCheckCommand(const CliOptions& options) {
    core::DiagnosticList setupDiagnostics;
    std::optional<CommandSetup> setup = prepareCommand(options, setupDiagnostics);
    if (!setup) return reportSetupFailure(setupDiagnostics, options.json);
    core::DiagnosticList all = setupDiagnostics;
    std::vector<CheckedProgram> checked;
    bool fileProblem = false;
    for (const std::string& argument : options.arguments) {
        checked.push_back(checkOne(argument, *setup, options, all));
        fileProblem = fileProblem || !checked.back().found;
    }
    if (options.json) {
        writeJson(checked, all);
    } else {
        writeText(checked, all);
    }
    return exitCodeFor(fileProblem, all);
}

}  // namespace mtc::cli
