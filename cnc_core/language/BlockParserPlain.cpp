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
//
// For a loose file the line scanner hands whole lines to parseLine (issue
// 21): the block number, the words and the line end are found in one pass
// over the line, the words written straight into the word list, the block
// stored packed; no BlockSource, Lexer or Block in between unless a word
// sends the rest of the line to the general path. A line the next line may
// continue (it starts with a blank) is left whole to the line scanner. Once
// a macro is known, a line that uses one becomes the one macro word of the
// general path (takeMacroLine); the enhanced number "N0053:0001" of a
// compiled program is read here too (its block is stored whole).
#include <algorithm>
#include <cstring>

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

/// True when 'M' is the only letter of an M word: the fast path asks the
/// letter alone whether a word may end the program (WordList::numberTurnsFlow).
constexpr bool onlyLetterOfM() {
    for (int c = 0; c < 256; ++c) {
        const std::uint8_t entry = kAddressTable.entry[c];
        if ((entry & kAddress) && (entry & kKindBits) == static_cast<std::uint8_t>(WordKind::M) &&
            c != 'M')
            return false;
    }
    return true;
}
static_assert(onlyLetterOfM());
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

/// True when the line ends at `pos` of the text of `size` bytes: its '\n',
/// a '\r' before the '\n' or the text's end, or the text's end itself.
bool lineEndAt(const char* text, std::uint32_t pos, std::uint32_t size) {
    if (pos >= size || text[pos] == '\n') return true;
    return text[pos] == '\r' && (pos + 1 == size || text[pos + 1] == '\n');
}

/// takePlainBlockNumber for the line starting at `begin` with 'N' before
/// its end is known: true, with the number's value (and the enhanced
/// number's, else -1) and the offset after its digits, only where
/// takePlainBlockNumber takes it as a one-line block (it leaves a '\r'
/// inside the line to the general path). A digit never ends a line, so
/// the digits are counted up to the text's end as well as the line's.
bool lineBlockNumberAt(const char* text, std::uint32_t begin, std::uint32_t size,
                       std::int32_t& number, std::int32_t& subNumber, std::uint32_t& after) {
    if (!fourDigitsAt(text, begin + 1, size, number)) return false;
    std::uint32_t digitsEnd = begin + 1 + kBlockNumberDigits;
    if (digitsEnd < size && text[digitsEnd] == ':') {  // "N0053:0001" of a compiled program
        if (!fourDigitsAt(text, digitsEnd + 1, size, subNumber)) return false;
        digitsEnd += 1 + kBlockNumberDigits;
    }
    after = digitsEnd;
    if (lineEndAt(text, digitsEnd, size)) return true;
    if (!isPlainBlank(text[digitsEnd])) return false;
    std::uint32_t next = digitsEnd;
    while (next < size && isPlainBlank(text[next]))
        ++next;
    if (lineEndAt(text, next, size)) return true;
    const char c = text[next];
    return c != '/' && c != ':' && c != '.' && c != '\r';  // the general prefix takes these
}

/// Where the line whose words stopped at `stop` ends: `end` (without a
/// final '\r') and `newline` (its '\n', or `size`).
void findLineEnd(const char* text, std::uint32_t stop, std::uint32_t size, std::uint32_t& end,
                 std::uint32_t& newline) {
    if (lineEndAt(text, stop, size)) {
        end = stop;
        newline = stop < size && text[stop] == '\r' ? stop + 1 : stop;
        return;
    }
    const void* found = std::memchr(text + stop, '\n', size - stop);
    newline = found ? static_cast<std::uint32_t>(static_cast<const char*>(found) - text) : size;
    end = newline;
    if (text[end - 1] == '\r') --end;  // end > stop: the line does not end at stop
}

/// The digits of a number as the common case reads them: before and after
/// one point, stopped by any other byte.
struct PlainNumber {
    std::uint64_t mantissa = 0;  // wraps for a long run of digits: then unused
    std::uint32_t digits = 0;
    unsigned scale = 0;
};

PlainNumber scanDigits(const unsigned char* text, std::uint32_t& pos) {
    PlainNumber number;
    std::uint32_t p = pos;
    for (unsigned digit = 0; (digit = text[p] - static_cast<unsigned>('0')) <= 9; ++p)
        number.mantissa = number.mantissa * 10 + digit;
    number.digits = p - pos;
    if (text[p] == '.') {
        const std::uint32_t decimals = ++p;
        for (unsigned digit = 0; (digit = text[p] - static_cast<unsigned>('0')) <= 9; ++p)
            number.mantissa = number.mantissa * 10 + digit;
        number.scale = p - decimals;
        number.digits += number.scale;
    }
    pos = p;
    return number;
}

/// A plain word up to its value: address letter, table entry, sign, column.
struct WordStart {
    WordKind kind;
    char letter;
    std::uint8_t address;
    bool negative;
    std::uint32_t column;
};

/// The number of `word` at `value` by the rules themselves (scanNumberAt,
/// normalizeNumber, tryPushNumber) for what the common case leaves: more
/// than nine digits, more than seven decimals, a second point, a sign or
/// decimals on a whole-number word, no digits. Appends the word and sets
/// `after` when the fast path takes it; false otherwise.
bool takeNumber(WordList& words, const char* text, std::uint32_t value, std::uint32_t end,
                const WordStart& word, std::uint32_t& after) {
    NumberText number;
    after = value;
    if (!scanPlainNumber(text, value, end, number, after))
        after = Lexer::scanNumberAt(text, value, end, number);
    if (after == value || (after < end && text[after] == '.') || !number.exact) return false;
    std::int64_t mantissa = number.mantissa;
    unsigned scale = number.scale;
    // normalizeNumber changes and refuses nothing for a number of at most
    // 7 decimals below 2^31 unless its word needs a whole number and it
    // is negative or has decimals: its branches are skipped then.
    const bool normalize = (scale > 7) | (mantissa > 2147483647) |
                           (((word.address & kWhole) != 0) & (word.negative | (scale != 0)));
    if (normalize && normalizeNumber(word.kind, word.negative, mantissa, scale) != NumberCheck::Ok)
        return false;
    return words.tryPushNumber(word.kind, word.letter, 0, word.column,
                               word.negative ? -mantissa : mantissa, scale);
}

}  // namespace

bool BlockParser::parseLine(std::uint32_t begin, std::uint32_t line, std::uint32_t& newline) {
    const char* text = text_.data();
    const auto size = static_cast<std::uint32_t>(text_.size());
    std::int32_t number = -1, subNumber = -1;
    std::uint32_t pos = begin;
    if (text[begin] == 'N') {
        if (!lineBlockNumberAt(text, begin, size, number, subNumber, pos)) return false;
    } else if (!(kAddressTable.entry[static_cast<unsigned char>(text[begin])] & kAddress)) {
        return false;
    }
    if (!context_.macros().empty()) {  // parse() asks for a macro before any word
        if (subNumber >= 0) return false;
        const MacroLine macro = takeMacroLine(begin, pos, line, number, newline);
        if (macro != MacroLine::NoMacro) return macro == MacroLine::Taken;
    }
    const auto firstWord = static_cast<std::uint32_t>(program_.words.size());
    std::uint32_t stop = scanPlainWords(pos, size, begin);
    std::uint32_t end = stop;
    findLineEnd(text, stop, size, end, newline);
    if (newline < size && text[newline + 1] == ' ') {  // the next line may continue the block
        program_.words.truncate(firstWord);
        return false;
    }
    if (stop != end) stop = takeCornerWord(stop, end, begin, firstWord);
    if (stop != end) {
        finishLine(BlockSource{begin, end, line, 1}, number, subNumber, firstWord, stop);
        return true;
    }
    // every word taken: the block is stored without the general path's Block
    const auto words = static_cast<std::uint16_t>(program_.words.size() - firstWord);
    if (subNumber >= 0 ||
        !program_.blocks.tryPushPlain(firstWord, words, static_cast<std::int16_t>(number), line,
                                      begin, end - begin)) {
        Block block;  // as startBlock and finish make it
        block.firstWord = firstWord;
        block.wordCount = words;
        block.number = number;
        if (subNumber >= 0) block.subNumber = static_cast<std::int16_t>(subNumber);
        block.line = line;
        block.lineCount = 1;
        block.sourceText = TextSpan{begin, end - begin};
        program_.blocks.push_back(block);
    }
    return true;
}

std::uint32_t BlockParser::takeCornerWord(std::uint32_t stop, std::uint32_t end,
                                          std::uint32_t lineBegin, std::uint32_t firstWord) {
    static const bool commands =  // (they are: the general path would read them so)
        lookupKeyword("CF").keywordClass == KeywordClass::CompilerCommand &&
        lookupKeyword("RD").keywordClass == KeywordClass::CompilerCommand;
    const char* text = text_.data();
    if (end - stop < 3 || !commands ||
        !((text[stop] == 'C' && text[stop + 1] == 'F') ||
          (text[stop] == 'R' && text[stop + 1] == 'D')))
        return stop;
    std::uint32_t token = stop + 2;  // the value, as skipRawToken reads it
    while (token < end && (digitValue(text[token]) <= 9 || text[token] == '.'))
        ++token;
    std::uint32_t after = token;
    while (after < end && isPlainBlank(text[after]))
        ++after;
    if (token == stop + 2 || after != end || program_.words.size() - firstWord >= kMaxWords)
        return stop;
    Word word;  // parseCommand's word
    word.kind = WordKind::Command;
    word.flags = kWordNeedsCompiler;
    word.column = static_cast<std::uint16_t>(std::min<std::uint32_t>(stop - lineBegin + 1, 65535));
    word.text = TextSpan{stop, token - stop};
    word.args = TextSpan{stop + 2, token - stop - 2};
    program_.words.push_back(word);
    program_.usesCompilerKeywords = true;
    return end;
}

BlockParser::MacroLine BlockParser::takeMacroLine(std::uint32_t begin, std::uint32_t pos,
                                                  std::uint32_t line, std::int32_t number,
                                                  std::uint32_t& newline) {
    const char* text = text_.data();
    const auto size = static_cast<std::uint32_t>(text_.size());
    const void* found = std::memchr(text + pos, '\n', size - pos);
    newline = found ? static_cast<std::uint32_t>(static_cast<const char*>(found) - text) : size;
    std::uint32_t end = newline;  // as the line scanner ends the line
    if (end > begin && text[end - 1] == '\r') --end;
    if (newline < size && text[newline + 1] == ' ') return MacroLine::General;  // may continue
    const void* semicolon = std::memchr(text + pos, ';', end - pos);
    const std::uint32_t comment =
        semicolon ? static_cast<std::uint32_t>(static_cast<const char*>(semicolon) - text) : end;
    if (!wordsUseMacro(pos, end, comment)) return MacroLine::NoMacro;
    if (comment != end) return MacroLine::General;
    // emitMacroBlock's word and finish's block
    std::uint32_t start = pos;
    while (start < end && Lexer::isBlank(static_cast<unsigned char>(text[start])))
        ++start;
    Word word;
    word.kind = WordKind::Command;
    word.flags = kWordNeedsCompiler;
    word.column = static_cast<std::uint16_t>(std::min<std::uint32_t>(start - begin + 1, 65535));
    word.text = trimmedSpan(start, comment);
    word.args = word.text;
    const auto firstWord = static_cast<std::uint32_t>(program_.words.size());
    program_.words.push_back(word);
    program_.usesCompilerKeywords = true;
    if (!program_.blocks.tryPushPlain(firstWord, 1, static_cast<std::int16_t>(number), line, begin,
                                      end - begin)) {
        startBlock(BlockSource{begin, end, line, 1});
        block_.firstWord = firstWord;
        block_.number = number;
        finish();
    }
    return MacroLine::Taken;
}

void BlockParser::finishLine(const BlockSource& source, std::int32_t number, std::int32_t subNumber,
                             std::uint32_t firstWord, std::uint32_t stop) {
    startBlock(source);
    block_.firstWord = firstWord;
    block_.number = number;
    if (subNumber >= 0) block_.subNumber = static_cast<std::int16_t>(subNumber);
    lexer_.seek(stop);
    if (!lexer_.atEnd())
        while (parseNextWord()) {
        }
    finish();
}

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
    lexer_.seek(scanPlainWords(lexer_.position(), source_.end, source_.begin));
}

std::uint32_t BlockParser::scanPlainWords(std::uint32_t pos, const std::uint32_t end,
                                          const std::uint32_t lineBegin) {
    // The line ends at `end` with '\n', '\r' or the '\0' after the source:
    // no scan below passes a byte of these, so only axisIndexAt needs `end`.
    const char* const base = text_.data();
    const auto* text = reinterpret_cast<const unsigned char*>(base);
    // Words go straight into the list's free slots (all in locals: a store
    // through a member would make the compiler reload every member).
    WordList& words = program_.words;
    WordList::Packed* out = words.spareBegin();
    WordList::Packed* outEnd = words.spareEnd();
    std::uint8_t* columns = words.spareColumns();
    // The block has no words yet, and a word takes two bytes at least: up to
    // the last column the packed forms hold, the fast path takes fewer than
    // kMaxWords words (the general path reports PARSE_TOO_MANY_WORDS).
    static_assert(WordList::kMaxPackedColumn / 2 < kMaxWords);
    for (;;) {
        unsigned c = text[pos];
        while (c == ' ' || c == '\t')
            c = text[++pos];
        const std::uint8_t address = kAddressTable.entry[c];
        const std::uint32_t column = pos - lineBegin + 1;
        if (!(address & kAddress) || column > WordList::kMaxPackedColumn) break;
        std::uint32_t value = pos + 1;
        if ((address & kIndexed) && axisIndexAt(base, value, end) != 0) break;
        const bool negative = text[value] == '-';
        value += negative || text[value] == '+';
        std::uint32_t after = value;
        const PlainNumber number = scanDigits(text, after);
        // Up to nine digits, seven decimals, no sign or decimals on a whole-
        // number word: nothing to normalise; below 2^26, the narrow form
        // holds it once the list has a code for its letter and scale.
        if (number.digits - 1 < 9 && number.scale < 8 && text[after] != '.' &&
            !((address & kWhole) && (negative || number.scale != 0)) &&
            number.mantissa < WordList::kNarrowLimit) {
            WordList::Packed code = words.plainCodeAt(WordList::codeKey(c, number.scale));
            if (code == WordList::kWideCode)
                code = words.plainCode(static_cast<WordKind>(address & kKindBits),
                                       static_cast<char>(c), number.scale);
            if (code != WordList::kWideCode) {
                if (out == outEnd) {
                    words.endAt(out);
                    words.makeSpare();
                    out = words.spareBegin();
                    outEnd = words.spareEnd();
                    columns = words.spareColumns();
                }
                const auto unsignedMantissa = static_cast<std::int32_t>(number.mantissa);
                const std::int32_t mantissa = negative ? -unsignedMantissa : unsignedMantissa;
                // M02 / M30 (a jump word is never a plain number); the
                // letter first: one compare per word of the hot loop.
                if (c == 'M' && WordList::numberTurnsFlow(WordKind::M, mantissa, number.scale))
                    words.noteFlowTurning(out);
                *out++ = WordList::narrowSlot(code, mantissa);
                *columns++ = static_cast<std::uint8_t>(column);
                pos = after;
                continue;
            }
        }
        words.endAt(out);
        const WordStart word{static_cast<WordKind>(address & kKindBits), static_cast<char>(c),
                             address, negative, column};
        const bool taken = takeNumber(words, base, value, end, word, after);
        out = words.spareBegin();
        outEnd = words.spareEnd();
        columns = words.spareColumns();
        if (!taken) break;
        pos = after;
    }
    words.endAt(out);
    return pos;
}

}  // namespace mtc::core
