#include "cnc_core/compiler/UserCompilers.h"

#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "cnc_core/compiler/CommandLine.h"
#include "cnc_core/compiler/CompilerFiles.h"
#include "cnc_core/compiler/CompilerText.h"
#include "cnc_core/program/AtomicWrite.h"
#include "cnc_core/program/FileText.h"

namespace mtc::core {

namespace {

bool readWhole(const std::string& path, std::string& text) {
    std::string ignored;  // a missing or unreadable file is reported by its caller
    return readFileText(path, text, ignored);
}

CompilerError generalError(int slot, int number, std::string message) {
    CompilerError e;
    e.code = "USER_COMPILER_FAILED";
    e.generalNumber = number;
    e.message = "User compiler " + std::to_string(slot) + ": " + message;
    e.details = {e.message};
    e.message = limitMessage(e.message);
    return e;
}

/// Runs one user compiler on `text` (changed in place); false on an error.
bool runUserCompiler(int slot, const std::string& command, std::string& text,
                     const std::string& directory, const CompilerOptions& options,
                     std::vector<CompilerError>& errors) {
    const std::string base = directory + "/user_compiler_" + std::to_string(slot);
    const std::string input = base + ".in", output = base + ".out", messages = base + ".ERR";
    std::remove(output.c_str());
    std::remove(messages.c_str());
    std::string problem;
    if (!writeFileAtomically(input, text, problem)) {
        errors.push_back(
            generalError(slot, static_cast<int>(errors.size()) + 1, "cannot write its input file"));
        return false;
    }
    // D-010: no shell in between; the files are three more arguments.
    std::vector<std::string> arguments;
    if (!splitCommandLine(command, arguments, problem)) {
        errors.push_back(
            generalError(slot, static_cast<int>(errors.size()) + 1, "not run: " + problem));
        std::remove(input.c_str());
        return false;
    }
    arguments.insert(arguments.end(), {input, output, messages});
    const CommandOutcome outcome = runCommand(arguments, kUserCompilerTimeoutSeconds);
    const bool ok = outcome.problem.empty() && outcome.exitStatus == 0;
    std::string errorText, identification;
    if (readWhole(messages, errorText))
        for (CompilerError e : parseErrorFile(errorText, identification)) {
            e.program = options.programNumber;
            if (e.code.empty()) e.code = "USER_COMPILER_" + std::to_string(slot);
            errors.push_back(std::move(e));
        }
    std::string changed;
    if (readWhole(output, changed)) text = std::move(changed);
    std::remove(input.c_str());
    std::remove(output.c_str());
    std::remove(messages.c_str());
    if (!ok && errors.empty())
        errors.push_back(
            generalError(slot, 1,
                         outcome.problem.empty()
                             ? "failed (exit status " + std::to_string(outcome.exitStatus) + ")"
                             : outcome.problem));
    return ok;
}

/// The line map of an object text changed by a user compiler: block lines
/// by their "Nxxxx:yyyy" numbers, source lines taken from `old` where the
/// same block number was there before.
std::vector<ObjectLine> rebuildLineMap(const std::string& text,
                                       const std::vector<ObjectLine>& old) {
    std::vector<ObjectLine> map;
    std::istringstream lines(text);
    std::string line;
    ObjectLine current{ObjectLineKind::Header, 0, -1, 0, false};
    while (std::getline(lines, line)) {
        ObjectLine entry = current;
        if (map.empty() && line.rfind("iMTc", 0) == 0) {
            entry.kind = ObjectLineKind::Identification;
        } else if (line.size() >= 10 && line[0] == 'N' && line[5] == ':') {
            entry = {ObjectLineKind::Block, 0, std::atoi(line.substr(1, 4).c_str()),
                     std::atoi(line.substr(6, 4).c_str()), false};
            entry.intermediate = entry.subNumber > 0;
            for (const ObjectLine& o : old)
                if (o.sourceNumber == entry.sourceNumber && o.subNumber == entry.subNumber)
                    entry.sourceLine = o.sourceLine;
            if (line.find("PROGRAMMENDE") != std::string::npos)
                entry.kind = ObjectLineKind::ProgramEnd;
            current = entry;
        } else if (line.rfind("      ", 0) == 0 && !map.empty()) {
            entry.kind = ObjectLineKind::Continuation;
        }
        map.push_back(entry);
    }
    return map;
}

}  // namespace

CompileResult compileWithUserCompilers(const Compiler& compiler, std::string_view source,
                                       const CompilerOptions& options,
                                       const UserCompilerSlots& slots,
                                       const std::string& workDirectory) {
    CompileResult result;
    std::string text(source);
    for (int k = 0; k < 2; ++k) {
        if (slots.before[static_cast<std::size_t>(k)].empty()) continue;
        if (!runUserCompiler(k + 1, slots.before[static_cast<std::size_t>(k)], text, workDirectory,
                             options, result.errors)) {
            result.status = CompileStatus::Error;
            return result;
        }
    }
    std::vector<CompilerError> early = std::move(result.errors);
    result = compiler.compile(text, options);
    result.errors.insert(result.errors.begin(), early.begin(), early.end());
    if (result.status != CompileStatus::Compiled) return result;
    for (int k = 0; k < 2; ++k) {
        if (slots.after[static_cast<std::size_t>(k)].empty()) continue;
        const std::string before = result.objectText;
        if (!runUserCompiler(k + 3, slots.after[static_cast<std::size_t>(k)], result.objectText,
                             workDirectory, options, result.errors)) {
            result.status = CompileStatus::Error;
            result.objectText.clear();
            result.lineMap.clear();
            return result;
        }
        if (result.objectText != before)
            result.lineMap = rebuildLineMap(result.objectText, result.lineMap);
    }
    if (result.hasErrors()) {
        result.status = CompileStatus::Error;
        result.objectText.clear();
        result.lineMap.clear();
    }
    return result;
}

}  // namespace mtc::core
