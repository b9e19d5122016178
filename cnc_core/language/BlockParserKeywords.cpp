// Keyword words of a block: jumps, NC commands, compiler keywords, DEFINE
// macros and PROGRAMMENDE. Part of BlockParser (see BlockParser.h).
#include <algorithm>
#include <cstring>
#include <limits>

#include "cnc_core/language/BlockParser.h"
#include "cnc_core/language/ExpressionParser.h"

namespace mtc::core {

namespace {

constexpr std::uint32_t kNotFound = std::numeric_limits<std::uint32_t>::max();
constexpr std::size_t kMaxMacroName = 20;  // seed 001, ch. 4

/// `name` for a message, cut to 32 characters.
std::string shortened(std::string_view name) {
    std::string shown(name.substr(0, 32));
    if (name.size() > 32) shown += "...";
    return shown;
}

/// A-Z 0-9 _ as a table: the macro name scan reads every character of a
/// block that may use a macro.
struct NameChars {
    bool is[256];
};

constexpr NameChars makeNameChars() {
    NameChars table{};
    for (int c = 0; c < 256; ++c)
        table.is[c] = (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
    return table;
}

constexpr NameChars kNameChars = makeNameChars();

bool isNameChar(char c) {
    return kNameChars.is[static_cast<unsigned char>(c)];
}

/// Offset of the first name in [begin, end) that is a defined macro (names:
/// runs of A-Z 0-9 _ starting with a letter; label names after '.' and
/// variables after '@' do not count), or kNotFound. Only a letter some
/// macro starts with can start one: the scan stops at those and skips the
/// ones inside a run (a run starts at `begin` or after a byte that is no
/// name character).
std::uint32_t findMacroUse(std::string_view text, std::uint32_t begin, std::uint32_t end,
                           const ParseContext& context) {
    const std::uint32_t letters = context.macroLetters();
    for (std::uint32_t i = begin; i < end; ++i) {
        const unsigned letter = static_cast<unsigned char>(text[i]) - 'A';
        if (letter >= 26 || !((letters >> letter) & 1u)) continue;
        if (i != begin && isNameChar(text[i - 1])) continue;  // inside a run
        const std::uint32_t start = i;
        while (i + 1 < end && isNameChar(text[i + 1]))
            ++i;
        const char before = start > 0 ? text[start - 1] : ' ';
        if (before != '.' && before != '*' && context.isMacro(text.substr(start, i + 1 - start)))
            return start;
    }
    return kNotFound;
}

/// "MQ" / "QQ" alone or followed by digits only (the value's first digits
/// were read into the identifier): a swift auxiliary function.
bool isSwiftAuxName(std::string_view name) {
    if (name.size() < 2 || (name[0] != 'M' && name[0] != 'Q') || name[1] != 'Q') return false;
    for (std::size_t i = 2; i < name.size(); ++i)
        if (name[i] < '0' || name[i] > '9') return false;
    return true;
}

}  // namespace

bool BlockParser::parseKeyword(std::string_view name, std::uint32_t start) {
    KeywordInfo info = lookupKeyword(name);
    switch (info.keywordClass) {
        case KeywordClass::Jump:
            return parseJump(info.jump, start);
        case KeywordClass::Command:
            return parseCommand(false, start);
        case KeywordClass::CompilerCommand:
        case KeywordClass::AxisFeed:
            return parseCommand(true, start);
        case KeywordClass::CompilerRestOfBlock:
            return parseRestOfBlock(name, start);
        case KeywordClass::EffectiveRadius:
            return parseValue(WordKind::EffectiveRadius, 0, 0, start);
        case KeywordClass::Mtd:
            return parseMtdAssignment(start);
        case KeywordClass::ReadOnly:
            return error("PARSE_READ_ONLY_WORD", start,
                         std::string(name) + " can only be read in an expression (e.g. @1=" +
                             shortened(name) + ")");
        case KeywordClass::ProgramEnd:
            return parseProgramEnd(start);
        case KeywordClass::None:
            break;
    }
    if (isSwiftAuxName(name)) return parseSwiftAux(name, start);
    return error("PARSE_UNKNOWN_WORD", start, "unknown word '" + shortened(name) + "'");
}

bool BlockParser::parseSwiftAux(std::string_view name, std::uint32_t start) {
    lexer_.seek(start + 2);  // the value follows "MQ" / "QQ" like after M / Q
    const std::size_t before = program_.words.size();
    const bool m = name[0] == 'M';
    if (!parseValue(m ? WordKind::M : WordKind::Q, name[0], 0, start)) return false;
    if (program_.words.size() != before + 1) return true;
    Word word = program_.words.back();
    word.flags |= kWordSwift;
    program_.words.set(before, word);
    return true;
}

// ---------------------------------------------------------------- jumps

bool BlockParser::parseJump(JumpKind kind, std::uint32_t start) {
    Word word;
    word.kind = WordKind::Jump;
    word.jump = kind;
    word.column = static_cast<std::uint16_t>(std::min<std::uint32_t>(columnOf(start), 65535));
    bool ok = true;
    switch (kind) {
        case JumpKind::BST:
        case JumpKind::RET:
        case JumpKind::RTS:
            break;
        case JumpKind::JSR:
        case JumpKind::JMP:
            ok = parseProgramReference(word, start);
            break;
        case JumpKind::JEV:
            ok = parseProgramReference(word, start) && parseEvent(word, start);
            break;
        case JumpKind::BES:
        case JumpKind::BER:
        case JumpKind::BEV:
            ok = parseJumpLabel(word, start) && parseEvent(word, start);
            break;
        default:
            ok = parseJumpLabel(word, start);
            break;
    }
    return ok && addWord(word);
}

bool BlockParser::parseJumpLabel(Word& word, std::uint32_t start) {
    lexer_.skipBlanks();
    std::uint32_t dot = lexer_.position();
    if (lexer_.peek() != '.')
        return error("PARSE_MISSING_LABEL", start,
                     std::string(jumpName(word.jump)) + " needs a jump label (.NAME)");
    lexer_.advance();
    std::string_view name = lexer_.scanLabelName();
    if (name.empty())
        return error("PARSE_MISSING_LABEL_NAME", dot, "'.' must be followed by a label name");
    int next = lexer_.peek();
    if (!(next < 0 || Lexer::isBlank(next) || next == ';' || next == '(' || next == '['))
        return error("PARSE_BAD_LABEL", lexer_.position(),
                     "label names consist of letters, digits, '_' and '*'");
    word.text = TextSpan{dot + 1, static_cast<std::uint32_t>(name.size())};
    return true;
}

bool BlockParser::parseEvent(Word& word, std::uint32_t start) {
    // "p:e": process and event number, e.g. "1:15".
    lexer_.skipBlanks();
    std::uint32_t at = lexer_.position();
    NumberText process, event;
    if (!Lexer::isDigit(lexer_.peek()))
        return error(
            "PARSE_MISSING_EVENT", start,
            std::string(jumpName(word.jump)) + " needs an event 'process:event' (e.g. 1:15)");
    lexer_.scanNumber(process);
    if (lexer_.peek() != ':' || !Lexer::isDigit(lexer_.peek(1)))
        return error("PARSE_BAD_EVENT", at, "event must be written 'process:event' (e.g. 1:15)");
    lexer_.advance();
    lexer_.scanNumber(event);
    if (process.scale || event.scale || !process.exact || !event.exact ||
        process.mantissa > 32767 || event.mantissa > 32767 || text_[process.end - 1] == '.' ||
        text_[event.end - 1] == '.')
        return error("PARSE_BAD_EVENT", at, "event numbers must be whole numbers up to 32767");
    word.eventProcess = static_cast<std::int16_t>(process.mantissa);
    word.eventNumber = static_cast<std::int16_t>(event.mantissa);
    return true;
}

bool BlockParser::parseProgramReference(Word& word, std::uint32_t start) {
    lexer_.skipBlanks();
    std::uint32_t at = lexer_.position();
    if (lexer_.peek() == '@') {
        ExpressionParser expressions(lexer_, program_.expressions, text_);
        word.expr = expressions.parseVariable();
        if (word.expr < 0)
            return error(expressions.error().code, expressions.error().offset,
                         expressions.error().message);
        return true;
    }
    NumberText number;
    if (!Lexer::isDigit(lexer_.peek()))
        return error("PARSE_MISSING_PROGRAM", start,
                     std::string(jumpName(word.jump)) + " needs a program number or a variable");
    lexer_.scanNumber(number);
    if (number.scale || !number.exact || number.mantissa > 999999 || text_[number.end - 1] == '.')
        return error("PARSE_BAD_NUMBER", at, "program number must be a whole number");
    word.number = static_cast<double>(number.mantissa);
    return true;
}

// ---------------------------------------------------------------- commands

bool BlockParser::parseCommand(bool compiler, std::uint32_t start) {
    std::uint32_t keywordEnd = lexer_.position();
    if (!scanCommandArguments())
        return error("PARSE_UNBALANCED_PARENTHESES", start,
                     "an argument bracket of this command is not closed in the block");
    Word word;
    word.kind = WordKind::Command;
    word.column = static_cast<std::uint16_t>(std::min<std::uint32_t>(columnOf(start), 65535));
    word.text = trimmedSpan(start, lexer_.position());
    word.args = trimmedSpan(keywordEnd, lexer_.position());
    if (compiler) word.flags |= kWordNeedsCompiler;
    return addWord(word);
}

bool BlockParser::scanCommandArguments() {
    // Raw arguments: bracket groups "(…)" "[…]", an attached token ("CF2",
    // "FZ1=4500"), a blank-separated numeric token ("RD 2", "WES 1:5") and
    // a final "= value" (value operators may be surrounded by blanks).
    for (;;) {
        std::uint32_t save = lexer_.position();
        bool blank = lexer_.skipBlanks();
        int c = lexer_.peek();
        if (c == '(' || c == '[') {
            if (!lexer_.skipBalanced(static_cast<char>(c), c == '(' ? ')' : ']')) return false;
        } else if (c == '=') {
            lexer_.advance();
            lexer_.skipBlanks();
            if (!lexer_.skipRawToken()) return false;
            for (;;) {
                std::uint32_t afterValue = lexer_.position();
                lexer_.skipBlanks();
                int op = lexer_.peek();
                if (op != '+' && op != '-' && op != '*' && op != '/') {
                    lexer_.seek(afterValue);
                    return true;
                }
                lexer_.advance();
                lexer_.skipBlanks();
                if (!lexer_.skipRawToken()) return false;
            }
        } else if (c >= 0 && c != ';' &&
                   (!blank || Lexer::isDigit(c) || c == '@' || c == '-' || c == '+' || c == '.')) {
            if (!lexer_.skipRawToken()) return false;
        } else {
            lexer_.seek(save);
            return true;
        }
    }
}

std::uint32_t BlockParser::commentStart() const {
    const std::uint32_t from = std::min(lexer_.position(), source_.end);
    const void* found = std::memchr(text_.data() + from, ';', source_.end - from);
    return found ? static_cast<std::uint32_t>(static_cast<const char*>(found) - text_.data())
                 : source_.end;
}

bool BlockParser::parseRestOfBlock(std::string_view name, std::uint32_t start) {
    std::uint32_t keywordEnd = lexer_.position();
    std::uint32_t end = commentStart();
    Word word;
    word.kind = WordKind::Command;
    word.flags = kWordNeedsCompiler;
    word.column = static_cast<std::uint16_t>(std::min<std::uint32_t>(columnOf(start), 65535));
    word.text = trimmedSpan(start, end);
    word.args = trimmedSpan(keywordEnd, end);
    if (name == "DEFINE" && !checkDefine(word.args.offset, word.args.offset + word.args.length))
        return false;
    lexer_.seek(end);
    return addWord(word);
}

bool BlockParser::checkDefine(std::uint32_t argsBegin, std::uint32_t argsEnd) {
    // DEFINE <name> AS <instructions>  (seed 001, ch. 4)
    std::uint32_t i = argsBegin;
    while (i < argsEnd && isNameChar(text_[i]))
        ++i;
    std::string_view name = text_.substr(argsBegin, i - argsBegin);
    std::uint32_t as = i;
    while (as < argsEnd && Lexer::isBlank(static_cast<unsigned char>(text_[as])))
        ++as;
    bool hasAs = as + 2 <= argsEnd && text_.substr(as, 2) == "AS" &&
                 (as + 2 == argsEnd || Lexer::isBlank(static_cast<unsigned char>(text_[as + 2])));
    std::uint32_t body = hasAs ? as + 2 : argsEnd;
    while (body < argsEnd && Lexer::isBlank(static_cast<unsigned char>(text_[body])))
        ++body;
    if (name.empty() || !(name[0] >= 'A' && name[0] <= 'Z') || !hasAs || body >= argsEnd ||
        (i < argsEnd && !Lexer::isBlank(static_cast<unsigned char>(text_[i]))))
        return error("PARSE_BAD_DEFINE", argsBegin,
                     "macro definition: DEFINE <name> AS <instructions>");
    if (name.size() > kMaxMacroName)
        return error("PARSE_MACRO_NAME_TOO_LONG", argsBegin,
                     "macro name longer than 20 characters: " + shortened(name));
    if (lookupKeyword(name).keywordClass != KeywordClass::None)
        return error("PARSE_MACRO_REDEFINES_KEYWORD", argsBegin,
                     "a keyword cannot be redefined by a macro: " + std::string(name));
    context_.addMacro(name);  // so that a self-reference counts as nesting
    std::uint32_t nested = findMacroUse(text_, body, argsEnd, context_);
    if (nested != kNotFound)
        return error("PARSE_NESTED_MACRO", nested,
                     "macros must not be nested (macro used in the "
                     "instructions of macro " +
                         shortened(name) + ")");
    return true;
}

bool BlockParser::blockUsesMacro() const {
    return wordsUseMacro(lexer_.position(), source_.end, commentStart());
}

bool BlockParser::wordsUseMacro(std::uint32_t begin, std::uint32_t end,
                                std::uint32_t comment) const {
    while (begin < end && Lexer::isBlank(static_cast<unsigned char>(text_[begin])))
        ++begin;
    if (text_.substr(begin, 6) == "DEFINE") return false;
    return findMacroUse(text_, begin, comment, context_) != kNotFound;
}

void BlockParser::emitMacroBlock() {
    // The compiler replaces macro names by their instructions; the block is
    // kept whole as one compiler command.
    lexer_.skipBlanks();
    std::uint32_t end = commentStart();
    Word word;
    word.kind = WordKind::Command;
    word.flags = kWordNeedsCompiler;
    word.column =
        static_cast<std::uint16_t>(std::min<std::uint32_t>(columnOf(lexer_.position()), 65535));
    word.text = trimmedSpan(lexer_.position(), end);
    word.args = word.text;
    lexer_.seek(end);
    if (addWord(word) && end < source_.end) parseComment(end);
}

bool BlockParser::parseProgramEnd(std::uint32_t start) {
    if (program_.words.size() != block_.firstWord)
        return error("PARSE_MISPLACED_PROGRAMMENDE", start,
                     "PROGRAMMENDE must stand alone in the last block");
    lexer_.skipBlanks();
    if (!lexer_.atEnd() && lexer_.peek() != ';')
        return error("PARSE_MISPLACED_PROGRAMMENDE", lexer_.position(),
                     "nothing may follow PROGRAMMENDE in its block");
    block_.flags |= kBlockProgramEnd;
    programEnded_ = true;
    return true;
}

}  // namespace mtc::core
