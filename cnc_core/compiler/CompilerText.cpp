#include "cnc_core/compiler/CompilerText.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace mtc::core {

std::string formatFourDigits(int number) {
    if (number < 0) number = 0;
    if (number > 9999) return std::to_string(number);
    return {static_cast<char>('0' + number / 1000), static_cast<char>('0' + number / 100 % 10),
            static_cast<char>('0' + number / 10 % 10), static_cast<char>('0' + number % 10)};
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
    if (text.find(';') == std::string_view::npos) return text.size();
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
    std::string text;
    appendCoordinate(text, value);
    return text;
}

void appendCoordinate(std::string& out, double value) {
    appendTicks(out, coordinateTicks(value));
}

long long coordinateTicks(double value) {
    if (!std::isfinite(value) || std::fabs(value) > 1e14) return 0;
    return std::llround(value * 10000.0);
}

void appendTicks(std::string& out, long long scaled) {
    // a count of zero has no sign, so "-0" cannot occur
    if (scaled < 0) {
        out += '-';
        scaled = -scaled;
    }
    char digits[24];
    char* first = digits + sizeof digits;
    long long whole = scaled / 10000;
    do {
        *--first = static_cast<char>('0' + whole % 10);
        whole /= 10;
    } while (whole > 0);
    out.append(first, static_cast<std::size_t>(digits + sizeof digits - first));
    const int fraction = static_cast<int>(scaled % 10000);
    if (fraction == 0) return;
    char decimals[4] = {
        static_cast<char>('0' + fraction / 1000), static_cast<char>('0' + fraction / 100 % 10),
        static_cast<char>('0' + fraction / 10 % 10), static_cast<char>('0' + fraction % 10)};
    int length = 4;
    while (length > 0 && decimals[length - 1] == '0')
        --length;
    out += '.';
    out.append(decimals, static_cast<std::size_t>(length));
}

bool containsAnyCaseless(std::string_view text,
                         std::initializer_list<std::string_view> upperNeedles) {
    std::string upper;  // only built when the text has small letters
    if (std::any_of(text.begin(), text.end(), [](char c) { return c >= 'a' && c <= 'z'; })) {
        upper.assign(text);
        for (char& c : upper)
            if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 32);
        text = upper;
    }
    for (std::string_view needle : upperNeedles)
        if (text.find(needle) != std::string_view::npos) return true;
    return false;
}

}  // namespace mtc::core
