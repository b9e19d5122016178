#include "cnc_core/compiler/ObjectWriter.h"

#include <algorithm>
#include <string_view>

#include "cnc_core/compiler/CompilerText.h"
#include "cnc_core/text/Digits.h"

namespace mtc::core {

namespace {

constexpr const char* kIndent = "      ";  // six blanks mark a continuation line

/// Pieces of `text` between blanks outside brackets; each piece keeps the
/// blanks in front of it (so the source's blanks are transferred).
std::vector<std::string> splitPieces(std::string_view text) {
    std::vector<std::string> pieces;
    std::string piece;
    int depth = 0;
    bool comment = false;
    for (char c : text) {
        if (!comment && (c == '(' || c == '[')) ++depth;
        if (!comment && (c == ')' || c == ']') && depth > 0) --depth;
        if (c == ';' && depth == 0) comment = true;
        if (c == ' ' && depth == 0 && !piece.empty() && piece.back() != ' ') {
            pieces.push_back(std::move(piece));
            piece.clear();
        }
        piece += c;
    }
    if (!piece.empty()) pieces.push_back(std::move(piece));
    return pieces;
}

/// Lines of one block: `lead` ("N0053:0001") then `text` wrapped at blanks.
std::vector<std::string> wrapBlock(const std::string& lead, std::string_view text) {
    std::vector<std::string> lines{lead};
    if (text.empty()) return lines;
    if (lead.size() + 1 + text.size() <= kMaxObjectLine) {  // the common case: one line
        lines[0].reserve(lead.size() + 1 + text.size());
        if (!lead.empty()) lines[0] += ' ';
        lines[0] += text;
        return lines;
    }
    for (std::string& piece : splitPieces(text)) {
        std::string& line = lines.back();
        const bool first = line == lead && lines.size() == 1;
        std::string_view trimmed(piece);
        while (!trimmed.empty() && trimmed.front() == ' ')
            trimmed.remove_prefix(1);
        if (first) {
            if (!lead.empty()) line += ' ';
            line += trimmed;
        } else if (line.size() + piece.size() <= kMaxObjectLine || line == kIndent) {
            line += line == kIndent ? std::string(trimmed) : piece;
        } else {
            lines.emplace_back(std::string(kIndent) + std::string(trimmed));
        }
    }
    return lines;
}

std::size_t blockChars(const std::vector<std::string>& lines) {
    std::size_t n = 0;
    for (const std::string& line : lines)
        n += line.size();
    return n;
}

bool fits(const std::vector<std::string>& lines) {
    if (lines.size() > kMaxBlockLines || blockChars(lines) > kMaxBlockChars) return false;
    for (const std::string& line : lines)
        if (line.size() > kMaxObjectLine) return false;
    return true;
}

/// The lines of an unchanged source block: its own layout with the
/// enhanced number inserted, when that still fits.
bool sourceLayoutLines(const std::string& lead, const CompileBlock& block,
                       std::vector<std::string>& lines) {
    lines.clear();
    std::string_view layout(block.sourceLayout.empty() ? block.text : block.sourceLayout);
    std::size_t start = 0;
    while (start <= layout.size()) {
        std::size_t end = layout.find('\n', start);
        if (end == std::string_view::npos) end = layout.size();
        std::string_view line = layout.substr(start, end - start);
        if (lines.empty())
            lines.push_back(line.empty() ? lead : lead + " " + std::string(line));
        else if (!line.empty())
            lines.emplace_back(line);
        start = end + 1;
    }
    return fits(lines);
}

void appendFourDigits(std::string& out, int number) {
    if (number < 0) number = 0;
    if (number > 9999) {
        out += formatFourDigits(number);
        return;
    }
    const char digits[4] = {
        static_cast<char>('0' + number / 1000), static_cast<char>('0' + number / 100 % 10),
        static_cast<char>('0' + number / 10 % 10), static_cast<char>('0' + number % 10)};
    out.append(digits, 4);
}

/// `lead` becomes "/N0053:0001" (prefix and enhanced number; "" without number).
void setBlockLead(std::string& lead, const CompileBlock& block, int number, int sub) {
    lead = block.prefix;
    if (number < 0) return;
    if (number > 9999 || sub < 0 || sub > 9999) {  // more digits than four
        lead += 'N';
        appendFourDigits(lead, number);
        lead += ':';
        appendFourDigits(lead, sub);
        return;
    }
    char text[10] = {'N', 0, 0, 0, 0, ':', 0, 0, 0, 0};  // one append for the common case
    writeFourDigits(text + 1, number);
    writeFourDigits(text + 6, sub);
    lead.append(text, sizeof text);
}

/// setBlockLead's lead in a buffer (the common case: a short prefix and
/// four-digit numbers).
struct ShortLead {
    static constexpr std::size_t kMaxPrefix = 8;
    char data[kMaxPrefix + 10] = {};
    std::size_t size = 0;
};

/// setBlockLead into `lead`; false (nothing written) for a prefix of more
/// than kMaxPrefix characters or numbers of more than four digits.
bool setShortLead(ShortLead& lead, const CompileBlock& block, int number, int sub) {
    if (block.prefix.size() > ShortLead::kMaxPrefix ||
        (number >= 0 && (number > 9999 || sub < 0 || sub > 9999)))
        return false;
    lead.size = block.prefix.copy(lead.data, ShortLead::kMaxPrefix);
    if (number < 0) return true;
    char* const at = lead.data + lead.size;
    at[0] = 'N';
    writeFourDigits(at + 1, number);
    at[5] = ':';
    writeFourDigits(at + 6, sub);
    lead.size += 10;
    return true;
}

/// The common case of a block that is one line of at most 71 characters:
/// appends that line (with '\n') to `out` and returns true; false (nothing
/// appended) when the block needs the general layout (sourceLayoutLines,
/// wrapBlock). Writes exactly the line those would give.
bool appendSingleLine(std::string_view lead, const CompileBlock& block, std::string& out) {
    const std::string& text = block.text;
    const bool asSource = !block.intermediate && !block.changed;
    if (asSource && !block.sourceLayout.empty()) return false;  // continuation lines
    if (text.find('\n') != std::string::npos) return false;
    // sourceLayoutLines writes "lead text"; wrapBlock drops the blank after an empty lead
    const bool blank = !text.empty() && (asSource || !lead.empty());
    // (wrapBlock's one-line case counts the blank even after an empty lead)
    const std::size_t counted = lead.size() + (blank || !asSource ? 1 : 0) + text.size();
    if (text.empty() ? lead.size() > kMaxObjectLine : counted > kMaxObjectLine) return false;
    out.append(lead.data(), lead.size());
    if (blank) out.push_back(' ');
    out.append(text);
    out.push_back('\n');
    return true;
}

}  // namespace

bool continuesNumbering(const CompileBlock& block, int previousNumber) {
    return block.intermediate ||
           (block.sourceSub > 0 && block.number >= 0 && block.number == previousNumber);
}

ObjectText writeObjectText(const SourceFrame& frame, const BlockSequence& blocks,
                           CompileContext& context) {
    ObjectText out;
    // the frame, a line of lead, blank, text and '\n' per block, and a
    // PROGRAMMENDE line of its own ("N9999:0000 PROGRAMMENDE")
    std::size_t estimate = frame.identification.size() + frame.header.size() + 48;
    for (const CompileBlock& block : blocks)
        estimate += block.text.size() + block.prefix.size() + 12;
    out.text.reserve(estimate);
    out.lineMap.reserve(blocks.size() + 16);
    auto addLine = [&out](const std::string& line, ObjectLine entry) {
        out.text += line;
        out.text += '\n';
        out.lineMap.push_back(entry);
    };
    if (!frame.identification.empty())
        addLine(frame.identification, {ObjectLineKind::Identification, 1, -1, 0, false});
    if (!frame.header.empty()) {
        std::uint32_t line = frame.headerFirstLine;
        std::size_t start = 0;
        while (start <= frame.header.size()) {
            std::size_t end = frame.header.find('\n', start);
            if (end == std::string::npos) end = frame.header.size();
            addLine(frame.header.substr(start, end - start),
                    {ObjectLineKind::Header, line++, -1, 0, false});
            start = end + 1;
        }
    }
    int number = -1, sub = 0;
    std::vector<std::string> lines;
    std::string lead;
    ShortLead fastLead;
    bool endWritten = false;
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        const CompileBlock& block = blocks[i];
        if (continuesNumbering(block, number)) {
            ++sub;
        } else {
            number = block.number;
            sub = block.sourceSub;
        }
        const ObjectLineKind kind =
            block.programEnd ? ObjectLineKind::ProgramEnd : ObjectLineKind::Block;
        const bool shortLead = setShortLead(fastLead, block, number, sub);
        if (!shortLead) setBlockLead(lead, block, number, sub);
        if (appendSingleLine(
                shortLead ? std::string_view(fastLead.data, fastLead.size) : std::string_view(lead),
                block, out.text)) {
            out.lineMap.push_back({kind, block.sourceLine, number, sub, block.intermediate});
            if (block.programEnd) {
                endWritten = true;
                break;
            }
            ++out.blocks;
            continue;
        }
        if (shortLead) lead.assign(fastLead.data, fastLead.size);
        if (block.intermediate || block.changed || !sourceLayoutLines(lead, block, lines)) {
            lines = wrapBlock(lead, block.text);
            if (!fits(lines)) {
                const std::string_view text(block.text);
                lines = wrapBlock(lead, text.substr(0, commentOffset(text)));
            }
            if (!fits(lines) &&
                !context.reportAt(blocks, i, Severity::Error, "COMPILER_BLOCK_TOO_LONG",
                                  "Compiled block too long.",
                                  {"After compilation the block needs more than 230 characters "
                                   "or 4 lines of 71 characters.",
                                   "Measure: split the block or shorten its macros."}))
                break;
        }
        for (std::size_t l = 0; l < lines.size(); ++l)
            addLine(lines[l], {l == 0 ? kind : ObjectLineKind::Continuation, block.sourceLine,
                               number, sub, block.intermediate});
        if (block.programEnd) {
            endWritten = true;
            break;
        }
        ++out.blocks;
    }
    if (!endWritten) {
        const int endNumber = frame.lastNumber >= 0 ? std::min(frame.lastNumber + 1, 9999) : -1;
        std::string line = endNumber >= 0 ? formatBlockNumber(endNumber) + ":0000 " : "";
        addLine(line + "PROGRAMMENDE", {ObjectLineKind::ProgramEnd, 0, endNumber, 0, true});
    }
    if (frame.dat && out.lineMap.size() > kMaxObjectLines)
        context.reportGeneral("COMPILER_TOO_MANY_LINES", "Maximum number of NC blocks exceeded.",
                              {"The compiled program needs " + std::to_string(out.lineMap.size()) +
                                   " lines; an object file may have at most 10,000.",
                               "Measure: split the NC program."});
    return out;
}

}  // namespace mtc::core
