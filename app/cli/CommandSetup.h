#pragma once

#include <optional>

#include "cli/CliOptions.h"
#include "cli/ProgramMemory.h"
#include "cnc_core/compiler/CompilerTypes.h"
#include "cnc_core/language/Diagnostic.h"
#include "cnc_core/machine/MachineConfig.h"
#include "cnc_core/program/ProgramStore.h"

namespace mtc::cli {

/// What every program command needs before it starts: the machine and the
/// program directory.
struct CommandSetup {
    core::MachineConfig machine;
    ProgramMemory programs;
    /// Global macros of the NC options: GLOBAL_MACROS.MAC of --programs
    /// (GM-005); none for the built-in demo programs.
    std::vector<core::MacroDefinition> globalMacros;
};

/// Loads machine (--machine or the demo cell) and program directory
/// (--programs or the demo programs) and checks that --process exists when it
/// was given. Fails (nothing; diagnostics say why) on unreadable or invalid
/// files: the caller exits with code 2.
std::optional<CommandSetup> prepareCommand(const CliOptions& options,
                                           core::DiagnosticList& diagnostics);

/// Static check of a parsed program against the program memory: every label
/// a jump or call names must exist in the program itself or in program 99 of
/// `process` (seed 000, 2.5), every program called by a constant number
/// (JSR, JMP, JEV) must exist. Returns the problems found (PROGRAM_* codes).
core::DiagnosticList checkProgramReferences(const core::Program& program,
                                            const core::ProgramStore& store, int process);

}  // namespace mtc::cli
