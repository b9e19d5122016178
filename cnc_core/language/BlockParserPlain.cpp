// The parser's fast path for the block shape that makes up nearly every
// program: "N0012 G1 X10.5 Y-3 F1000" — a four-digit block number and address
// letters each followed directly by a plain number. It scans the raw text
// with no lexer calls per character and stores the packed words itself.
//
// It never decides anything the general path would decide differently: it
// uses the same rules (Lexer::scanNumberAt, blockNumberDigitsAt, addressKind,
// axisIndexAt, normalizeNumber, WordList::tryPushNumber; the first two in
// tighter forms that give the same result for the numbers they take, and
// hand every other number to the rule itself; addressKind looked up in a
// table built from it at compile time), takes a word only when the
// general path would take it without a diagnostic, and at the first word it
// does not take it stops and leaves the lexer at that word, where the general
// path (parseNextWord) goes on. The parser tests compare both paths.
#include "cnc_core/language/BlockParser.h"
#include "cnc_core/language/WordRules.h"

namespace mtc::core {

using word_rules::addressKind;
using word_rules::axisIndexAt;
using word_rules::kBlockNumberDigits;
using word_rules::normalizeNumber;
using word_rules::NumberCheck;
using word_rules::valueMustBeWhole;

namespace {

bool isPlainBlank(char c) {
    return c == ' ' || c == '\t';
}

/// addressKind of every byte in one table entry: kAddress set for an
/// address letter, kIndexed when it may carry an index, kWhole when its value
/// must be a whole number (valueMustBeWhole), the WordKind in the low bits.
constexpr std::uint8_t kAddress = 0x80;
constexpr std::uint8_t kIndexed = 0x40;
constexpr std::uint8_t kWhole = 0x20;
constexpr std::uint8_t kKindBits = 0x1f;
struct AddressTable {
    std::uint8_t entry[256];
};

constexpr AddressTable makeAddressTable() {
    AddressTable table{};
    for (int c = 0; c < 256; ++c) {
        WordKind kind = WordKind::Axis;
        bool indexed = false;
        if (addressKind(static_cast<char>(c), kind, indexed))
            table.entry[c] = static_cast<std::uint8_t>(kAddress | (indexed ? kIndexed : 0) |
                                                       (valueMustBeWhole(kind) ? kWhole : 0) |
                                                       static_cast<std::uint8_t>(kind));
    }
    return table;
}

constexpr AddressTable kAddressTable = makeAddressTable();
static_assert(static_cast<std::uint8_t>(WordKind::Command) <= kKindBits);

/// The value of a digit character, or more than 9 for any other byte.
unsigned digitValue(char c) {
    return static_cast<unsigned>(static_cast<unsigned char>(c)) - '0';
}

/// True when blockNumberDigitsAt(text, pos, end) counts exactly four digits
/// (four digits at `pos`, no fifth); `value` is then their value.
bool fourDigitsAt(const char* text, std::uint32_t pos, std::uint32_t end, std::int32_t& value) {
    if (end - pos < kBlockNumberDigits) return false;  // pos <= end
    const unsigned d0 = digitValue(text[pos]), d1 = digitValue(text[pos + 1]);
    const unsigned d2 = digitValue(text[pos + 2]), d3 = digitValue(text[pos + 3]);
    if (d0 > 9 || d1 > 9 || d2 > 9 || d3 > 9) return false;
    if (pos + 4 < end && digitValue(text[pos + 4]) <= 9) return false;
    value = static_cast<std::int32_t>(((d0 * 10 + d1) * 10 + d2) * 10 + d3);
    return true;
}

/// Most digits a number may have for the tight scan below: scanNumberAt
/// keeps every digit of a number up to 18 digits in its mantissa, exactly.
constexpr std::uint32_t kPlainNumberDigits = 17;

/// Lexer::scanNumberAt for numbers of up to kPlainNumberDigits digits:
/// the digits before the point in one loop, those after it in another.
/// Returns false for a longer number (then scanNumberAt reads it); otherwise
/// sets `after` to what scanNumberAt returns and, when a number starts at
/// `pos` (after > pos), `number` to what it gives.
bool scanPlainNumber(const char* text, std::uint32_t pos, std::uint32_t end, NumberText& number,
                     std::uint32_t& after) {
    std::uint64_t mantissa = 0;  // may wrap for a long run of digits: then unused
    std::uint32_t p = pos;
    for (unsigned digit = 0; p < end && (digit = digitValue(text[p])) <= 9; ++p)
        mantissa = mantissa * 10 + digit;
    std::uint32_t digits = p - pos;
    unsigned scale = 0;
    if (p < end && text[p] == '.') {
        const std::uint32_t decimals = ++p;
        for (unsigned digit = 0; p < end && (digit = digitValue(text[p])) <= 9; ++p)
            mantissa = mantissa * 10 + digit;
        scale = p - decimals;
        digits += scale;
    }
    if (digits > kPlainNumberDigits) return false;
    after = digits == 0 ? pos : p;
    number.mantissa = static_cast<std::int64_t>(mantissa);
    number.scale = scale;
    number.exact = true;
    number.begin = pos;
    number.end = p;
    return true;
}

}  // namespace

bool BlockParser::takePlainBlockNumber() {
    const char* text = text_.data();
    const std::uint32_t begin = source_.begin;
    const std::uint32_t end = source_.end;
    std::int32_t number = 0;
    if (begin >= end || text[begin] != 'N' || !fourDigitsAt(text, begin + 1, end, number))
        return false;
    std::uint32_t digitsEnd = begin + 1 + kBlockNumberDigits;
    std::int32_t subNumber = -1;
    if (digitsEnd < end && text[digitsEnd] == ':') {  // "N0053:0001" of a compiled program
        // not four digits: a primary colon or an error
        if (!fourDigitsAt(text, digitsEnd + 1, end, subNumber)) return false;
        digitsEnd += 1 + kBlockNumberDigits;
    }
    // After the number only a blank or the block end; and no skip slash,
    // primary colon or label, which the general prefix takes.
    if (digitsEnd < end && !isPlainBlank(text[digitsEnd])) return false;
    std::uint32_t next = digitsEnd;
    while (next < end && Lexer::isBlank(static_cast<unsigned char>(text[next])))
        ++next;
    if (next < end && (text[next] == '/' || text[next] == ':' || text[next] == '.')) return false;
    block_.number = number;
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
    // The block has no words yet and each plain word takes two characters at
    // least: only a block this long can reach kMaxWords.
    const bool mayBeFull = end - pos >= 2 * kMaxWords;
    for (;;) {
        if (pos < end && text[pos] == ' ') ++pos;  // the usual single blank
        while (pos < end && isPlainBlank(text[pos]))
            ++pos;
        if (pos >= end) break;
        const char letter = text[pos];
        const std::uint8_t address = kAddressTable.entry[static_cast<unsigned char>(letter)];
        if (!(address & kAddress)) break;
        const auto kind = static_cast<WordKind>(address & kKindBits);
        std::uint32_t value = pos + 1;
        if ((address & kIndexed) && axisIndexAt(text, value, end) != 0) break;
        const bool negative = value < end && text[value] == '-';
        if (value < end && (text[value] == '-' || text[value] == '+')) ++value;
        NumberText number;
        std::uint32_t after = value;
        if (!scanPlainNumber(text, value, end, number, after))
            after = Lexer::scanNumberAt(text, value, end, number);
        if (after == value || (after < end && text[after] == '.') || !number.exact) break;
        std::int64_t mantissa = number.mantissa;
        unsigned scale = number.scale;
        // normalizeNumber changes and refuses nothing for a number of at most
        // 7 decimals below 2^31 unless its word needs a whole number and it
        // is negative or has decimals: its branches are skipped then.
        const bool normalize = (scale > 7) | (mantissa > 2147483647) |
                               (((address & kWhole) != 0) & (negative | (scale != 0)));
        if (normalize && normalizeNumber(kind, negative, mantissa, scale) != NumberCheck::Ok) break;
        if (mayBeFull && program_.words.size() - block_.firstWord >= kMaxWords) break;
        const std::uint32_t column = pos - source_.begin + 1;  // a one-line block
        if (!program_.words.tryPushNumber(kind, letter, 0, column, negative ? -mantissa : mantissa,
                                          scale))
            break;
        pos = after;
    }
    lexer_.seek(pos);
}

}  // namespace mtc::core
