#pragma once

#include <string>
#include <vector>

#include "cnc_core/language/Diagnostic.h"
#include "cnc_core/language/SourceText.h"
#include "cnc_core/program/ProgramStore.h"

namespace mtc::cli {

/// Opens a program file as a file-backed text (read by the parse chunk by
/// chunk and again where needed; PROC-003). Fails (false, `error` set) when
/// the path does not name a readable regular file.
bool openProgramFile(const std::string& path, core::SourceText& text, std::string& error);

/// Adds CLI_FILE_CHANGED when the program's file changed on disk after the
/// parse and a part of its text had to be read again (it reads as blanks).
void reportChangedFile(const core::ProgramPtr& program, core::DiagnosticList& diagnostics);

/// The program memory of a command: every program of the program directory
/// (--programs DIR) or of the demo programs built into the binary, parsed,
/// by process and number; %MAC files in the cycle memory.
struct ProgramMemory {
    core::ProgramStore store;
    std::string origin;  ///< "built-in demo programs" or "program directory 'DIR'"
    /// Global macro names of the directory's NC options: every program
    /// (memory and file arguments) is parsed knowing them (GM-005).
    std::vector<std::string> macroNames;
};

/// Loads `directory` (empty = the built-in demo programs) into `memory`.
/// Fails (false, CLI_FILE_UNREADABLE in `diagnostics`) when the directory
/// cannot be read. Problems of single files (bad names, duplicates,
/// unreadable files) are added as warnings: they do not stop a command that
/// does not need those files.
bool loadProgramMemory(const std::string& directory, ProgramMemory& memory,
                       core::DiagnosticList& diagnostics);

/// A program to check or run, resolved from a command-line argument.
struct ProgramRequest {
    std::string argument;     ///< as typed
    std::string displayName;  ///< file name
    int process = 0;
    int number = 0;  ///< 0 for a loose file without seed name
    core::ProgramPtr program;
};

/// Turns a command-line program argument into a parsed program: a number (1
/// to 3 digits) is looked up in `memory` for `process`; anything else is a
/// path, read and parsed. A path with a seed file name takes program number
/// and, unless `processGiven`, the process from its name. Fails (false, a
/// CLI_* diagnostic in `diagnostics`) when the program cannot be found or
/// read. Parse problems stay in request.program->diagnostics.
bool resolveProgram(const std::string& argument, const ProgramMemory& memory, int process,
                    bool processGiven, ProgramRequest& request, core::DiagnosticList& diagnostics);

/// A copy of `store` with the requested program in it (it replaces a
/// program of the same process and number), as the program memory the
/// request runs or is checked against.
/// The lowest program number 1..999 of `process` that `store` does not use
/// (999 when all are taken: the request replaces it).
int freeProgramNumber(const core::ProgramStore& store, int process);

core::ProgramStore storeWith(const core::ProgramStore& store, const ProgramRequest& request);

}  // namespace mtc::cli
