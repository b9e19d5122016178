#include "cnc_core/language/Parser.h"

#include <algorithm>
#include <cstring>
#include <limits>

#include "cnc_core/language/BlockParser.h"
#include "cnc_core/language/ParseContext.h"
#include "cnc_core/language/SourceLayout.h"

namespace mtc::core {

namespace {

// Limits of a .DAT source file (seed 001, ch. 10).
constexpr std::uint32_t kMaxDatLines = 10000;
constexpr std::uint32_t kMaxDatLineLength = 71;
constexpr std::uint32_t kMaxDatBlockLength = 230;
constexpr std::uint32_t kMaxDatBlockLines = 4;
/// Continuation lines start with this many blanks (seed 001, ch. 10).
constexpr std::uint32_t kContinuationIndent = 6;

/// Groups the lines after the header into blocks (a line starting with six
/// blanks continues the previous block; blank and comment-only lines separate
/// blocks and make none), hands each block to the BlockParser and checks the
/// .DAT line limits.
class LineScanner {
  public:
    LineScanner(ParseContext& context, const SourceLayout& layout)
        : context_(context),
          text_(context.source()),
          layout_(layout),
          blocks_(context),
          wholeLines_(context.plainBlockFastPath() && !layout.dat) {}

    void run();

  private:
    /// Makes the line at `pos` ready (a file's window: fills ahead, and
    /// releases what no pending block needs).
    void advanceWindow(std::uint32_t pos) {
        context_.doneBefore(open_ ? std::min(pending_.begin, pos) : pos);
        ready_ = context_.readyLinesFrom(pos);
    }
    enum class LineKind { Blank, CommentOnly, Continuation, BlockStart };
    /// The fast path for the line at `pos`: true when it took the whole
    /// line (then `pos` and `line` are those of the next line).
    bool takeWholeLine(std::uint32_t& pos, std::uint32_t& line);
    LineKind classify(std::uint32_t begin, std::uint32_t end) const;
    void flush();
    void checkDatLine(std::uint32_t begin, std::uint32_t end, std::uint32_t line);
    void checkDatBlock(const BlockSource& block);
    void afterEnd(std::uint32_t begin, std::uint32_t end, std::uint32_t line);

    ParseContext& context_;
    std::string_view text_;
    SourceLayout layout_;
    BlockParser blocks_;
    BlockSource pending_;
    bool open_ = false;
    bool ended_ = false;
    bool warnedAfterEnd_ = false;
    /// Whether lines may take BlockParser::parseLine.
    const bool wholeLines_;
    std::uint32_t lastLine_ = 0;
    /// Line starts below it have their whole line ready in text_.
    std::uint32_t ready_ = 0;
};

void LineScanner::run() {
    const char* data = text_.data();
    auto size = static_cast<std::uint32_t>(text_.size());
    std::uint32_t pos = layout_.blocksBegin;
    std::uint32_t line = layout_.firstLine;
    lastLine_ =
        std::max<std::uint32_t>(line, 2) - 1;  // the header's last line when no block follows
    while (pos < size) {
        if (pos >= ready_) advanceWindow(pos);
        if (takeWholeLine(pos, line)) continue;
        const void* newline = std::memchr(data + pos, '\n', size - pos);
        std::uint32_t next =
            newline ? static_cast<std::uint32_t>(static_cast<const char*>(newline) - data) : size;
        std::uint32_t end = next;
        if (end > pos && data[end - 1] == '\r') --end;
        if (layout_.dat) checkDatLine(pos, end, line);
        if (ended_) {
            afterEnd(pos, end, line);
        } else {
            LineKind kind = classify(pos, end);
            if (kind == LineKind::Continuation) {
                pending_.end = end;
                if (pending_.lineCount < std::numeric_limits<std::uint16_t>::max())
                    ++pending_.lineCount;
            } else {
                flush();
                if (ended_) {
                    afterEnd(pos, end, line);
                } else if (kind == LineKind::BlockStart) {
                    pending_ = BlockSource{pos, end, line, 1};
                    open_ = true;
                }
            }
        }
        lastLine_ = line;
        pos = next + 1;
        ++line;
    }
    flush();
    Program& program = context_.program();
    if (layout_.dat && lastLine_ > kMaxDatLines)
        context_.report(Severity::Error, "FILE_TOO_MANY_LINES", kMaxDatLines + 1, 1, "",
                        "a program file may have at most 10000 lines; this one has " +
                            std::to_string(lastLine_));
    if (layout_.dat && !ended_)
        context_.report(Severity::Warning, "DAT_MISSING_PROGRAMMENDE", lastLine_, 1, "",
                        "the last block of a program file should be PROGRAMMENDE");
    (void)program;
}

bool LineScanner::takeWholeLine(std::uint32_t& pos, std::uint32_t& line) {
    // Only a line starting with a blank can continue the pending block: any
    // other line ends it. Line limits are checked line by line in .DAT files.
    if (!wholeLines_ || ended_ || text_[pos] == ' ') return false;
    flush();  // the pending block may define a macro (DEFINE): test them after it
    std::uint32_t newline = 0;
    if (ended_ || !blocks_.parseLine(pos, line, newline)) return false;
    ended_ = blocks_.programEnded();
    lastLine_ = line;
    pos = newline + 1;
    ++line;
    return true;
}

LineScanner::LineKind LineScanner::classify(std::uint32_t begin, std::uint32_t end) const {
    std::uint32_t first = begin;
    while (first < end && (text_[first] == ' ' || text_[first] == '\t'))
        ++first;
    if (first == end) return LineKind::Blank;
    if (open_ && end - begin > kContinuationIndent &&
        std::memcmp(text_.data() + begin, "      ", kContinuationIndent) == 0)
        return LineKind::Continuation;
    if (text_[first] == ';') return LineKind::CommentOnly;
    return LineKind::BlockStart;
}

void LineScanner::flush() {
    if (!open_) return;
    open_ = false;
    if (layout_.dat) checkDatBlock(pending_);
    blocks_.parse(pending_);
    ended_ = blocks_.programEnded();
}

void LineScanner::checkDatLine(std::uint32_t begin, std::uint32_t end, std::uint32_t line) {
    if (end - begin > kMaxDatLineLength)
        context_.report(Severity::Error, "FILE_LINE_TOO_LONG", line, kMaxDatLineLength + 1, "",
                        "line has " + std::to_string(end - begin) +
                            " characters; a program line may have at most 71");
}

void LineScanner::checkDatBlock(const BlockSource& block) {
    if (block.lineCount > kMaxDatBlockLines)
        context_.report(Severity::Error, "FILE_BLOCK_TOO_MANY_LINES", block.line, 1, "",
                        "a block may be split into at most 4 lines; this one has " +
                            std::to_string(block.lineCount));
    std::uint32_t length = block.end - block.begin;
    if (length <= kMaxDatBlockLength) return;
    std::uint32_t breaks = 0;
    for (std::uint32_t i = block.begin; i < block.end; ++i)
        if (text_[i] == '\n' || text_[i] == '\r') ++breaks;
    if (length - breaks > kMaxDatBlockLength)
        context_.report(Severity::Error, "FILE_BLOCK_TOO_LONG", block.line, 1, "",
                        "a block may have at most 230 characters; this one has " +
                            std::to_string(length - breaks));
}

void LineScanner::afterEnd(std::uint32_t begin, std::uint32_t end, std::uint32_t line) {
    if (warnedAfterEnd_) return;
    for (std::uint32_t i = begin; i < end; ++i) {
        if (text_[i] != ' ' && text_[i] != '\t') {
            warnedAfterEnd_ = true;
            context_.report(Severity::Warning, "PARSE_TEXT_AFTER_PROGRAMMENDE", line, i - begin + 1,
                            "", "text after PROGRAMMENDE is not part of the program");
            return;
        }
    }
}

/// Reserves the packed vectors from cheap counts so that parsing does not
/// reallocate (and peak memory stays near the final size).
void reserveFor(Program& program, std::string_view text, const ChunkedText* window) {
    std::size_t lines = 1, blanks = 0;
    if (window)
        window->countLinesAndBlanks(lines, blanks);
    else
        countLinesAndBlanks(text, lines, blanks);
    program.blocks.reserve(lines);
    program.words.reserve(blanks + lines / 8);
}

}  // namespace

Program parseProgram(SourceText source, const ParseOptions& options) {
    Program program;
    program.number = options.programNumber;
    program.name = options.name;
    program.source = std::move(source);
    ParseContext context(program, options.plainBlockFastPath);
    ChunkedText* const file = program.source.file();
    ChunkedText* const window = file && file->takeParseWindow() ? file : nullptr;
    const std::string_view text =
        window ? std::string_view(window->parseBytes(), window->size()) : program.source.view();
    context.useText(text, window);
    for (const std::string& name : options.macroNames)
        context.addMacro(name);
    if (program.source.size() >= std::numeric_limits<std::uint32_t>::max() - 1) {
        context.report(Severity::Error, "FILE_TOO_LARGE", 1, 1, "",
                       "program text larger than 4 GiB is not supported");
        return program;
    }
    reserveFor(program, text, window);
    const SourceLayout layout = options.fileLayout ? readSourceLayout(context) : SourceLayout{};
    program.hasDatHeader = layout.dat;
    if (program.name.empty()) program.name = program.title;
    LineScanner(context, layout).run();
    if (window) window->endParse();
    program.blocks.shrink_to_fit();
    program.words.shrink_to_fit();
    program.expressions.shrink_to_fit();
    return program;
}

}  // namespace mtc::core
