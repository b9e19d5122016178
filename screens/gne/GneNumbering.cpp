#include "screens/gne/GneNumbering.h"

#include <cctype>
#include <cstdio>

namespace mtc::screens {

GneNumbering::Lead GneNumbering::readLead(const std::string& line) {
    Lead lead;
    std::size_t i = 0;
    while (i < line.size() && (line[i] == ' ' || line[i] == '/'))
        ++i;
    if (i < line.size() && line[i] == 'N' && i + 1 < line.size() &&
        std::isdigit(static_cast<unsigned char>(line[i + 1]))) {
        std::size_t k = i + 1;
        int number = 0;
        while (k < line.size() && std::isdigit(static_cast<unsigned char>(line[k])) && k - i <= 6)
            number = number * 10 + (line[k++] - '0');
        int sub = 0;
        if (k + 4 < line.size() + 0 && line[k] == ':') {
            std::size_t s = k + 1;
            while (s < line.size() && s <= k + 4 &&
                   std::isdigit(static_cast<unsigned char>(line[s])))
                sub = sub * 10 + (line[s++] - '0');
            if (s == k + 5) k = s;
        }
        if (k == line.size() || line[k] == ' ') {
            lead.numbered = true;
            lead.number = number;
            lead.sub = sub;
            lead.prefix = line.substr(0, k) + " ";
        }
    }
    bool quoted = false;
    for (std::size_t c = 0; c < line.size(); ++c) {
        if (line[c] == '"') quoted = !quoted;
        if (line[c] == ';' && !quoted) {
            lead.comment = line.substr(c);
            break;
        }
    }
    return lead;
}

GneNumbering::GneNumbering(const std::vector<std::string>& programLines, int firstLine,
                           int lastLine, int insertLine)
    : lines_(programLines), first_(firstLine), last_(lastLine) {
    const int start = firstLine > 0 ? firstLine : insertLine;
    for (std::size_t i = 0; i < lines_.size(); ++i) {
        const Lead lead = readLead(lines_[i]);
        if (!lead.numbered) continue;
        int& highest = highestSub_[lead.number];
        if (lead.sub > highest) highest = lead.sub;
        if (static_cast<int>(i) + 1 < start) before_ = lead.number;
    }
}

bool GneNumbering::fromSection(int line) const {
    return first_ > 0 && line >= first_ && line <= last_ && line <= static_cast<int>(lines_.size());
}

int GneNumbering::nextSub(int number) {
    return ++highestSub_[number];
}

std::string GneNumbering::numbered(const std::vector<GneOutputLine>& lines) {
    std::string out;
    int current = before_;
    for (const GneOutputLine& line : lines) {
        std::string text = line.text;
        if (fromSection(line.sourceLine)) {
            const Lead lead = readLead(lines_[static_cast<std::size_t>(line.sourceLine - 1)]);
            if (!lead.comment.empty() && text.find(lead.comment) == std::string::npos)
                text += " " + lead.comment;
            if (lead.numbered) {
                text = lead.prefix + text;
                current = lead.number;
            }
        } else if (current >= 0) {
            char number[24];
            std::snprintf(number, sizeof number, "N%04d:%04d ", current, nextSub(current));
            text = number + text;
        }
        out += text + "\n";
    }
    return out;
}

}  // namespace mtc::screens
