#pragma once

#include "cli/CliOptions.h"
#include "cnc_core/compiler/CompilerTypes.h"
#include "cnc_core/language/Diagnostic.h"

namespace mtc::cli {

/// `mtc200-cli compile FILE|PROG [-o OUT.NCO]` (CLI-CONTRACT.md): runs the NC
/// compiler (seed 001) and writes the object file (.NCO) or, on errors, the
/// error file (.ERR) next to it. Exit 0 compiled, 1 compile errors, 2 usage
/// or file problems.
int runCompileCommand(const CliOptions& options);

}  // namespace mtc::cli
