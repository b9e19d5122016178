#pragma once

#include <cstdint>
#include <memory>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "cnc_core/compiler/CompilerTypes.h"
#include "cnc_core/language/Program.h"

/// The pass interface of the NC compiler (seed 001, ch. 7): the compiler
/// turns the source program into a sequence of blocks and runs a list of
/// passes over it, each one rewriting block texts, removing blocks or
/// inserting intermediate blocks. Macro expansion, the modal function and
/// chamfers/roundings are built-in passes; look-ahead and the graphical NC
/// editor's contours register as further passes (StandardPasses.cpp).
namespace mtc::core {

/// One block of the program while it is compiled. `text` is everything that
/// follows the block number in one logical line (label, words, comment),
/// without the line breaks and six-blank indents of continuation lines.
struct CompileBlock {
    std::int32_t number = -1;       ///< source block number N (-1: the source block had none)
    std::int32_t sourceSub = 0;     ///< enhanced number written in the source ("N0053:0002"
                                    ///< from the GNE): the object keeps the order after N0053
    std::uint32_t sourceIndex = 0;  ///< index of the source block it stems from
    std::uint32_t sourceLine = 0;   ///< 1-based first source line of that block
    bool intermediate = false;      ///< inserted by the compiler (gets N....:0001 ...)
    bool changed = false;           ///< text differs from the source (set by a pass)
    bool programEnd = false;        ///< the PROGRAMMENDE block (passes leave it alone)
    std::string prefix;             ///< "/" and/or ":" written before the block number
    std::string text;               ///< the words after the block number, one line
    std::string sourceLayout;       ///< unchanged source text after the number when it has
                                    ///< continuation lines ("" = as text); used while !changed
};

using BlockSequence = std::vector<CompileBlock>;

/// Parsed view of a block sequence: `program.blocks[i]` belongs to
/// `blocks[blockOf[i]]`; blocks with empty text have no parsed block.
struct ParsedSequence {
    Program program;
    std::vector<std::uint32_t> blockOf;    ///< parsed block -> sequence index
    std::vector<std::int32_t> parsedOf;    ///< sequence index -> parsed block or -1
    std::vector<std::uint32_t> lineOwner;  ///< parse line - 1 -> sequence index
};

/// What a pass may use and where it reports. Owned by the compiler run.
class CompileContext {
  public:
    CompileContext(const CompilerOptions& options, std::vector<CompilerError>& errors);

    const CompilerOptions& options() const { return options_; }

    /// Reports an error or a warning of `block` (message cut to 52 characters,
    /// at most 14 detail lines of at most 65 characters). Returns false once
    /// the compile must stop (40 errors reached); a pass then returns at once.
    bool report(const CompileBlock& block, Severity severity, std::string code, std::string message,
                std::vector<std::string> details = {});
    /// Like `report`, for blocks[index]; an intermediate block is named
    /// with its enhanced number ("N0053:0001").
    bool reportAt(const BlockSequence& blocks, std::size_t index, Severity severity,
                  std::string code, std::string message, std::vector<std::string> details = {});
    /// A general error (Auuuu, not tied to a block), numbered from 1.
    bool reportGeneral(std::string code, std::string message,
                       std::vector<std::string> details = {});
    /// True when an error was reported for the source block of `block`
    /// (later passes leave such a block alone: one error per cause).
    bool hasError(const CompileBlock& block) const {
        return errorLines_.count(block.sourceLine) > 0;
    }
    /// True once the error limit is reached (no pass may continue).
    bool stopped() const { return stopped_; }
    int errorCount() const { return errorCount_; }

    /// Parses the sequence (one parse of all texts; cached until `invalidate`).
    const ParsedSequence& parsed(const BlockSequence& blocks);
    /// Call after changing texts or the number of blocks, before `parsed` again.
    void invalidate() { parsedValid_ = false; }

    /// "N0053" / "N0053:0001" style id of `block` inside `blocks` (the
    /// intermediate number counts the intermediate blocks since the last
    /// source block), "L<line>" when the source block had no number.
    static std::string blockId(const BlockSequence& blocks, std::size_t index);

    /// Adds a ready-made error (limits of message and details applied).
    bool submit(CompilerError error);

  private:
    const CompilerOptions& options_;
    std::vector<CompilerError>& errors_;
    int errorCount_ = 0;
    std::set<std::uint32_t> errorLines_;
    int warningCount_ = 0;
    int generalCount_ = 0;
    bool stopped_ = false;
    bool parsedValid_ = false;
    ParsedSequence parsed_;
};

/// A step of the compiler pipeline. Passes run in ascending `order()`;
/// built-ins: 100 macros, 200 modal function, 300 contour (GNE), 400
/// chamfers/roundings, 500 look-ahead. A pass lists the compiler keywords it
/// handles; a keyword that is still in the program after the last pass and
/// that no pass handles is reported as COMPILER_KEYWORD_UNSUPPORTED.
class CompilerPass {
  public:
    virtual ~CompilerPass() = default;
    /// Short name for diagnostics and docs ("macros", "cf-rd", ...).
    virtual std::string_view name() const = 0;
    /// Position in the pipeline (see class comment).
    virtual int order() const = 0;
    /// Compiler keywords this pass consumes (e.g. {"LA_ON", "LA_OFF"}).
    virtual std::vector<std::string> keywords() const = 0;
    /// Rewrites `blocks`; reports through `context`. Must never throw for
    /// bad input and must stop when `context.report` returns false.
    virtual void run(BlockSequence& blocks, CompileContext& context) const = 0;
};

using CompilerPassList = std::vector<std::shared_ptr<const CompilerPass>>;

}  // namespace mtc::core
