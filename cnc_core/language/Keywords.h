#pragma once

#include <string_view>

#include "cnc_core/language/Word.h"

namespace mtc::core {

/// How the parser treats a multi-letter word.
enum class KeywordClass : std::uint8_t {
    None,                 ///< not a keyword
    Jump,                 ///< BRA ... BTE (JumpKind in KeywordInfo::jump)
    Command,              ///< NC command with raw arguments (MTP, TCH, AXD, GAX, DP, WES, ...)
    CompilerCommand,      ///< NC compiler keyword with raw arguments (CF, LA_ON, FORM_50, ...)
    CompilerRestOfBlock,  ///< compiler keyword taking the rest of the block (DEFINE, LINE, ...)
    EffectiveRadius,      ///< RI
    Mtd,                  ///< MTD(...) = expr
    ReadOnly,             ///< SPC, TIME: readable in expressions only
    ProgramEnd,           ///< PROGRAMMENDE
    AxisFeed,             ///< F<axis> (axis-related velocity of the look-ahead, seed 001 ch. 6)
};

struct KeywordInfo {
    KeywordClass keywordClass = KeywordClass::None;
    JumpKind jump = JumpKind::BRA;
};

/// Classifies an identifier as written (uppercase). Never fails: unknown
/// names give KeywordClass::None.
KeywordInfo lookupKeyword(std::string_view name);

/// True for the axis address letters X Y Z U V W A B C (seed 003, 5.1).
constexpr bool isAxisLetter(char c) {
    switch (c) {
        case 'X':
        case 'Y':
        case 'Z':
        case 'U':
        case 'V':
        case 'W':
        case 'A':
        case 'B':
        case 'C':
            return true;
        default:
            return false;
    }
}

/// The jump mnemonic ("BRA") of a JumpKind.
std::string_view jumpName(JumpKind kind);

}  // namespace mtc::core
