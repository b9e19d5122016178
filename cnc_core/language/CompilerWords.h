#pragma once

#include "cnc_core/language/Diagnostic.h"
#include "cnc_core/language/Program.h"

namespace mtc::core {

/// The download check of a program while the NC compiler is off (seed 001
/// ch. 7 note: a compiler keyword in the program is an error "at the
/// location concerned during the download process"): the first word that
/// needs the compiler (CF, RD, DEFINE, a macro name, a GNE or look-ahead
/// keyword ...) as the error NEEDS_COMPILER at its block, line and column.
/// False when the program needs no compiler. The station and the CLI refuse
/// such a program before anything of it runs.
bool findCompilerWord(const Program& program, Diagnostic& found);

}  // namespace mtc::core
