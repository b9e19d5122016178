#include "cli/ProgramMemory.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <system_error>
#include <utility>
#include <vector>

#include "cnc_core/program/DatFile.h"
#include "cnc_core/program/DatFileName.h"
#include "cnc_core/program/FileBackedText.h"
#include "cnc_core/program/FileText.h"
#include "cnc_core/program/ProgramLoader.h"
#include "resources/EmbeddedResources.h"

namespace mtc::cli {

namespace {

bool allDigits(std::string_view text) {
    return !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
        return std::isdigit(static_cast<unsigned char>(c)) != 0;
    });
}

std::string baseName(const std::string& path) {
    const auto slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

/// Loader problems of single files become warnings of the command.
void appendAsWarnings(const core::DiagnosticList& from, core::DiagnosticList& to) {
    for (core::Diagnostic d : from.items()) {
        d.severity = core::Severity::Warning;
        to.add(std::move(d));
    }
}

bool resolveNumber(const std::string& argument, const ProgramMemory& memory,
                   ProgramRequest& request, core::DiagnosticList& diagnostics) {
    request.number = std::stoi(argument);
    request.program = memory.store.find(request.process, request.number);
    if (!request.program) {
        diagnostics.error("CLI_PROGRAM_NOT_FOUND", {},
                          "program " + argument + " of process " + std::to_string(request.process) +
                              " not found in the " + memory.origin);
        return false;
    }
    request.displayName = request.program->name;
    return true;
}

}  // namespace

bool openProgramFile(const std::string& path, core::SourceText& text, std::string& error) {
    const std::string why = core::whyNotARegularFile(path);
    if (why == "does not exist") {
        error = "cannot read '" + path + "': no such file";
        return false;
    }
    if (!why.empty()) {
        error = "cannot read '" + path + "': not a regular file (it " + why + ")";
        return false;
    }
    std::string reason;
    std::shared_ptr<core::FileBackedText> file = core::FileBackedText::open(path, reason);
    if (!file) {
        error = "cannot read " + reason;
        return false;
    }
    text = core::SourceText(std::move(file));
    return true;
}

void reportChangedFile(const core::ProgramPtr& program, core::DiagnosticList& diagnostics) {
    const core::ChunkedText* file = program ? program->source.file() : nullptr;
    if (file && file->changed()) diagnostics.error("CLI_FILE_CHANGED", {}, file->changeMessage());
}

bool loadProgramMemory(const std::string& directory, ProgramMemory& memory,
                       core::DiagnosticList& diagnostics) {
    core::ProgramLoader loader(memory.store);
    loader.setMacroNames(memory.macroNames);
    if (directory.empty()) {
        memory.origin = "built-in demo programs";
        loader.loadTexts(resources::demoPrograms());
    } else {
        memory.origin = "program directory '" + directory + "'";
        std::error_code ec;
        if (!std::filesystem::is_directory(directory, ec)) {
            const bool exists = std::filesystem::exists(directory, ec);
            diagnostics.error(
                "CLI_FILE_UNREADABLE", {},
                "--programs '" + directory + "' " +
                    (exists ? "is a file, not a program directory" : "does not exist"));
            return false;
        }
        loader.loadDirectory(directory);
    }
    appendAsWarnings(loader.diagnostics(), diagnostics);
    return true;
}

bool resolveProgram(const std::string& argument, const ProgramMemory& memory, int process,
                    bool processGiven, ProgramRequest& request, core::DiagnosticList& diagnostics) {
    request = ProgramRequest{};
    request.argument = argument;
    request.process = process;
    if (argument.size() <= 3 && allDigits(argument))
        return resolveNumber(argument, memory, request, diagnostics);
    core::SourceText text;
    std::string error;
    if (!openProgramFile(argument, text, error)) {
        diagnostics.error("CLI_FILE_UNREADABLE", {}, error);
        return false;
    }
    request.displayName = baseName(argument);
    if (auto id = core::parseDatFileName(request.displayName)) {
        request.number = id->number;
        if (!processGiven) {
            request.process = id->process;
        } else if (id->process != process) {
            diagnostics.warning("CLI_PROCESS_MISMATCH", {},
                                "file name " + request.displayName + " names process " +
                                    std::to_string(id->process) + "; it runs in process " +
                                    std::to_string(process) + " as --process says");
        }
    }
    core::ParseOptions options{request.number, request.displayName, memory.macroNames};
    request.program = std::make_shared<const core::Program>(
        core::DatFile::parse(std::move(text), request.displayName, options));
    // A loose file name with a %NPG header: the program is the header's
    // number, and the store must hold it under that number too (a copy of
    // program 1 under another name replaced nothing, so a restart found
    // two different programs 1).
    if (request.number == 0) request.number = request.program->number;
    return true;
}

int freeProgramNumber(const core::ProgramStore& store, int process) {
    for (int number = 1; number < 999; ++number)
        if (!store.findSource(process, number)) return number;
    return 999;
}

core::ProgramStore storeWith(const core::ProgramStore& store, const ProgramRequest& request) {
    core::ProgramStore copy = store;
    copy.put(request.process, request.number, request.program);
    return copy;
}

}  // namespace mtc::cli
