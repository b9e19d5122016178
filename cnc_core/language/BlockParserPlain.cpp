// The parser's fast path for the block shape that makes up nearly every
// program: "N0012 G1 X10.5 Y-3 F1000" — a four-digit block number and address
// letters each followed directly by a plain number. It scans the raw text
// with no lexer calls per character and stores the packed words itself.
//
// It never decides anything the general path would decide differently: it
// uses the same rules (Lexer::scanNumberAt, blockNumberDigitsAt, addressKind,
// axisIndexAt, normalizeNumber, WordList::tryPushNumber), takes a word only when the
// general path would take it without a diagnostic, and at the first word it
// does not take it stops and leaves the lexer at that word, where the general
// path (parseNextWord) goes on. The parser tests compare both paths.
#include "cnc_core/language/BlockParser.h"
#include "cnc_core/language/WordRules.h"

namespace mtc::core {

using word_rules::addressKind;
using word_rules::axisIndexAt;
using word_rules::BlockNumberDigits;
using word_rules::blockNumberDigitsAt;
using word_rules::kBlockNumberDigits;
using word_rules::normalizeNumber;
using word_rules::NumberCheck;

namespace {

bool isPlainBlank(char c) {
    return c == ' ' || c == '\t';
}

}  // namespace

bool BlockParser::takePlainBlockNumber() {
    const char* text = text_.data();
    const std::uint32_t begin = source_.begin;
    const std::uint32_t end = source_.end;
    if (begin >= end || text[begin] != 'N') return false;
    const BlockNumberDigits digits = blockNumberDigitsAt(text, begin + 1, end);
    if (digits.count != kBlockNumberDigits) return false;
    std::uint32_t digitsEnd = digits.end;
    std::int32_t subNumber = -1;
    if (digitsEnd < end && text[digitsEnd] == ':') {  // "N0053:0001" of a compiled program
        const BlockNumberDigits sub = blockNumberDigitsAt(text, digitsEnd + 1, end);
        if (sub.count != kBlockNumberDigits) return false;  // a primary colon or an error
        subNumber = static_cast<std::int32_t>(sub.value);
        digitsEnd = sub.end;
    }
    // After the number only a blank or the block end; and no skip slash,
    // primary colon or label, which the general prefix takes.
    if (digitsEnd < end && !isPlainBlank(text[digitsEnd])) return false;
    std::uint32_t next = digitsEnd;
    while (next < end && Lexer::isBlank(static_cast<unsigned char>(text[next])))
        ++next;
    if (next < end && (text[next] == '/' || text[next] == ':' || text[next] == '.')) return false;
    block_.number = static_cast<std::int32_t>(digits.value);
    if (subNumber >= 0) block_.subNumber = static_cast<std::int16_t>(subNumber);
    lexer_.seek(digitsEnd);
    return true;
}

bool BlockParser::startsWithoutPrefix() const {
    // the general prefix only acts on blanks, '/', ':', 'N' and '.'
    if (source_.begin >= source_.end) return false;
    const char first = text_[source_.begin];
    return !Lexer::isBlank(static_cast<unsigned char>(first)) && first != '/' && first != ':' &&
           first != 'N' && first != '.';
}

void BlockParser::parsePlainWords() {
    const char* text = text_.data();
    const std::uint32_t end = source_.end;
    std::uint32_t pos = lexer_.position();
    for (;;) {
        while (pos < end && isPlainBlank(text[pos]))
            ++pos;
        if (pos >= end) break;
        const char letter = text[pos];
        WordKind kind = WordKind::Axis;
        bool indexed = false;
        if (!addressKind(letter, kind, indexed)) break;
        std::uint32_t value = pos + 1;
        if (indexed && axisIndexAt(text, value, end) != 0) break;
        const bool negative = value < end && text[value] == '-';
        if (value < end && (text[value] == '-' || text[value] == '+')) ++value;
        NumberText number;
        const std::uint32_t after = Lexer::scanNumberAt(text, value, end, number);
        if (after == value || (after < end && text[after] == '.') || !number.exact) break;
        std::int64_t mantissa = number.mantissa;
        unsigned scale = number.scale;
        if (normalizeNumber(kind, negative, mantissa, scale) != NumberCheck::Ok) break;
        if (program_.words.size() - block_.firstWord >= kMaxWords) break;
        const std::uint32_t column = pos - source_.begin + 1;  // a one-line block
        if (!program_.words.tryPushNumber(kind, letter, 0, column, negative ? -mantissa : mantissa,
                                          scale))
            break;
        pos = after;
    }
    lexer_.seek(pos);
}

}  // namespace mtc::core
