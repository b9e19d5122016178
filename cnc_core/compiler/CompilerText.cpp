#include "cnc_core/compiler/CompilerText.h"

#include <cmath>
#include <cstdio>

namespace mtc::core {

std::string formatFourDigits(int number) {
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "%04d", number < 0 ? 0 : number);
    return buffer;
}

std::string formatBlockNumber(int number) {
    return "N" + formatFourDigits(number);
}

std::string limitMessage(std::string_view message) {
    return std::string(message.substr(0, kMaxBriefMessage));
}

std::vector<std::string> wrapWords(std::string_view text, std::size_t width) {
    std::vector<std::string> lines;
    std::string line;
    std::size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && text[i] == ' ')
            ++i;
        std::size_t end = i;
        while (end < text.size() && text[end] != ' ')
            ++end;
        if (end == i) break;
        std::string_view word = text.substr(i, end - i);
        i = end;
        while (word.size() > width) {  // a word longer than a line is cut
            if (!line.empty()) lines.push_back(std::move(line));
            line.clear();
            lines.emplace_back(word.substr(0, width));
            word.remove_prefix(width);
        }
        if (!line.empty() && line.size() + 1 + word.size() > width) {
            lines.push_back(std::move(line));
            line.clear();
        }
        if (!line.empty()) line += ' ';
        line += word;
    }
    if (!line.empty()) lines.push_back(std::move(line));
    return lines;
}

std::vector<std::string> limitDetails(const std::vector<std::string>& details) {
    std::vector<std::string> lines;
    for (const std::string& detail : details)
        for (std::string& line : wrapWords(detail, kMaxDetailLength))
            if (lines.size() < kMaxDetailLines) lines.push_back(std::move(line));
    return lines;
}

std::size_t commentOffset(std::string_view text) {
    int round = 0, square = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '(') ++round;
        if (c == ')' && round > 0) --round;
        if (c == '[') ++square;
        if (c == ']' && square > 0) --square;
        if (c == ';' && round == 0 && square == 0) return i;
    }
    return text.size();
}

std::string formatCoordinate(double value) {
    if (!std::isfinite(value)) value = 0.0;
    double rounded = std::round(value * 10000.0) / 10000.0;
    if (rounded == 0.0) rounded = 0.0;  // no "-0"
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, "%.4f", rounded);
    std::string text(buffer);
    while (!text.empty() && text.back() == '0')
        text.pop_back();
    if (!text.empty() && text.back() == '.') text.pop_back();
    if (text == "-0") text = "0";
    return text;
}

}  // namespace mtc::core
