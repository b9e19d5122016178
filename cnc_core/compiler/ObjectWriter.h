#pragma once

#include <string>
#include <vector>

#include "cnc_core/compiler/CompilerPass.h"
#include "cnc_core/compiler/SourceBlocks.h"

namespace mtc::core {

/// The object file text and its line map.
struct ObjectText {
    std::string text;
    std::vector<ObjectLine> lineMap;
    std::size_t blocks = 0;  ///< NC blocks without PROGRAMMENDE
};

/// True when `block` goes on counting the enhanced number of the block
/// before it (number `previousNumber`): an intermediate block, or a source
/// block the GNE numbered "N0053:0002" right after the blocks of N0053.
bool continuesNumbering(const CompileBlock& block, int previousNumber);

/// Writes the object file (seed 001, ch. 11): identification and header
/// copied, every block as "Nxxxx:yyyy text" (yyyy 0000 for a source block,
/// counting up for the intermediate blocks after it and for source blocks
/// written with an enhanced number of the same source number), lines of at most 71
/// characters with six-blank continuation lines, at most 230 characters and
/// 4 lines per block (comments are dropped first when a block is too long),
/// the PROGRAMMENDE block last. Problems are reported through `context`:
/// a block that does not fit, and more than 10,000 lines (general error;
/// for .DAT programs, as the parser's file limits).
ObjectText writeObjectText(const SourceFrame& frame, const BlockSequence& blocks,
                           CompileContext& context);

}  // namespace mtc::core
