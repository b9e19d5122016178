// Parser: every index and span of the parsed program lies inside its
// vectors and its source, every diagnostic has a code, a message and a place;
// the fast path for plain blocks gives exactly what the general path gives.
#include <string>

#include "../FuzzTargets.h"
#include "cnc_core/language/Parser.h"
#include "cnc_core/program/DatFile.h"
#include "tests/support/ProgramDifference.h"

namespace mtc::fuzz {
namespace {

using core::Program;

void checkProgram(const Program& p, std::string_view input) {
    require(p.source == input, "the program keeps its source", input);
    const std::size_t sourceSize = p.source.size();
    auto spanOk = [&](core::TextSpan s) { return std::size_t{s.offset} + s.length <= sourceSize; };
    std::size_t expectedWord = 0;
    for (std::size_t b = 0; b < p.blocks.size(); ++b) {
        const core::Block block = p.blocks[b];
        require(block.firstWord == expectedWord, "blocks' words follow each other", input);
        expectedWord += block.wordCount;
        require(expectedWord <= p.words.size(), "a block's words exist", input);
        require(spanOk(block.sourceText) && spanOk(block.label) && spanOk(block.comment),
                "block spans inside the source", input);
        require(block.line >= 1, "a block has a line", input);
    }
    require(expectedWord == p.words.size(), "every word belongs to a block", input);
    const auto nodes = static_cast<std::int64_t>(p.expressions.size());
    for (std::size_t i = 0; i < p.words.size(); ++i) {
        const core::Word w = p.words[i];
        require(w.expr >= -1 && w.expr < nodes && w.target >= -1 && w.target < nodes,
                "a word's expressions exist", input);
        require(spanOk(w.text) && spanOk(w.args), "word spans inside the source", input);
    }
    for (std::size_t i = 0; i < p.expressions.size(); ++i) {
        const core::ExprNode& n = p.expressions[i];
        for (std::int32_t child : {n.a, n.b, n.c, n.d})
            require(child >= -1 && child < static_cast<std::int64_t>(i),
                    "expression children come before their parent", input);
    }
    for (const auto& [name, index] : p.labels)
        require(index < p.blocks.size(), "a label names a block", input);
    for (const auto& d : p.diagnostics.items()) {
        require(!d.code.empty() && !d.message.empty(), "a diagnostic has code and message", input);
        require(d.where.line >= 0 && d.where.column >= 0, "a diagnostic has a place", input);
    }
    require(p.diagnostics.size() <= 1001, "diagnostics are bounded", input);
}

/// The fast paths (whole lines, plain blocks) against the general path.
void compareWithGeneralPath(const std::string& text, core::ParseOptions options,
                            std::string_view input) {
    const Program fast = core::DatFile::parse(text, "loose.nc", options);
    checkProgram(fast, input);
    options.plainBlockFastPath = false;
    const Program general = core::DatFile::parse(text, "loose.nc", options);
    require(core::testing::programDifference(fast, general).empty(),
            "the fast path for plain blocks parses as the general path", input);
}

}  // namespace

void fuzzParser(std::string_view input) {
    const std::string text(input);
    checkProgram(core::DatFile::parse(text, "N1010005.DAT"), input);
    // Without macros: the fast path for whole lines (BlockParser::parseLine).
    compareWithGeneralPath(text, core::ParseOptions{}, input);
    core::ParseOptions options;
    options.programNumber = 7;
    options.macroNames = {"FAST", "SLOW", "M860", "X1"};
    compareWithGeneralPath(text, options, input);
}

}  // namespace mtc::fuzz
