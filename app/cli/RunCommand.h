#pragma once

#include "cli/CliOptions.h"

namespace mtc::cli {

/// `mtc200-cli run FILE|PROG [--no-motion]`: executes one program in
/// simulated time on the selected process and prints status, diagnostics,
/// motion (streamed while the program runs, left out with --no-motion) and
/// the final state. Returns 0 on success, 1 when the program or the run has
/// errors (including exceeding --max-blocks), 2 on file or usage problems.
int runRunCommand(const CliOptions& options);

}  // namespace mtc::cli
