// GneEditModel, second half: the section as it goes back into the program
// (keyword lines, NC blocks, block numbers of GS-007, the splice).

#include <QtGlobal>  // QT_TRANSLATE_NOOP only: the texts stay plain English strings
#include <algorithm>

#include "cnc_core/contour/GneText.h"
#include "screens/gne/GneEditModel.h"
#include "screens/gne/GneEditSupport.h"

namespace mtc::screens {

namespace gne = mtc::core::gne;
using namespace gneedit;

std::vector<GneOutputLine> GneEditModel::keywordLines() const {
    std::vector<GneOutputLine> lines;
    for (std::size_t i = 0; i < items_.size(); ++i) {
        const gne::GneItem& item = items_[i];
        if (!item.isContour) {
            lines.push_back({gne::writeCall(item.call), static_cast<int>(item.call.line)});
            continue;
        }
        const gne::Contour& c = item.contour;
        const gne::GnePlane plane = planeOf(static_cast<int>(i));
        lines.push_back({"CONT (" + std::to_string(c.number) + (c.raw ? ", RAW)" : ", FINAL)"),
                         static_cast<int>(c.line)});
        for (const gne::ContourElement& e : c.elements)
            lines.push_back({gne::writeElement(e, plane), static_cast<int>(e.line)});
        lines.push_back({"END_CONT", static_cast<int>(c.endLine)});
    }
    return lines;
}

std::string GneEditModel::keywordText() const {
    std::string text;
    for (const GneOutputLine& line : keywordLines())
        text += line.text + "\n";
    return text;
}

bool GneEditModel::ncBlockLines(std::vector<GneOutputLine>& lines,
                                gnefields::ModelText& problem) const {
    const std::vector<gnefields::ModelText> open = sectionProblemTexts();
    if (!open.empty()) {
        problem = {QT_TRANSLATE_NOOP("GneModel", "the section does not expand: %1"),
                   {open.front().english()}};
        return false;
    }
    lines.clear();
    bool anyCycle = false;
    std::vector<GneOutputLine> keywords = keywordLines();
    std::size_t next = 0;  // keywords[next] is the first line of item i
    for (std::size_t i = 0; i < items_.size(); ++i) {
        const std::size_t count =
            items_[i].isContour ? items_[i].contour.elements.size() + 2 : std::size_t{1};
        if (isCycle(items_[i])) {
            anyCycle = true;
            lines.push_back(
                {"; GNE " + keywords[next].text + " expanded", keywords[next].sourceLine});
            const auto line = static_cast<std::uint32_t>(kLineBase + kItemStride * i);
            for (const gne::ExpandedCall& call : expansion_.calls)
                if (call.line == line)
                    for (const std::string& block : call.blocks)
                        lines.push_back({block, 0});
        } else {
            for (std::size_t k = next; k < next + count; ++k)
                lines.push_back({"; GNE " + keywords[k].text, keywords[k].sourceLine});
        }
        next += count;
    }
    if (!anyCycle) {
        problem = {QT_TRANSLATE_NOOP("GneModel",
                                     "NC blocks need a machining cycle: insert a CYCLE_xx for the "
                                     "contour, or save as function call")};
        return false;
    }
    return true;
}

bool GneEditModel::ncBlocks(std::string& text, gnefields::ModelText& problem) const {
    std::vector<GneOutputLine> lines;
    if (!ncBlockLines(lines, problem)) return false;
    text.clear();
    for (const GneOutputLine& line : lines)
        text += line.text + "\n";
    return true;
}

bool GneEditModel::output(GneOutput kind, std::string& text, gnefields::ModelText& problem) const {
    std::vector<GneOutputLine> lines;
    if (kind == GneOutput::NcBlocks) {
        if (!ncBlockLines(lines, problem)) return false;
    } else if (!modified_ && !isNew()) {
        text.clear();  // unchanged: the section's lines exactly as they were
        for (int line = firstLine_; line <= lastLine_; ++line)
            text += programLines_[static_cast<std::size_t>(line - 1)] + "\n";
        return true;
    } else {
        lines = keywordLines();
    }
    text = GneNumbering(programLines_, firstLine_, lastLine_, insertLine_).numbered(lines);
    return true;
}

std::string GneEditModel::splice(const std::string& output) const {
    std::vector<std::string> lines = programLines_;
    std::vector<std::string> add = splitLines(output);
    if (!add.empty() && add.back().empty()) add.pop_back();
    std::size_t from = 0, count = 0;
    if (!isNew()) {
        from = static_cast<std::size_t>(firstLine_) - 1;
        count = static_cast<std::size_t>(lastLine_ - firstLine_) + 1;
    } else {
        from = std::min(static_cast<std::size_t>(std::max(insertLine_, 1)) - 1, lines.size());
        if (from == lines.size() && !lines.empty() && lines.back().empty()) from = lines.size() - 1;
        count = replaceEmptyLine_ ? 1 : 0;
    }
    lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(from),
                lines.begin() + static_cast<std::ptrdiff_t>(from + count));
    lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(from), add.begin(), add.end());
    std::string out;
    for (std::size_t i = 0; i < lines.size(); ++i)
        out += (i ? "\n" : "") + lines[i];
    return out;
}

int GneEditModel::spliceLine() const {
    if (!isNew()) return firstLine_;
    return std::max(insertLine_, 1);
}

}  // namespace mtc::screens
