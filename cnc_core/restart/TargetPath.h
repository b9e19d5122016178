#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "cnc_core/interp/InterpreterState.h"
#include "cnc_core/language/Diagnostic.h"
#include "cnc_core/program/ProgramStore.h"
#include "cnc_core/restart/RestartSelection.h"

namespace mtc::core {

/// One reference of a target path as written: `N<number>` or `L<line>`,
/// optionally prefixed by `P<program>:`.
struct PathReference {
    int program = -1;     ///< P prefix; -1 = none (the program the path is in)
    bool byLine = false;  ///< L<line> instead of N<number>
    int number = 0;       ///< block number or source line
    std::string text;     ///< as written
};

/// Splits a target path (CLI-CONTRACT.md, "Target path"): references
/// separated by `>`. Fails (false, RESTART_PATH_SYNTAX) on malformed text.
bool parseTargetPath(std::string_view text, std::vector<PathReference>& references,
                     DiagnosticList& diagnostics);

/// The outcome of resolveTargetPath.
struct TargetPathResult {
    bool ok = false;
    bool syntaxError = false;    ///< the text is malformed (a usage error, not a program error)
    RestartSelection selection;  ///< runs = 1, fromLastPrimary = false: the caller sets those
    DiagnosticList diagnostics;
};

/// Follows a target path through the program memory of `process` as the
/// operator does on the restart screen with <Plane+> (seed 000, 2.5),
/// starting in `mainProgram`: every reference but the last must be a block
/// with a jump or call <Plane+> follows; labels are searched in the program,
/// then in program 99 (a label in the cycle memory is refused); JSR, JMP and
/// JEV go to their program, a program number in a single variable is the
/// value the operator enters in the variable window (the next reference's
/// `P<n>:`, recorded in variableChanges) or else the variable's value in
/// `current` (0 without a state). BES/BER/BEV/JEV events are set so that the
/// followed jump or call is taken (recorded in eventChanges). Errors:
/// RESTART_PATH_SYNTAX, RESTART_PATH_BLOCK_NOT_FOUND, RESTART_PATH_PROGRAM,
/// RESTART_PATH_NOT_A_CALL, RESTART_PATH_LABEL_NOT_FOUND,
/// RESTART_PATH_PROGRAM_NOT_FOUND, RESTART_IN_CYCLE, RESTART_PATH_DEPTH,
/// RESTART_PROGRAM_NOT_FOUND.
TargetPathResult resolveTargetPath(std::string_view text, const ProgramStore& store, int process,
                                   int mainProgram, const InterpreterState* current = nullptr);

}  // namespace mtc::core
