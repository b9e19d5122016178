#pragma once

#include <string>

#include "cnc_core/language/Program.h"

namespace mtc::core {

struct ParseOptions {
    int programNumber = 0;  ///< goes into every diagnostic and Program::number
    std::string name;       ///< file name / title for Program::name
};

/// Parses NC source text: a .DAT file (identification line, %NPG/%MAC header,
/// blocks, PROGRAMMENDE) or a loose file of blocks. Never throws and never
/// crashes: every problem becomes a diagnostic in Program::diagnostics with
/// program, block, line and column; parsing recovers at the next block.
Program parseProgram(std::string source, const ParseOptions& options = {});

}  // namespace mtc::core
