#include "cnc_core/compiler/CompilerText.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cnc_core/text/Digits.h"

namespace mtc::core {

std::string formatFourDigits(int number) {
    if (number < 0) number = 0;
    if (number > 9999) return std::to_string(number);
    std::string digits(4, '0');
    writeFourDigits(digits.data(), number);
    return digits;
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

namespace {

/// Writes the fraction (1..9999 steps of 0.0001) as ".dddd" without
/// trailing zeros before `first`.
char* putFraction(char* first, unsigned fraction) {
    char digits[4];
    putDigitPair(putDigitPair(digits + 4, fraction % 100), fraction / 100);
    std::size_t length = 4;
    while (digits[length - 1] == '0')
        --length;
    first -= length;
    std::copy(digits, digits + length, first);
    *--first = '.';
    return first;
}

}  // namespace

char* writeTicksBefore(char* end, long long scaled) {
    char* first = end;                 // written back to front
    const bool negative = scaled < 0;  // a count of zero has no sign: no "-0"
    unsigned long long magnitude = negative ? 0ull - static_cast<unsigned long long>(scaled)
                                            : static_cast<unsigned long long>(scaled);
    const auto fraction = static_cast<unsigned>(magnitude % 10000);
    magnitude /= 10000;
    if (fraction != 0) first = putFraction(first, fraction);
    while (magnitude >= 100) {
        first = putDigitPair(first, static_cast<unsigned>(magnitude % 100));
        magnitude /= 100;
    }
    if (magnitude >= 10)
        first = putDigitPair(first, static_cast<unsigned>(magnitude));
    else
        *--first = static_cast<char>('0' + magnitude);
    if (negative) *--first = '-';
    return first;
}

void appendTicks(std::string& out, long long scaled) {
    char buffer[kMaxTicksText];  // one append for the whole number
    char* const end = buffer + sizeof buffer;
    const char* first = writeTicksBefore(end, scaled);
    out.append(first, static_cast<std::size_t>(end - first));
}

namespace {

char upperLetter(char c) {
    return c >= 'a' && c <= 'z' ? static_cast<char>(c - 32) : c;
}

}  // namespace

CaselessNeedles::CaselessNeedles(std::initializer_list<std::string_view> upperNeedles) {
    for (std::string_view needle : upperNeedles) {
        if (needle.empty() || needles_.size() == 32) continue;
        const std::uint32_t bit = 1u << needles_.size();
        needles_.emplace_back(needle);
        const char first = needle.front();
        startingHere_[static_cast<unsigned char>(first)] |= bit;
        if (first >= 'A' && first <= 'Z')
            startingHere_[static_cast<unsigned char>(first + 32)] |= bit;
        for (std::size_t c = 0; c < secondHere_.size(); ++c)  // as matchesAt compares it
            if (needle.size() == 1 || upperLetter(static_cast<char>(c)) == needle[1])
                secondHere_[c] |= bit;
    }
}

bool CaselessNeedles::matchesAt(std::string_view text, std::size_t at,
                                const std::string& needle) const {
    if (needle.size() > text.size() - at) return false;
    for (std::size_t k = 1; k < needle.size(); ++k)
        if (upperLetter(text[at + k]) != needle[k]) return false;
    return true;
}

std::size_t CaselessNeedles::nextStart(std::string_view text, std::size_t from) const {
    const auto starts = [&](std::size_t i) {
        return startingHere_[static_cast<unsigned char>(text[i])];
    };
    // four characters per step while none of them can start a needle
    while (from + 4 <= text.size() &&
           (starts(from) | starts(from + 1) | starts(from + 2) | starts(from + 3)) == 0)
        from += 4;
    while (from < text.size() && starts(from) == 0)
        ++from;
    return from;
}

bool CaselessNeedles::foundIn(std::string_view text) const {
    for (std::size_t i = nextStart(text, 0); i < text.size(); i = nextStart(text, i + 1)) {
        std::uint32_t candidates = startingHere_[static_cast<unsigned char>(text[i])];
        if (i + 1 < text.size())  // the second character rules out nearly all of them
            candidates &= secondHere_[static_cast<unsigned char>(text[i + 1])];
        for (std::size_t n = 0; candidates != 0; ++n, candidates >>= 1)
            if ((candidates & 1u) && matchesAt(text, i, needles_[n])) return true;
    }
    return false;
}

bool containsAnyCaseless(std::string_view text,
                         std::initializer_list<std::string_view> upperNeedles) {
    return CaselessNeedles(upperNeedles).foundIn(text);
}

}  // namespace mtc::core
