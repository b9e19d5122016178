#pragma once

#include "cli/CliOptions.h"

namespace mtc::cli {

/// `mtc200-cli restart FILE|PROG --target PATH [--runs K] [--from-primary]
/// [--adjust]` (CLI-CONTRACT.md): NC program restart of one program on the
/// selected process. Follows PATH through the program memory
/// (core::resolveTargetPath), runs the computing process to the target block
/// and, with --adjust, goes on as the operator would with the machine keys:
/// Start (ADJUST), Automatic after the SPS selected manual mode, Start
/// (REPOS), up to the re-entry. Prints target, start, blocks, state,
/// auxiliary output, interface signals (and adjust/repos motion, final state).
/// Returns 0 on success, 1 when the restart fails (target not found, missing
/// program, a path that does not follow a call, ADJUST missing, a rejected
/// block, the block bound), 2 on usage or file problems (bad --runs or PATH).
int runRestartCommand(const CliOptions& options);

}  // namespace mtc::cli
