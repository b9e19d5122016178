#pragma once

#include <cstdint>

#include "cnc_core/language/Word.h"

namespace mtc::core {

/// Block flags.
enum BlockFlags : std::uint8_t {
    kBlockSkip = 1,        ///< '/' skip block
    kBlockPrimary = 2,     ///< ':' primary block
    kBlockHasError = 4,    ///< the parser rejected (part of) this block
    kBlockProgramEnd = 8,  ///< the PROGRAMMENDE line (no words; the program text ends here)
};

struct Block {
    std::uint32_t firstWord = 0;
    std::uint16_t wordCount = 0;
    std::uint8_t flags = 0;
    std::int32_t number = -1;     ///< N number, -1 = none
    std::uint32_t line = 0;       ///< 1-based first source line
    std::uint16_t lineCount = 1;  ///< with continuation lines
    TextSpan label;               ///< ".NAME" without the dot; empty = none
    TextSpan comment;             ///< text after ';' (else the first ( ) / [ ] text)
    TextSpan sourceText;          ///< the whole block's source text
    std::int16_t subNumber = -1;  ///< compiled programs: enhanced number of "N0053:0001"
    TextSpan text;                ///< first ( ... ) / [ ... ] text, without the brackets
};

}  // namespace mtc::core
