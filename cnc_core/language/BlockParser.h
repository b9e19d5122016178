#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "cnc_core/language/Keywords.h"
#include "cnc_core/language/Lexer.h"
#include "cnc_core/language/ParseContext.h"

namespace mtc::core {

/// Where one block's text lies: [begin, end) of the source, from the start of
/// its first line to the end of its last continuation line (no final '\n').
struct BlockSource {
    std::uint32_t begin = 0;
    std::uint32_t end = 0;
    std::uint32_t line = 0;
    std::uint16_t lineCount = 1;
};

/// Parses one NC block into Program::blocks / words / expressions:
/// [/] [Nxxxx[:yyyy]] [:] [.LABEL] [:] words [; comment].
/// On the first error in a block it reports a diagnostic, flags the block
/// with kBlockHasError, keeps the words parsed so far and skips the rest
/// (recovery at the next block). Never throws.
class BlockParser {
  public:
    /// Most words one block may have (Block::wordCount is 16 bits).
    static constexpr std::size_t kMaxWords = 65535;

    explicit BlockParser(ParseContext& context);

    /// Parses `source` and appends exactly one Block.
    void parse(const BlockSource& source);
    /// The fast path for whole lines (BlockParserPlain.cpp): when the line
    /// at `begin` (1-based number `line`) starts like a plain block and the
    /// next line cannot continue it, parses it as parse() would parse it as
    /// a one-line block, appends exactly one Block, sets `newline` to the
    /// offset of the line's '\n' (the source size when it has none) and
    /// returns true. Otherwise appends nothing and returns false. Only for a
    /// parse with the plain-block fast path, and only after the blocks
    /// before the line are parsed (a DEFINE among them names a macro).
    bool parseLine(std::uint32_t begin, std::uint32_t line, std::uint32_t& newline);
    /// True once a PROGRAMMENDE block was parsed.
    bool programEnded() const { return programEnded_; }

  private:
    // Block structure (BlockParser.cpp).
    bool parsePrefix();
    /// A skip slash '/' at the current position (at most one per block).
    void takeSkip();
    void takePrimary();
    bool parseBlockNumber();
    bool parseBlockLabel();
    bool parseNextWord();
    bool parseAddress(char letter, std::uint32_t start);
    std::uint8_t scanAxisIndex();
    bool parseValue(WordKind kind, char letter, std::uint8_t index, std::uint32_t start);
    bool parseNumberValue(WordKind kind, char letter, std::uint8_t index, std::uint32_t start,
                          bool negative);
    bool parseExpressionValue(Word& word, std::uint32_t start);
    bool parseAssignment(std::uint32_t start);
    bool parseMtdAssignment(std::uint32_t start);
    bool parseText(char open, char close, std::uint32_t start);
    bool parseComment(std::uint32_t start);
    bool finishSimpleValue(Word& word, std::int32_t node, std::uint32_t start);
    void finish();

    // Fast path for the common block shape (BlockParserPlain.cpp).
    bool takePlainBlockNumber();
    /// True when the block starts with a character the prefix cannot take
    /// (no skip, primary colon, number or label: the general prefix reads nothing).
    bool startsWithoutPrefix() const;
    void parsePlainWords();
    /// Takes plain words from `pos` up to `end` at most as the fast path
    /// takes them (stopping at the first word it does not take, a character
    /// that is not a blank ' ' / '\t', or `end`; at most kMaxWords words);
    /// columns count from `lineBegin`. Returns where it stopped.
    std::uint32_t scanPlainWords(std::uint32_t pos, std::uint32_t end, std::uint32_t lineBegin);
    /// Starts the Block of `source` (block_, lexer_ and source_).
    void startBlock(const BlockSource& source);
    /// parseLine's general part: the line [begin, end) whose plain words
    /// up to `stop` are parsed already (from `firstWord` on).
    void finishLine(const BlockSource& source, std::int32_t number, std::int32_t subNumber,
                    std::uint32_t firstWord, std::uint32_t stop);
    /// The chamfer or rounding "CF0.8" / "RD1.5" (a plain value) as the last
    /// word of the line [.., end) at `stop`: appends the word parseCommand
    /// makes of it and returns `end`; otherwise appends nothing and returns
    /// `stop`.
    std::uint32_t takeCornerWord(std::uint32_t stop, std::uint32_t end, std::uint32_t lineBegin,
                                 std::uint32_t firstWord);
    /// What takeMacroLine did with a line.
    enum class MacroLine { NoMacro, Taken, General };
    /// parseLine for a parse with macros: a line whose words from `pos` use
    /// a macro (no DEFINE, no comment) becomes the one macro word the
    /// general path makes of it (Taken, `newline` set); NoMacro when its
    /// words use none (parseLine reads them), General when the general path
    /// must parse it (a comment, or the next line may continue it).
    MacroLine takeMacroLine(std::uint32_t begin, std::uint32_t pos, std::uint32_t line,
                            std::int32_t number, std::uint32_t& newline);

    // Keywords (BlockParserKeywords.cpp).
    bool parseKeyword(std::string_view name, std::uint32_t start);
    /// MQxxx / QQxxx: an M or Q word marked kWordSwift.
    bool parseSwiftAux(std::string_view name, std::uint32_t start);
    bool parseJump(JumpKind kind, std::uint32_t start);
    bool parseJumpLabel(Word& word, std::uint32_t start);
    bool parseEvent(Word& word, std::uint32_t start);
    bool parseProgramReference(Word& word, std::uint32_t start);
    bool parseCommand(bool compiler, std::uint32_t start);
    bool scanCommandArguments();
    bool parseRestOfBlock(std::string_view name, std::uint32_t start);
    bool checkDefine(std::uint32_t argsBegin, std::uint32_t argsEnd);
    bool parseProgramEnd(std::uint32_t start);
    bool blockUsesMacro() const;
    /// blockUsesMacro for the words from `begin` of a block ending at `end`
    /// whose comment starts at `comment` (`end` when it has none).
    bool wordsUseMacro(std::uint32_t begin, std::uint32_t end, std::uint32_t comment) const;
    void emitMacroBlock();
    std::uint32_t commentStart() const;

    // Helpers.
    bool addWord(const Word& word);
    bool error(const char* code, std::uint32_t offset, std::string message);
    void warning(const char* code, std::uint32_t offset, std::string message);
    std::uint32_t lineOf(std::uint32_t offset) const;
    std::uint32_t columnOf(std::uint32_t offset) const;
    TextSpan trimmedSpan(std::uint32_t begin, std::uint32_t end) const;

    ParseContext& context_;
    Program& program_;
    std::string_view text_;
    Lexer lexer_;
    /// ParseOptions::plainBlockFastPath, fixed for the whole parse.
    const bool plainFastPath_;
    BlockSource source_;
    Block block_;
    bool primarySeen_ = false;
    bool programEnded_ = false;
};

}  // namespace mtc::core
