#include "cnc_core/machine/ConfigText.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "cnc_core/text/Numbers.h"

namespace mtc::core {
namespace {

bool isDigit(char c) {
    return c >= '0' && c <= '9';
}

/// True when `text` is exactly [+-]digits[.digits][(e|E)[+-]digits] with at
/// least one mantissa digit (".5" and "5." are accepted).
bool plainDecimalSyntax(std::string_view text) {
    std::size_t i = 0;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    std::size_t digits = 0;
    while (i < text.size() && isDigit(text[i]))
        ++i, ++digits;
    if (i < text.size() && text[i] == '.') {
        ++i;
        while (i < text.size() && isDigit(text[i]))
            ++i, ++digits;
    }
    if (digits == 0) return false;
    if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
        ++i;
        if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
        std::size_t exponent = 0;
        while (i < text.size() && isDigit(text[i]))
            ++i, ++exponent;
        if (exponent == 0) return false;
    }
    return i == text.size();
}

/// Length of the UTF-8 sequence starting at text[i] (0 = not valid UTF-8).
std::size_t utf8Length(std::string_view text, std::size_t i) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char lead = byte(i);
    std::size_t length = 0;
    if (lead < 0x80) return 1;
    if (lead >= 0xC2 && lead <= 0xDF)
        length = 2;
    else if (lead >= 0xE0 && lead <= 0xEF)
        length = 3;
    else if (lead >= 0xF0 && lead <= 0xF4)
        length = 4;
    else
        return 0;
    if (i + length > text.size()) return 0;
    for (std::size_t k = 1; k < length; ++k)
        if ((byte(i + k) & 0xC0) != 0x80) return 0;
    const unsigned char second = byte(i + 1);
    if ((lead == 0xE0 && second < 0xA0) || (lead == 0xED && second > 0x9F) ||
        (lead == 0xF0 && second < 0x90) || (lead == 0xF4 && second > 0x8F))
        return 0;  // overlong forms, surrogates, beyond U+10FFFF
    return length;
}

/// The power of ten of the first significant digit of a plain decimal
/// (`text` passed plainDecimalSyntax): 2 for "123", -3 for "0.00123e0".
long decimalExponent(std::string_view text) {
    long exponent = 0, digitsBeforePoint = 0, firstSignificant = -1, position = 0;
    bool afterPoint = false;
    std::size_t i = 0;
    for (; i < text.size() && text[i] != 'e' && text[i] != 'E'; ++i) {
        if (text[i] == '.') afterPoint = true;
        if (!isDigit(text[i])) continue;
        if (!afterPoint) ++digitsBeforePoint;
        if (firstSignificant < 0 && text[i] != '0') firstSignificant = position;
        ++position;
    }
    if (i < text.size()) {
        const std::string_view rest = text.substr(i + 1);
        const bool negative = !rest.empty() && rest.front() == '-';
        for (char c : rest)
            if (isDigit(c)) exponent = std::min(exponent * 10 + (c - '0'), 100000L);
        if (negative) exponent = -exponent;
    }
    return firstSignificant < 0 ? 0 : digitsBeforePoint - 1 - firstSignificant + exponent;
}

bool isControl(unsigned char c) {
    return c < 0x20 || c == 0x7F;
}

}  // namespace

NumberProblem readDecimal(std::string_view text, double& value) {
    if (text.empty()) return NumberProblem::Empty;
    if (!plainDecimalSyntax(text)) return NumberProblem::NotANumber;
    const char* first = text.data() + (text.front() == '+' ? 1 : 0);
    double result = 0.0;
    const auto [end, error] = std::from_chars(first, text.data() + text.size(), result);
    if (end != text.data() + text.size()) return NumberProblem::NotANumber;
    if (error == std::errc::result_out_of_range)  // overflow or underflow
        return decimalExponent(text) > 0 ? NumberProblem::NotFinite : NumberProblem::Denormal;
    if (!std::isfinite(result)) return NumberProblem::NotFinite;
    if (std::fpclassify(result) == FP_SUBNORMAL) return NumberProblem::Denormal;
    value = result == 0.0 ? 0.0 : result;  // no -0
    return NumberProblem::None;
}

NumberProblem readWholeNumber(std::string_view text, double& value) {
    double number = 0.0;
    const NumberProblem problem = readDecimal(text, number);
    if (problem != NumberProblem::None) return problem;
    if (number != std::floor(number) || std::fabs(number) > 9007199254740992.0)
        return NumberProblem::NotWhole;
    value = number;
    return NumberProblem::None;
}

const char* describeNumberProblem(NumberProblem problem) {
    switch (problem) {
        case NumberProblem::None:
            return "is a number";
        case NumberProblem::Empty:
            return "is empty";
        case NumberProblem::NotANumber:
            return "is not a number (decimal notation with '.' as decimal point)";
        case NumberProblem::NotFinite:
            return "is not a finite number";
        case NumberProblem::Denormal:
            return "is too close to 0 to be held exactly";
        case NumberProblem::NotWhole:
            return "is not a whole number";
    }
    return "is not a number";
}

std::string quotedValue(std::string_view text, std::size_t limit) {
    std::string out = "'";
    std::size_t shown = 0;
    for (std::size_t i = 0; i < text.size(); ++shown) {
        if (shown == limit) {
            out += "...";
            break;
        }
        const unsigned char c = static_cast<unsigned char>(text[i]);
        const std::size_t length = utf8Length(text, i);
        if (length == 0 || isControl(c) || c == '\\' || c == '\'') {
            char escaped[8];
            if (c == '\\' || c == '\'')
                std::snprintf(escaped, sizeof escaped, "\\%c", c);
            else
                std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
            out += escaped;
            ++i;
            continue;
        }
        out.append(text.substr(i, length));
        i += length;
    }
    return out + "'";
}

bool isPrintableText(std::string_view text) {
    for (std::size_t i = 0; i < text.size();) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        const std::size_t length = utf8Length(text, i);
        if (length == 0 || (isControl(c) && c != '\t')) return false;
        i += length;
    }
    return true;
}

std::string formatConfigNumber(double value) {
    return formatGeneral(value, 10);
}

}  // namespace mtc::core
