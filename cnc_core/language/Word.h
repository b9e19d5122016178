#pragma once

#include <cstdint>

namespace mtc::core {

/// A slice of Program::source.
struct TextSpan {
    std::uint32_t offset = 0;
    std::uint32_t length = 0;
    bool empty() const { return length == 0; }
};

/// What a word is. Address letters that carry a number are separate kinds so
/// the interpreter dispatches with one switch.
enum class WordKind : std::uint8_t {
    G,                ///< G<n> (number) or G=<expr>
    M,                ///< M<n> or M=<expr>
    Q,                ///< Q<n> or Q=<expr>
    S,                ///< spindle speed; axisIndex = spindle 0..3 (0 = S without index)
    T,                ///< tool number
    E,                ///< E word
    F,                ///< feed
    D,                ///< D correction
    Axis,             ///< axis word: letter in `letter`, index 0..3 in `axisIndex`
    CircleCenter,     ///< I / J / K in `letter`
    EffectiveRadius,  ///< RI
    Assign,           ///< @n = expr (variable node in `target`)
    AssignMTD,        ///< MTD(a,b,c,d) = expr (ReadMTD node in `target`)
    Jump,             ///< branch / jump / call / return; see JumpKind
    Command,          ///< other keyword command (MTP, TCH, AXD, GAX, ...): raw args in `text`
};

/// Jump commands, in groups:
/// - BRA always; BEQ (= 0), BNE (!= 0), BPL (>= 0), BMI (< 0) test the result
///   of the last arithmetic;
/// - BST, RET end the program;
/// - BSR / RTS: subroutine in the same program or program 99 / return;
/// - JSR / JMP: other program, by number or variable;
/// - BES, BER, BEV, JEV: event-dependent (event in eventProcess:eventNumber);
/// - BRF, BSE, BTE: tool-related branches.
// clang-format off
enum class JumpKind : std::uint8_t {
    BRA, BEQ, BNE, BPL, BMI,
    BST, RET,
    BSR, RTS,
    JSR, JMP,
    BES, BER, BEV, JEV,
    BRF, BSE, BTE,
};
// clang-format on

/// Word::flags bits.
enum WordFlags : std::uint8_t {
    /// A keyword of the NC compiler (seed 001: CF, RD, DEFINE, MODF_ON, LA_ON,
    /// CONT, FORM_xx, CYCLE_xx, TL_RADIUS, ...) or a use of a DEFINE macro.
    /// The control cannot run it uncompiled: the interpreter reports
    /// "needs the NC compiler".
    kWordNeedsCompiler = 1,
    /// M or Q written as a swift auxiliary function, MQxxx / QQxxx (seed
    /// 001 ch. 6: allowed inside a look-ahead segment). Runs like M / Q.
    kWordSwift = 2,
};

/// One word of a block.
///
/// Meaning of the fields by kind (added by the language helper, all optional):
/// - G/M/Q/S/T/E/F/D/Axis/CircleCenter/EffectiveRadius: value = `number`, or
///   the expression `expr` when written with `=` and an expression or a variable.
/// - Assign / AssignMTD: `target` = Variable / ReadMTD node, `expr` = value.
/// - Jump: `text` = label without '.' (empty for JSR/JMP/JEV/BST/RET/RTS);
///   JSR/JMP/JEV program number in `number` or as `expr` (`JMP @2`);
///   BES/BER/BEV/JEV event in eventProcess:eventNumber.
/// - Command: `text` = keyword and raw arguments as written (e.g.
///   "AXD (X:S-0-0104)=7000"), `args` = the arguments alone, trimmed;
///   `flags & kWordNeedsCompiler` for compiler keywords.
struct Word {
    WordKind kind = WordKind::G;
    char letter = 0;                 ///< Axis / CircleCenter letter; Command: 0
    std::uint8_t axisIndex = 0;      ///< 0 = no index, 1..3
    JumpKind jump = JumpKind::BRA;   ///< only for WordKind::Jump
    std::uint16_t column = 0;        ///< 1-based column in the source line
    std::int32_t expr = -1;          ///< value expression; -1 = use `number`
    std::int32_t target = -1;        ///< Assign/AssignMTD target node
    double number = 0.0;             ///< constant value when expr == -1
    TextSpan text;                   ///< label (without '.') / command keyword+args / raw word
    std::int16_t eventProcess = -1;  ///< BES/BER/BEV/JEV "p:e"
    std::int16_t eventNumber = -1;
    std::uint8_t flags = 0;  ///< WordFlags
    TextSpan args;           ///< Command: raw arguments without the keyword
};

/// The part of a Word that a number word (G M Q S T E F D, axis, I J K, RI)
/// needs: its value is `number`, or the expression `expr` when that is >= 0.
struct NumberWord {
    WordKind kind = WordKind::G;
    char letter = 0;
    std::uint8_t axisIndex = 0;
    std::uint16_t column = 0;
    std::int32_t expr = -1;
    double number = 0.0;
};

/// The number part of `word`.
inline NumberWord numberWordOf(const Word& word) {
    return {word.kind, word.letter, word.axisIndex, word.column, word.expr, word.number};
}

/// M02 or M30 with a constant number: the program ends at this word, before
/// any jump of its block (seed 000, 2.4).
inline bool endsProgram(WordKind kind, std::int32_t expr, double number) {
    return kind == WordKind::M && expr < 0 && (number == 2 || number == 30);
}

/// A word after which the flow may leave the straight run from block to
/// block: a jump word, or endsProgram(). WordList keeps the indices of such
/// words (WordList::flowTurningWords), the restart's flow analysis reads
/// only their blocks.
inline bool turnsFlow(WordKind kind, std::int32_t expr, double number) {
    return kind == WordKind::Jump || endsProgram(kind, expr, number);
}

}  // namespace mtc::core
