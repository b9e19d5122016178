#pragma once

#include <string>
#include <vector>

#include "cnc_core/language/Program.h"

namespace mtc::core {

struct ParseOptions {
    int programNumber = 0;  ///< goes into every diagnostic and Program::number
    std::string name;       ///< file name / title for Program::name
    /// Global macros of the NC options (seed 001 ch. 4) known before the
    /// first block: a block using one is kept whole as a compiler command,
    /// like a block using a DEFINE macro of the program itself.
    std::vector<std::string> macroNames;
    /// The fast path for plain blocks (BlockParserPlain.cpp). It gives the
    /// same program as the general path; only the tests that prove this
    /// switch it off.
    bool plainBlockFastPath = true;
    /// Read an identification line and a %NPG / %MAC header (a program file
    /// or a loose file of blocks). False for an MDI entry, which is blocks
    /// only: a header line typed there is a block, and an error.
    bool fileLayout = true;
};

/// Parses NC source text: a .DAT file (identification line, %NPG/%MAC header,
/// blocks, PROGRAMMENDE) or a loose file of blocks. Never throws and never
/// crashes: every problem becomes a diagnostic in Program::diagnostics with
/// program, block, line and column; parsing recovers at the next block.
/// A file-backed `source` (SourceText over a ChunkedText) is parsed through
/// its window the first time: its text is not all in memory at once.
Program parseProgram(SourceText source, const ParseOptions& options = {});

}  // namespace mtc::core
