#pragma once

// Compares two parsed programs field by field: the parser's fast path for
// plain blocks must give exactly what its general path gives (core test
// ParserFastPath, fuzz target "parser").

#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "cnc_core/language/Parser.h"
#include "cnc_core/language/Program.h"

namespace mtc::core::testing {

inline std::string describeBlockFields(const Block& b) {
    std::ostringstream out;
    out << "first=" << b.firstWord << " count=" << b.wordCount << " flags=" << int(b.flags)
        << " N=" << b.number << ":" << b.subNumber << " line=" << b.line << "+" << b.lineCount
        << " label=" << b.label.offset << "/" << b.label.length << " comment=" << b.comment.offset
        << "/" << b.comment.length << " source=" << b.sourceText.offset << "/"
        << b.sourceText.length << " text=" << b.text.offset << "/" << b.text.length;
    return out.str();
}

/// Every field of a word; the value bit for bit.
inline std::string describeWordFields(const Word& w) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &w.number, sizeof bits);
    std::ostringstream out;
    out << "kind=" << int(w.kind) << " letter=" << int(w.letter) << " index=" << int(w.axisIndex)
        << " jump=" << int(w.jump) << " column=" << w.column << " expr=" << w.expr
        << " target=" << w.target << " number=" << std::hex << bits << std::dec
        << " text=" << w.text.offset << "/" << w.text.length << " event=" << w.eventProcess << ":"
        << w.eventNumber << " flags=" << int(w.flags) << " args=" << w.args.offset << "/"
        << w.args.length;
    return out.str();
}

inline std::string describeDiagnosticFields(const Diagnostic& d) {
    return std::to_string(int(d.severity)) + " " + d.code + " " + d.where.block + " " +
           std::to_string(d.where.line) + ":" + std::to_string(d.where.column) + " " + d.message;
}

/// The indices of the words that turnsFlow(), read word by word: what
/// WordList::flowTurningWords() must list.
inline std::vector<std::uint32_t> flowTurningWordsReadOneByOne(const WordList& words) {
    std::vector<std::uint32_t> turning;
    for (std::size_t i = 0; i < words.size(); ++i) {
        const Word word = words[i];
        if (turnsFlow(word.kind, word.expr, word.number))
            turning.push_back(static_cast<std::uint32_t>(i));
    }
    return turning;
}

/// The first difference between `a` and `b` (blocks, words, expressions,
/// labels, diagnostics), or an empty string when they are the same. Also
/// checks that each lists its turning words as reading every word finds them.
inline std::string programDifference(const Program& a, const Program& b) {
    if (a.words.flowTurningWords() != flowTurningWordsReadOneByOne(a.words))
        return "turning words of the first";
    if (b.words.flowTurningWords() != flowTurningWordsReadOneByOne(b.words))
        return "turning words of the second";
    if (a.blocks.size() != b.blocks.size()) return "block count";
    for (std::size_t i = 0; i < a.blocks.size(); ++i) {
        std::string x = describeBlockFields(a.blocks[i]), y = describeBlockFields(b.blocks[i]);
        if (x != y) return "block " + std::to_string(i) + ": " + x + " / " + y;
    }
    if (a.words.size() != b.words.size()) return "word count";
    for (std::size_t i = 0; i < a.words.size(); ++i) {
        std::string x = describeWordFields(a.words[i]), y = describeWordFields(b.words[i]);
        if (x != y) return "word " + std::to_string(i) + ": " + x + " / " + y;
    }
    if (a.expressions.size() != b.expressions.size()) return "expression count";
    if (a.labels != b.labels) return "labels";
    if (a.usesCompilerKeywords != b.usesCompilerKeywords) return "compiler keywords";
    const auto& da = a.diagnostics.items();
    const auto& db = b.diagnostics.items();
    if (da.size() != db.size()) return "diagnostic count";
    for (std::size_t i = 0; i < da.size(); ++i) {
        std::string x = describeDiagnosticFields(da[i]), y = describeDiagnosticFields(db[i]);
        if (x != y) return "diagnostic: " + x + " / " + y;
    }
    return "";
}

/// `text` parsed with the fast path for plain blocks on or off (and the
/// names of global macros).
inline Program parseWith(const std::string& text, bool fastPath,
                         const std::vector<std::string>& macroNames = {}) {
    ParseOptions options;
    options.plainBlockFastPath = fastPath;
    options.macroNames = macroNames;
    return parseProgram(text, options);
}

/// Parses `text` both ways; an empty string when they agree, else the first
/// difference.
inline std::string differenceBetweenPaths(const std::string& text,
                                          const std::vector<std::string>& macroNames = {}) {
    return programDifference(parseWith(text, true, macroNames), parseWith(text, false, macroNames));
}

}  // namespace mtc::core::testing
