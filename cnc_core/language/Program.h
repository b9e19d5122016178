#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "cnc_core/language/Diagnostic.h"

/// The parsed form of an NC program. Compact and flat on purpose: a program of
/// 1,000,000 blocks must parse and stay in memory at a few times its source
/// size, so blocks, words and expression nodes live in three vectors and refer
/// to each other by index; text is kept once in `source` and referenced by span.
namespace mtc::core {

/// A slice of Program::source.
struct TextSpan {
    std::uint32_t offset = 0;
    std::uint32_t length = 0;
};

/// Expression node. Children are indices into Program::expressions.
enum class ExprOp : std::uint8_t {
    Constant,    ///< value
    Variable,    ///< @n (process = -1: own process) or @p:n; number in `index`
    Negate,      ///< -a
    Add, Subtract, Multiply, Divide,  ///< a op b
    ReadM,       ///< M(a): last M of group a (1..16)
    ReadG,       ///< G(a): active G of group a
    ReadT,       ///< T
    ReadE,       ///< E
    ReadS,       ///< S / S1..S3 (spindle in `index`, 0 = main spindle)
    ReadSPC,     ///< SPC
    ReadTime,    ///< TIME
    ReadMTD,     ///< MTD(a,b,c,d); empty argument = -1 node index
};

struct ExprNode {
    ExprOp op = ExprOp::Constant;
    std::int8_t process = -1;  ///< Variable: explicit process or -1
    std::int32_t index = 0;    ///< Variable number, spindle index
    std::int32_t a = -1, b = -1, c = -1, d = -1;  ///< children (MTD uses all four)
    double value = 0.0;
};

/// What a word is. Address letters that carry a number are separate kinds so
/// the interpreter dispatches with one switch.
enum class WordKind : std::uint8_t {
    G,            ///< G<n> (number) or G=<expr>
    M,            ///< M<n> or M=<expr>
    Q,            ///< Q<n> or Q=<expr>
    S,            ///< spindle speed; axisIndex = spindle 0..3 (0 = S without index)
    T,            ///< tool number
    E,            ///< E word
    F,            ///< feed
    D,            ///< D correction
    Axis,         ///< axis word: letter in `letter`, index 0..3 in `axisIndex`
    CircleCenter, ///< I / J / K in `letter`
    EffectiveRadius,  ///< RI
    Assign,       ///< @n = expr (variable node in `target`)
    AssignMTD,    ///< MTD(a,b,c,d) = expr (ReadMTD node in `target`)
    Jump,         ///< branch / jump / call / return; see JumpKind
    Command,      ///< other keyword command (MTP, TCH, AXD, GAX, ...): raw args in `text`
};

enum class JumpKind : std::uint8_t {
    BRA, BEQ, BNE, BPL, BMI,  ///< branches on the last arithmetic result
    BST, RET,                 ///< program end
    BSR, RTS,                 ///< subroutine in same program / program 99
    JSR, JMP,                 ///< other program (number or variable)
    BES, BER, BEV, JEV,       ///< event-dependent (event in eventProcess:eventNumber)
    BRF, BSE, BTE,            ///< tool-related branches
};

struct Word {
    WordKind kind = WordKind::G;
    char letter = 0;                ///< Axis / CircleCenter letter; Command: 0
    std::uint8_t axisIndex = 0;     ///< 0 = no index, 1..3
    JumpKind jump = JumpKind::BRA;  ///< only for WordKind::Jump
    std::uint16_t column = 0;       ///< 1-based column in the source line
    std::int32_t expr = -1;         ///< value expression; -1 = use `number`
    std::int32_t target = -1;       ///< Assign/AssignMTD target node
    double number = 0.0;            ///< constant value when expr == -1
    TextSpan text;                  ///< label (without '.') / command keyword+args / raw word
    std::int16_t eventProcess = -1; ///< BES/BER/BEV/JEV "p:e"
    std::int16_t eventNumber = -1;
};

/// Block flags.
enum BlockFlags : std::uint8_t {
    kBlockSkip = 1,      ///< '/' skip block
    kBlockPrimary = 2,   ///< ':' primary block
    kBlockHasError = 4,  ///< the parser rejected (part of) this block
};

struct Block {
    std::uint32_t firstWord = 0;
    std::uint16_t wordCount = 0;
    std::uint8_t flags = 0;
    std::int32_t number = -1;    ///< N number, -1 = none
    std::uint32_t line = 0;      ///< 1-based first source line
    std::uint16_t lineCount = 1; ///< with continuation lines
    TextSpan label;              ///< ".NAME" without the dot; empty = none
    TextSpan comment;            ///< text after ';' (and texts in ( ) / [ ])
    TextSpan sourceText;         ///< the whole block's source text
};

/// One parsed NC program.
struct Program {
    int number = 0;                ///< program number (0 = loose file)
    std::string name;              ///< file name or title
    std::string identification;    ///< .DAT first line, if any
    std::string header;            ///< %NPG..%NPG header lines, if any
    std::string source;            ///< the text all spans refer to
    std::vector<Block> blocks;
    std::vector<Word> words;
    std::vector<ExprNode> expressions;
    std::unordered_map<std::string, std::uint32_t> labels;  ///< label -> block index
    DiagnosticList diagnostics;    ///< parse problems
    bool isCycle = false;          ///< lives in the cycle memory (%MAC)

    std::string_view text(TextSpan span) const {
        return std::string_view(source).substr(span.offset, span.length);
    }
    /// "N0012" or "" for a block without number.
    std::string blockId(std::size_t blockIndex) const;
    /// Index of the block with label `name`, or -1.
    long findLabel(std::string_view name) const;
};

using ProgramPtr = std::shared_ptr<const Program>;

}  // namespace mtc::core
