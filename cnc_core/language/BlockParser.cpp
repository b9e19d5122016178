#include "cnc_core/language/BlockParser.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cnc_core/language/ExpressionParser.h"
#include "cnc_core/language/WordRules.h"

namespace mtc::core {

using word_rules::addressKind;
using word_rules::axisIndexAt;
using word_rules::normalizeNumber;
using word_rules::NumberCheck;
using word_rules::valueMustBeWhole;

namespace {

/// Largest magnitude a written number may have (15 digits before the point).
constexpr double kMaxMagnitude = 1e15;

std::string describeChar(int c) {
    char buffer[48];
    if (c >= 0x20 && c < 0x7f)
        std::snprintf(buffer, sizeof buffer, "'%c'", c);
    else
        std::snprintf(buffer, sizeof buffer, "byte 0x%02X", static_cast<unsigned>(c) & 0xffu);
    return buffer;
}

}  // namespace

BlockParser::BlockParser(ParseContext& context)
    : context_(context),
      program_(context.program()),
      text_(context.source()),
      lexer_(text_, 0, 0),
      plainFastPath_(context.plainBlockFastPath()) {}

void BlockParser::startBlock(const BlockSource& source) {
    source_ = source;
    lexer_ = Lexer(text_, source.begin, source.end);
    block_ = Block{};
    block_.firstWord = static_cast<std::uint32_t>(program_.words.size());
    block_.line = source.line;
    block_.lineCount = source.lineCount;
    block_.sourceText = TextSpan{source.begin, source.end - source.begin};
    primarySeen_ = false;
}

void BlockParser::parse(const BlockSource& source) {
    startBlock(source);
    if (parsePrefix()) {
        if (!context_.macros().empty() && blockUsesMacro()) {
            emitMacroBlock();
        } else {
            if (source.lineCount == 1 && plainFastPath_) parsePlainWords();
            // (at the block end parseNextWord would only find it again)
            if (!lexer_.atEnd())
                while (parseNextWord()) {
                }
        }
    }
    finish();
}

void BlockParser::finish() {
    block_.wordCount = static_cast<std::uint16_t>(program_.words.size() - block_.firstWord);
    if (block_.comment.empty() && !block_.text.empty()) block_.comment = block_.text;
    auto index = static_cast<std::uint32_t>(program_.blocks.size());
    if (!block_.label.empty()) {
        auto [it, inserted] =
            program_.labels.emplace(std::string(program_.text(block_.label)), index);
        if (!inserted) {
            block_.flags |= kBlockHasError;
            context_.report(Severity::Error, "PARSE_DUPLICATE_LABEL", block_.line,
                            columnOf(block_.label.offset - 1), formatBlockId(block_.number),
                            "label ." + it->first + " already defined in line " +
                                std::to_string(program_.blocks[it->second].line));
        }
    }
    program_.blocks.push_back(block_);
}

// ---------------------------------------------------------------- prefix

bool BlockParser::parsePrefix() {
    // [/] [:] [Nxxxx[:yyyy]] [/] [:] [.LABEL] [:]  with at most one '/' and one
    // ':'; the skip slash stands before the colon (seed 000, 5.1: "N0003 /: ...").
    if (plainFastPath_ && (takePlainBlockNumber() || startsWithoutPrefix())) return true;
    takeSkip();
    takePrimary();
    if (lexer_.peek() == 'N' && Lexer::isDigit(lexer_.peek(1)) && !parseBlockNumber()) return false;
    if (!primarySeen_) takeSkip();
    takePrimary();
    if (lexer_.peek() == '.') {
        if (!parseBlockLabel()) return false;
        takePrimary();
    }
    if (primarySeen_) block_.flags |= kBlockPrimary;
    return true;
}

void BlockParser::takeSkip() {
    lexer_.skipBlanks();
    if (lexer_.peek() != '/' || (block_.flags & kBlockSkip)) return;
    block_.flags |= kBlockSkip;
    lexer_.advance();
    lexer_.skipBlanks();
}

void BlockParser::takePrimary() {
    lexer_.skipBlanks();
    if (lexer_.peek() != ':' || primarySeen_) return;
    primarySeen_ = true;
    lexer_.advance();
    lexer_.skipBlanks();
}

bool BlockParser::parseBlockNumber() {
    const std::uint32_t start = lexer_.position();
    const word_rules::BlockNumberDigits digits =
        word_rules::blockNumberDigitsAt(text_.data(), start + 1, lexer_.end());  // after 'N'
    lexer_.seek(digits.end);
    if (digits.count > word_rules::kBlockNumberDigits || lexer_.peek() == '.') {
        return error("PARSE_BAD_BLOCK_NUMBER", start,
                     "block number must be 'N' and four digits (N0000..N9999)");
    }
    block_.number = static_cast<std::int32_t>(digits.value);
    if (digits.count < word_rules::kBlockNumberDigits)
        warning("PARSE_SHORT_BLOCK_NUMBER", start,
                "block number should have four digits (" + formatBlockId(block_.number) + ")");
    // Compiled programs: "N0053:0001" (colon directly followed by 4 digits).
    if (lexer_.peek() == ':' && Lexer::isDigit(lexer_.peek(1)) && Lexer::isDigit(lexer_.peek(2)) &&
        Lexer::isDigit(lexer_.peek(3)) && Lexer::isDigit(lexer_.peek(4)) &&
        !Lexer::isDigit(lexer_.peek(5))) {
        int sub = 0;
        for (std::uint32_t i = 1; i <= 4; ++i)
            sub = sub * 10 + (lexer_.peek(i) - '0');
        block_.subNumber = static_cast<std::int16_t>(sub);
        lexer_.advance(5);
    }
    return true;
}

bool BlockParser::parseBlockLabel() {
    std::uint32_t start = lexer_.position();
    lexer_.advance();  // '.'
    std::string_view name = lexer_.scanLabelName();
    if (name.empty())
        return error("PARSE_MISSING_LABEL_NAME", start, "'.' must be followed by a label name");
    int next = lexer_.peek();
    if (!(next < 0 || Lexer::isBlank(next) || next == ';' || next == ':' || next == '(' ||
          next == '['))
        return error("PARSE_BAD_LABEL", lexer_.position(),
                     describeChar(next) + " is not allowed in a label (letters, digits, _ and *)");
    block_.label = TextSpan{start + 1, static_cast<std::uint32_t>(name.size())};
    return true;
}

// ---------------------------------------------------------------- words

bool BlockParser::parseNextWord() {
    lexer_.skipBlanks();
    if (lexer_.atEnd()) return false;
    std::uint32_t start = lexer_.position();
    int c = lexer_.peek();
    if (Lexer::isUpper(c)) {
        int next = lexer_.peek(1);
        if (!Lexer::isUpper(next) && next != '_') {  // fast path: address letter
            lexer_.advance();
            return parseAddress(static_cast<char>(c), start);
        }
        std::string_view name = lexer_.scanIdentifier();
        if (name.size() == 1) return parseAddress(name[0], start);
        return parseKeyword(name, start);
    }
    switch (c) {
        case ';':
            return parseComment(start);
        case '@':
            return parseAssignment(start);
        case '(':
            return parseText('(', ')', start);
        case '[':
            return parseText('[', ']', start);
        case ')':
        case ']':
            return error("PARSE_UNBALANCED_PARENTHESES", start,
                         describeChar(c) + " without a matching opening bracket");
        case '.':
            if (Lexer::isDigit(lexer_.peek(1)))
                return error("PARSE_UNEXPECTED_NUMBER", start, "value without an address letter");
            return error("PARSE_MISPLACED_LABEL", start,
                         "a label must stand at the start of the block (after the block number)");
        case ':':
            return error("PARSE_MISPLACED_PRIMARY", start,
                         "':' (primary block) must stand at the start of the block");
        case '/':
            return error("PARSE_MISPLACED_SKIP", start,
                         "'/' (skip block) must stand at the start of the block or after the "
                         "block number, before ':' (seed 000, 5.1)");
        default:
            break;
    }
    bool number =
        Lexer::isDigit(c) || (c == '.' && Lexer::isDigit(lexer_.peek(1))) ||
        ((c == '-' || c == '+') && (Lexer::isDigit(lexer_.peek(1)) || lexer_.peek(1) == '.'));
    if (number) return error("PARSE_UNEXPECTED_NUMBER", start, "value without an address letter");
    if (c == '-' || c == '+' || c == '*' || c == '=' || c == ',')
        return error("PARSE_UNEXPECTED_CHARACTER", start, describeChar(c) + " cannot start a word");
    if (c >= 'a' && c <= 'z')
        return error("LEX_BAD_CHAR", start,
                     describeChar(c) + ": NC words are written in capital letters");
    return error("LEX_BAD_CHAR", start, describeChar(c) + " is not part of the NC language");
}

bool BlockParser::parseAddress(char letter, std::uint32_t start) {
    WordKind kind = WordKind::Axis;
    bool indexed = false;
    if (!addressKind(letter, kind, indexed)) {
        if (letter == 'N')
            return error("PARSE_MISPLACED_BLOCK_NUMBER", start,
                         "the block number must be the first word of the block");
        return error("PARSE_UNKNOWN_WORD", start,
                     std::string("'") + letter + "' is not an NC address letter");
    }
    std::uint8_t index = indexed ? scanAxisIndex() : 0;
    return parseValue(kind, letter, index, start);
}

std::uint8_t BlockParser::scanAxisIndex() {
    std::uint8_t index = axisIndexAt(text_.data(), lexer_.position(), lexer_.end());
    if (index) lexer_.advance();
    return index;
}

bool BlockParser::parseValue(WordKind kind, char letter, std::uint8_t index, std::uint32_t start) {
    lexer_.skipBlanks();
    int c = lexer_.peek();
    if (c == '=') {
        lexer_.advance();
        Word word;
        word.kind = kind;
        word.letter = letter;
        word.axisIndex = index;
        return parseExpressionValue(word, start);
    }
    bool negative = c == '-';
    if (c == '-' || c == '+') {
        lexer_.advance();
        c = lexer_.peek();
    }
    if (Lexer::isDigit(c) || (c == '.' && Lexer::isDigit(lexer_.peek(1))))
        return parseNumberValue(kind, letter, index, start, negative);
    if (c == '@') {
        std::size_t firstNode = program_.expressions.size();
        ExpressionParser expressions(lexer_, program_.expressions, text_);
        std::int32_t node = expressions.parseVariable();
        if (node >= 0 && negative) {
            ExprNode negate;
            negate.op = ExprOp::Negate;
            negate.a = node;
            program_.expressions.push_back(negate);
            node = static_cast<std::int32_t>(program_.expressions.size() - 1);
        }
        if (node < 0) {
            program_.expressions.resize(firstNode);
            return error(expressions.error().code, expressions.error().offset,
                         expressions.error().message);
        }
        Word word;
        word.kind = kind;
        word.letter = letter;
        word.axisIndex = index;
        word.expr = node;
        word.column = static_cast<std::uint16_t>(columnOf(start));
        return addWord(word);
    }
    std::string name = kind == WordKind::EffectiveRadius ? "RI" : std::string(1, letter);
    if (index) name += static_cast<char>('0' + index);
    return error("PARSE_MISSING_VALUE", start, "'" + name + "' needs a value");
}

bool BlockParser::parseNumberValue(WordKind kind, char letter, std::uint8_t index,
                                   std::uint32_t start, bool negative) {
    NumberText number;
    std::uint32_t numberStart = lexer_.position();
    lexer_.scanNumber(number);
    if (lexer_.peek() == '.')
        return error("PARSE_BAD_NUMBER", numberStart, "number with two decimal points");
    std::int64_t mantissa = number.mantissa;
    unsigned scale = number.scale;
    switch (normalizeNumber(kind, negative, mantissa, scale)) {
        case NumberCheck::NegativeWhole:
            return error("PARSE_BAD_NUMBER", numberStart,
                         std::string("'") + letter + "' needs a positive whole number");
        case NumberCheck::NotWhole:
            return error("PARSE_BAD_NUMBER", numberStart,
                         std::string("'") + letter + "' needs a whole number");
        case NumberCheck::Ok:
            break;
    }
    std::uint32_t column = columnOf(start);
    if (number.exact && program_.words.size() - block_.firstWord < kMaxWords &&
        program_.words.tryPushNumber(kind, letter, index, column, negative ? -mantissa : mantissa,
                                     scale))
        return true;
    double value = number.value(text_);
    if (!(std::fabs(value) < kMaxMagnitude))
        return error("PARSE_BAD_NUMBER", numberStart, "number out of range");
    Word word;
    word.kind = kind;
    word.letter = letter;
    word.axisIndex = index;
    word.number = negative ? -value : value;
    word.column = static_cast<std::uint16_t>(column > 65535 ? 65535 : column);
    return addWord(word);
}

bool BlockParser::parseExpressionValue(Word& word, std::uint32_t start) {
    std::size_t firstNode = program_.expressions.size();
    ExpressionParser expressions(lexer_, program_.expressions, text_);
    std::int32_t node = expressions.parse();
    if (node < 0) {
        program_.expressions.resize(firstNode);
        return error(expressions.error().code, expressions.error().offset,
                     expressions.error().message);
    }
    return finishSimpleValue(word, node, start);
}

bool BlockParser::finishSimpleValue(Word& word, std::int32_t node, std::uint32_t start) {
    // A constant (or a negated constant) needs no expression nodes.
    auto& nodes = program_.expressions;
    const ExprNode& root = nodes[static_cast<std::size_t>(node)];
    bool constant = root.op == ExprOp::Constant;
    bool negated =
        root.op == ExprOp::Negate && nodes[static_cast<std::size_t>(root.a)].op == ExprOp::Constant;
    if ((constant || negated) && static_cast<std::size_t>(node) + 1 == nodes.size()) {
        double value = constant ? root.value : -nodes[static_cast<std::size_t>(root.a)].value;
        nodes.resize(static_cast<std::size_t>(constant ? node : root.a));
        if (valueMustBeWhole(word.kind) && (value < 0 || value != std::floor(value)))
            return error("PARSE_BAD_NUMBER", start,
                         std::string("'") + word.letter + "' needs a positive whole number");
        word.number = value;
        word.expr = -1;
    } else {
        word.expr = node;
    }
    word.column = static_cast<std::uint16_t>(std::min<std::uint32_t>(columnOf(start), 65535));
    return addWord(word);
}

bool BlockParser::parseAssignment(std::uint32_t start) {
    std::size_t firstNode = program_.expressions.size();
    ExpressionParser expressions(lexer_, program_.expressions, text_);
    std::int32_t target = expressions.parseVariable();
    if (target < 0) {
        program_.expressions.resize(firstNode);
        return error(expressions.error().code, expressions.error().offset,
                     expressions.error().message);
    }
    lexer_.skipBlanks();
    if (lexer_.peek() != '=') {
        program_.expressions.resize(firstNode);
        return error("PARSE_EXPECTED_ASSIGNMENT", lexer_.position(),
                     "a variable in a block must be assigned: @n=value");
    }
    lexer_.advance();
    std::int32_t value = expressions.parse();
    if (value < 0) {
        program_.expressions.resize(firstNode);
        return error(expressions.error().code, expressions.error().offset,
                     expressions.error().message);
    }
    Word word;
    word.kind = WordKind::Assign;
    word.target = target;
    return finishSimpleValue(word, value, start);
}

bool BlockParser::parseMtdAssignment(std::uint32_t start) {
    std::size_t firstNode = program_.expressions.size();
    ExpressionParser expressions(lexer_, program_.expressions, text_);
    std::int32_t target = expressions.parseMtdArguments(start);
    std::int32_t value = -1;
    if (target >= 0) {
        lexer_.skipBlanks();
        if (lexer_.peek() != '=') {
            program_.expressions.resize(firstNode);
            return error("PARSE_EXPECTED_ASSIGNMENT", start,
                         "MTD(...) in a block must be assigned: MTD(...)=value");
        }
        lexer_.advance();
        value = expressions.parse();
    }
    if (value < 0) {
        program_.expressions.resize(firstNode);
        return error(expressions.error().code, expressions.error().offset,
                     expressions.error().message);
    }
    Word word;
    word.kind = WordKind::AssignMTD;
    word.target = target;
    return finishSimpleValue(word, value, start);
}

bool BlockParser::parseText(char open, char close, std::uint32_t start) {
    if (!lexer_.skipBalanced(open, close))
        return error("PARSE_UNBALANCED_TEXT", start,
                     std::string("text started with '") + open + "' is not closed with '" + close +
                         "' in this block");
    if (block_.text.empty()) block_.text = TextSpan{start + 1, lexer_.position() - start - 2};
    return true;
}

bool BlockParser::parseComment(std::uint32_t start) {
    block_.comment = trimmedSpan(start + 1, source_.end);
    lexer_.seek(source_.end);
    return false;
}

// ---------------------------------------------------------------- helpers

bool BlockParser::addWord(const Word& word) {
    if (program_.words.size() - block_.firstWord >= kMaxWords)
        return error("PARSE_TOO_MANY_WORDS", lexer_.position(),
                     "more than 65535 words in one block");
    program_.words.push_back(word);
    if (word.flags & kWordNeedsCompiler) program_.usesCompilerKeywords = true;
    return true;
}

bool BlockParser::error(const char* code, std::uint32_t offset, std::string message) {
    block_.flags |= kBlockHasError;
    context_.report(Severity::Error, code, lineOf(offset), columnOf(offset),
                    formatBlockId(block_.number, block_.subNumber), std::move(message));
    // Keep the block's comment for display even though its words are skipped.
    std::uint32_t semicolon = commentStart();
    if (block_.comment.empty() && semicolon < source_.end)
        block_.comment = trimmedSpan(semicolon + 1, source_.end);
    lexer_.seek(source_.end);
    return false;
}

void BlockParser::warning(const char* code, std::uint32_t offset, std::string message) {
    context_.report(Severity::Warning, code, lineOf(offset), columnOf(offset),
                    formatBlockId(block_.number, block_.subNumber), std::move(message));
}

std::uint32_t BlockParser::lineOf(std::uint32_t offset) const {
    std::uint32_t line = source_.line;
    if (source_.lineCount > 1)
        for (std::uint32_t i = source_.begin; i < offset && i < source_.end; ++i)
            if (text_[i] == '\n') ++line;
    return line;
}

std::uint32_t BlockParser::columnOf(std::uint32_t offset) const {
    std::uint32_t lineStart = source_.begin;
    if (source_.lineCount > 1)
        for (std::uint32_t i = offset; i > source_.begin; --i)
            if (text_[i - 1] == '\n') {
                lineStart = i;
                break;
            }
    return offset - lineStart + 1;
}

TextSpan BlockParser::trimmedSpan(std::uint32_t begin, std::uint32_t end) const {
    while (begin < end && Lexer::isBlank(static_cast<unsigned char>(text_[begin])))
        ++begin;
    while (end > begin && Lexer::isBlank(static_cast<unsigned char>(text_[end - 1])))
        --end;
    return TextSpan{begin, end - begin};
}

}  // namespace mtc::core
