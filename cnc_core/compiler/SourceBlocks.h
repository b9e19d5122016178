#pragma once

#include <string>

#include "cnc_core/compiler/CompilerPass.h"
#include "cnc_core/language/Program.h"

namespace mtc::core {

/// The parts of a source program the compiler copies or compiles.
struct SourceFrame {
    std::string identification;         ///< first line of a .DAT file ("" for a loose file)
    std::string header;                 ///< %NPG ... %NPG lines, '\n'-separated ("" if none)
    std::uint32_t headerFirstLine = 0;  ///< source line of the first header line
    bool dat = false;                   ///< a .DAT text (limits apply)
    bool hasProgramEnd = false;         ///< the source ends with a PROGRAMMENDE block
    std::int32_t lastNumber = -1;       ///< highest block number seen
};

/// Splits a parsed source program into compile blocks, one per source
/// block (comment-only and blank lines are not blocks; seed 001 ch. 11 lets
/// the compiler drop comments), and fills `frame`.
BlockSequence splitSourceBlocks(const Program& program, SourceFrame& frame);

}  // namespace mtc::core
