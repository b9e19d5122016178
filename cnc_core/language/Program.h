#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "cnc_core/language/BlockList.h"
#include "cnc_core/language/Diagnostic.h"
#include "cnc_core/language/SourceText.h"
#include "cnc_core/language/WordList.h"

/// The parsed form of an NC program. Compact and flat on purpose: a program of
/// 1,000,000 blocks must parse and stay in memory at a few times its source
/// size, so blocks, words and expression nodes live in three vectors and refer
/// to each other by index; text is kept once in `source` and referenced by span.
///
/// Storage note (language helper): `Program::blocks` and `Program::words` are
/// packed containers (BlockList / WordList below). Reading them looks exactly
/// like reading a std::vector (`size()`, `operator[]`, range-for, `back()`),
/// but elements come back BY VALUE as `const Block` / `const Word`: bind them
/// with `const Block& b = program.blocks[i]` or `auto b = ...`; to change one,
/// use `set(i, value)`. Common words (a letter and a decimal of less than
/// 2^26 units of its last digit, 67,108.864 at three decimals) take 5 bytes
/// (a slot and a column byte), other plain numeric words 5 + 8, common
/// blocks 12 bytes plus 12 per 64 blocks; everything else
/// lives in side tables (docs/decisions/language.md, "Memory").
namespace mtc::core {

/// Expression node. Children are indices into Program::expressions.
enum class ExprOp : std::uint8_t {
    Constant,  ///< value
    Variable,  ///< @n (process = -1: own process) or @p:n; number in `index`
    Negate,    ///< -a
    Add,
    Subtract,
    Multiply,
    Divide,    ///< a op b
    ReadM,     ///< M(a): last M of group a (1..16)
    ReadG,     ///< G(a): active G of group a
    ReadT,     ///< T
    ReadE,     ///< E
    ReadS,     ///< S / S1..S3 (spindle in `index`, 0 = main spindle)
    ReadSPC,   ///< SPC
    ReadTime,  ///< TIME
    ReadMTD,   ///< MTD(a,b,c,d); empty argument = -1 node index
    ReadAXD,   ///< AXD(axis:P-7-nnnn): axis letter*10+index in `index`, nnnn in `value`
    ReadQ,     ///< Q: the last Q function (seed 000, 3.1: read like M(16))
};

struct ExprNode {
    ExprOp op = ExprOp::Constant;
    std::int8_t process = -1;                     ///< Variable: explicit process or -1
    std::int32_t index = 0;                       ///< Variable number, spindle index
    std::int32_t a = -1, b = -1, c = -1, d = -1;  ///< children (MTD uses all four)
    double value = 0.0;
};

/// A cycle parameter declared in a %MAC file between %CHBEGIN% and %CHEND%:
/// "%V% @141 INT[1,2] text" (seed 000, 7.2).
struct CycleParameter {
    int variable = 0;      ///< @n
    std::string type;      ///< INT, REAL, ...
    double minimum = 0.0;  ///< range, when given
    double maximum = 0.0;
    bool hasRange = false;
    std::string text;  ///< operator prompt
    std::uint32_t line = 0;
};

/// One parsed NC program.
struct Program {
    int number = 0;              ///< program number (0 = loose file)
    std::string name;            ///< file name or title
    std::string identification;  ///< .DAT first line, if any
    std::string header;          ///< %NPG..%NPG header lines, if any
    SourceText source;           ///< the text all spans refer to
    BlockList blocks;
    WordList words;
    std::vector<ExprNode> expressions;
    std::unordered_map<std::string, std::uint32_t> labels;  ///< label -> block index
    DiagnosticList diagnostics;                             ///< parse problems
    bool isCycle = false;                                   ///< lives in the cycle memory (%MAC)

    // Added by the language helper:
    std::string title;                  ///< header line "*title", if any
    bool hasDatHeader = false;          ///< the source had the .DAT structure (limits checked)
    bool usesCompilerKeywords = false;  ///< some word has kWordNeedsCompiler
    std::vector<CycleParameter> cycleParameters;  ///< %V% declarations of a cycle
    std::string cycleCall;  ///< %N% line of a cycle ("BSR .*WSTCH ;cycle call")

    std::string_view text(TextSpan span) const { return source.span(span.offset, span.length); }
    /// "N0012" (or "N0012:0001" for compiled blocks) or "" for a block without number.
    std::string blockId(std::size_t blockIndex) const;
    /// Index of the block with label `name`, or -1.
    long findLabel(std::string_view name) const;
    /// 1-based source line of `offset` in `source` (binary search over the line
    /// starts is not kept, so this scans; for diagnostics only).
    std::uint32_t lineOf(std::uint32_t offset) const;
    /// Bytes this program holds (source, vectors, side tables; an estimate for
    /// maps and strings). For the memory benchmark.
    std::size_t memoryBytes() const;
};

using ProgramPtr = std::shared_ptr<const Program>;

}  // namespace mtc::core
