#include "cnc_core/compiler/SourceBlocks.h"

#include <algorithm>

namespace mtc::core {

namespace {

bool isDigit(char c) {
    return c >= '0' && c <= '9';
}

/// The text without '\r'.
std::string withoutCarriageReturns(std::string_view text) {
    if (text.find('\r') == std::string_view::npos) return std::string(text);
    std::string out;
    out.reserve(text.size());
    for (char c : text)
        if (c != '\r') out += c;
    return out;
}

/// One logical line: each line break and the blanks after it become one
/// blank. `lineBreak`: `layout` has a '\n'.
std::string joinContinuationLines(std::string_view layout, bool lineBreak) {
    if (!lineBreak) {
        while (!layout.empty() && layout.back() == ' ')
            layout.remove_suffix(1);
        return std::string(layout);
    }
    std::string out;
    out.reserve(layout.size());
    for (std::size_t i = 0; i < layout.size(); ++i) {
        if (layout[i] != '\n') {
            out += layout[i];
            continue;
        }
        while (i + 1 < layout.size() && layout[i + 1] == ' ')
            ++i;
        if (!out.empty() && out.back() != ' ') out += ' ';
    }
    while (!out.empty() && out.back() == ' ')
        out.pop_back();
    return out;
}

/// Reads "[/][:] Nxxxx[:yyyy] " off the front of `raw`.
void splitNumber(std::string_view raw, CompileBlock& block) {
    std::size_t i = 0;
    while (i < raw.size() && (raw[i] == ' ' || raw[i] == '/' || raw[i] == ':')) {
        if (raw[i] != ' ') block.prefix += raw[i];
        ++i;
    }
    std::size_t digits = i + 1;
    while (digits < raw.size() && isDigit(raw[digits]))
        ++digits;
    if (i < raw.size() && raw[i] == 'N' && digits > i + 1 && digits - i - 1 <= 6) {
        int number = 0;  // at most 6 digits: no overflow
        for (std::size_t d = i + 1; d < digits; ++d)
            number = number * 10 + (raw[d] - '0');
        block.number = number;
        i = digits;
        if (i + 4 < raw.size() + 0 && raw[i] == ':' &&
            std::all_of(raw.begin() + static_cast<long>(i) + 1,
                        raw.begin() + static_cast<long>(i) + 5, isDigit)) {
            // an enhanced number (a block the GNE inserted, C-015) orders the
            // block after the others of its number; the object renumbers
            block.sourceSub = (raw[i + 1] - '0') * 1000 + (raw[i + 2] - '0') * 100 +
                              (raw[i + 3] - '0') * 10 + (raw[i + 4] - '0');
            i += 5;
        }
        if (i < raw.size() && raw[i] == ' ') ++i;
    } else if (!block.prefix.empty()) {
        // prefix without a block number: keep it in the text as written
        block.prefix.clear();
        i = 0;
        while (i < raw.size() && raw[i] == ' ')
            ++i;
    }
    const std::string_view layout = raw.substr(i);
    const bool lineBreak = layout.find('\n') != std::string_view::npos;
    block.text = joinContinuationLines(layout, lineBreak);
    if (lineBreak) block.sourceLayout = std::string(layout);
}

}  // namespace

BlockSequence splitSourceBlocks(const Program& program, SourceFrame& frame) {
    frame.identification = withoutCarriageReturns(program.identification);
    frame.header = withoutCarriageReturns(program.header);
    frame.headerFirstLine = program.identification.empty() ? 1 : 2;
    frame.dat = program.hasDatHeader;
    BlockSequence blocks;
    blocks.reserve(program.blocks.size());
    for (std::size_t b = 0; b < program.blocks.size(); ++b) {
        const Block block = program.blocks[b];
        CompileBlock& out = blocks.emplace_back();  // filled in place (room reserved)
        out.sourceIndex = static_cast<std::uint32_t>(b);
        out.sourceLine = block.line;
        out.programEnd = (block.flags & kBlockProgramEnd) != 0;
        const std::string_view raw = program.text(block.sourceText);
        if (raw.find('\r') == std::string_view::npos)
            splitNumber(raw, out);
        else
            splitNumber(withoutCarriageReturns(raw), out);
        if (out.number < 0 && block.number >= 0) out.number = block.number;
        frame.lastNumber = std::max(frame.lastNumber, out.number);
        if (out.programEnd) frame.hasProgramEnd = true;
    }
    return blocks;
}

}  // namespace mtc::core
