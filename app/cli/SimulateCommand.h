#pragma once

#include "cli/CliOptions.h"

namespace mtc::cli {

/// `mtc200-cli simulate FILE|PROG [--stl OUT.stl] [--resolution MM]`
/// (CLI-CONTRACT.md "Extensions"): cuts the process's stock with the
/// program (cnc_core/removal, docs/DECISIONS.md D-020), reports the removed
/// volume and writes the finished part as binary STL (atomically; not when
/// the program has errors). Exit 0, 1 (program errors), 2 (usage, files,
/// a stock the model cannot be made of).
int runSimulateCommand(const CliOptions& options);

}  // namespace mtc::cli
