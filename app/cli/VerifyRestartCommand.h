#pragma once

#include "cli/CliOptions.h"

namespace mtc::cli {

/// `mtc200-cli verify-restart FILE|PROG [--adjust] [--max-passes K] [--json]`
/// (CLI-CONTRACT.md "Extensions", restart.md R-028): every arrival at every
/// block of the program tree, the first K passes of each, as an NC program
/// restart target (core::RestartVerifier). Prints every difference with its
/// target and the coverage line. Returns 0 when every target is
/// re-established, 1 with differences, failures or a run that stopped on an
/// error, 2 on usage or file problems.
int runVerifyRestartCommand(const CliOptions& options);

}  // namespace mtc::cli
