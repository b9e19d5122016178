#pragma once

#include "cli/CliOptions.h"

namespace mtc::cli {

/// `mtc200-cli check FILE|PROG...`: parses and checks every program and prints
/// the diagnostics (text, or one JSON document with --json). Changes nothing.
/// Returns 0 when no program has errors, 1 when one has, 2 when a program,
/// the machine or the program directory cannot be read.
int runCheckCommand(const CliOptions& options);

}  // namespace mtc::cli
