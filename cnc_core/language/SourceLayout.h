#pragma once

#include <cstdint>
#include <string_view>

#include "cnc_core/language/ParseContext.h"

namespace mtc::core {

/// Where the blocks of a source text start, after the .DAT identification
/// line, the %NPG / %MAC header and a cycle's %CHBEGIN% ... %CHEND%
/// declarations (seed 001, ch. 10; seed 000, 7.2).
struct SourceLayout {
    std::uint32_t blocksBegin = 0;  ///< offset of the first block line
    std::uint32_t firstLine = 1;    ///< its 1-based line number
    bool dat = false;               ///< a %NPG/%MAC header was found
};

/// Reads the identification line and header (if any) of program.source into
/// Program::identification, header, title, number (when it is 0), isCycle,
/// cycleParameters and cycleCall. A text without header is a loose file of
/// blocks (layout.dat = false). Problems become diagnostics (DAT_...); the
/// text is never dropped.
SourceLayout readSourceLayout(ParseContext& context);

}  // namespace mtc::core
