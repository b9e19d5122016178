#include "cli/CompileCommand.h"

#include <cstdio>
#include <optional>

#include "cli/CliOutput.h"
#include "cli/CommandSetup.h"
#include "cli/JsonWriter.h"
#include "cli/ProgramMemory.h"
#include "cnc_core/compiler/Compiler.h"
#include "cnc_core/compiler/CompilerFiles.h"
#include "cnc_core/compiler/CompilerText.h"
#include "cnc_core/compiler/ProgramCheck.h"
#include "cnc_core/compiler/UserCompilers.h"

namespace mtc::cli {

namespace {

struct CompileOutcome {
    core::CompileResult result;
    std::string objectPath;
    std::string errorPath;
    std::size_t intermediateBlocks = 0;
};

bool isDigits(const std::string& text) {
    if (text.empty() || text.size() > 3) return false;
    for (char c : text)
        if (c < '0' || c > '9') return false;
    return true;
}

/// Where the source lives: the argument itself, or the file in --programs
/// DIR, or (built-in demo programs) the current directory.
std::string sourcePathOf(const CliOptions& options, const ProgramRequest& request) {
    if (!isDigits(request.argument)) return request.argument;
    if (!options.programsDir.empty()) return options.programsDir + "/" + request.displayName;
    return request.displayName.empty() ? "program.DAT" : request.displayName;
}

void writeJson(const CompileOutcome& outcome, const core::DiagnosticList& diagnostics) {
    JsonWriter json(stdout);
    json.beginObject();
    json.key("status");
    json.value(diagnostics.hasErrors() ? "error" : "ok");
    writeDiagnosticsJson(json, diagnostics);
    json.key("compile_status");
    json.value(std::string(1, core::statusLetter(outcome.result.status)));
    json.key("object_file");
    json.value(outcome.result.status == core::CompileStatus::Compiled ? outcome.objectPath : "");
    json.key("error_file");
    json.value(outcome.errorPath);
    json.key("blocks");
    json.value(outcome.result.objectBlocks);
    json.key("intermediate_blocks");
    json.value(outcome.intermediateBlocks);
    json.key("object_lines");
    json.value(outcome.result.lineMap.size());
    json.endObject();
    json.finish();
}

void writeText(const CompileOutcome& outcome, const core::DiagnosticList& diagnostics) {
    printDiagnosticsText(stdout, diagnostics);
    if (outcome.result.status == core::CompileStatus::Compiled)
        std::printf("compile: ok, %zu blocks (%zu inserted) -> %s\n", outcome.result.objectBlocks,
                    outcome.intermediateBlocks, outcome.objectPath.c_str());
    else
        std::printf("compile: errors found -> %s\n", outcome.errorPath.c_str());
    if (outcome.result.status == core::CompileStatus::Compiled && !outcome.errorPath.empty())
        std::printf("compile: warnings -> %s\n", outcome.errorPath.c_str());
}

}  // namespace

int runCompileCommand(const CliOptions& options) {
    if (options.arguments.size() != 1)
        return reportUsageError("compile takes exactly one program (FILE.DAT or number)",
                                options.json);
    core::DiagnosticList diagnostics;
    std::optional<CommandSetup> setup = prepareCommand(options, diagnostics);
    if (!setup) return reportSetupFailure(diagnostics, options.json);
    ProgramRequest request;
    if (!resolveProgram(options.arguments[0], setup->programs, options.process,
                        options.processGiven, request, diagnostics))
        return reportSetupFailure(diagnostics, options.json);
    core::CompilerOptions compilerOptions;
    compilerOptions.compilerActive = true;  // the <Compile> soft key exists only then
    compilerOptions.process = setup->machine.process(request.process);
    compilerOptions.programNumber = request.number;
    compilerOptions.programName = request.displayName;
    compilerOptions.globalMacros = setup->globalMacros;
    CompileOutcome outcome;
    core::UserCompilerSlots slots;
    for (const std::string& entry : options.userCompilers) {
        const int slot = entry[0] - '1';
        (slot < 2 ? slots.before[static_cast<std::size_t>(slot)]
                  : slots.after[static_cast<std::size_t>(slot - 2)]) = entry.substr(2);
    }
    const std::string source = sourcePathOf(options, request);
    if (slots.empty()) {
        outcome.result = core::Compiler().compile(*request.program, compilerOptions);
    } else {
        const std::size_t slash = source.find_last_of('/');
        const std::string directory = slash == std::string::npos ? "." : source.substr(0, slash);
        outcome.result = core::compileWithUserCompilers(core::Compiler(), request.program->source,
                                                        compilerOptions, slots, directory);
    }
    for (const core::ObjectLine& line : outcome.result.lineMap)
        if (line.intermediate && line.kind == core::ObjectLineKind::Block)
            ++outcome.intermediateBlocks;
    outcome.objectPath = options.outputPath;
    std::string error;
    if (outcome.objectPath.empty()) {
        const std::size_t dot = source.find_last_of('.');
        const std::size_t slash = source.find_last_of('/');
        outcome.objectPath =
            (dot != std::string::npos && (slash == std::string::npos || dot > slash)
                 ? source.substr(0, dot)
                 : source) +
            ".NCO";
    }
    if (!core::writeCompileFiles(source, outcome.objectPath, outcome.result, outcome.errorPath,
                                 error)) {
        diagnostics.error("CLI_FILE_UNWRITABLE", {}, error);
        return reportSetupFailure(diagnostics, options.json);
    }
    diagnostics.append(core::compilerDiagnostics(outcome.result.errors));
    reportChangedFile(request.program, diagnostics);
    if (options.json)
        writeJson(outcome, diagnostics);
    else
        writeText(outcome, diagnostics);
    return exitCodeFor(false, diagnostics);
}

}  // namespace mtc::cli
