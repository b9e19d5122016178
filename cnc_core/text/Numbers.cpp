#include "cnc_core/text/Numbers.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <system_error>

namespace mtc::core {

namespace {

bool isBlank(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
}

bool isDigit(char c) {
    return c >= '0' && c <= '9';
}

/// The decimal exponent of the first significant digit of a number that
/// from_chars reported out of range: > 0 overflows, otherwise it underflows.
long magnitude(const char* first, const char* last) {
    long digitsBeforePoint = 0;
    long leadingZerosAfterPoint = 0;
    bool point = false;
    bool significant = false;
    const char* p = first;
    for (; p != last && (isDigit(*p) || (*p == '.' && !point)); ++p) {
        if (*p == '.') {
            point = true;
        } else if (!point) {
            if (*p != '0' || significant) ++digitsBeforePoint, significant = true;
        } else if (!significant) {
            if (*p == '0')
                ++leadingZerosAfterPoint;
            else
                significant = true;
        }
    }
    long exponent = 0;
    if (p != last && (*p == 'e' || *p == 'E')) {
        ++p;
        const bool negative = p != last && *p == '-';
        if (p != last && (*p == '-' || *p == '+')) ++p;
        for (; p != last && isDigit(*p); ++p)
            exponent = std::min(exponent * 10 + (*p - '0'), 100000L);
        if (negative) exponent = -exponent;
    }
    return (digitsBeforePoint > 0 ? digitsBeforePoint : -leadingZerosAfterPoint) + exponent;
}

std::string format(double value, std::chars_format style, int precision) {
    // %.17g of the largest double has 24 characters; %.Nf of 1e308 has ~310+N.
    char text[400];
    const auto result = std::to_chars(text, text + sizeof text, value, style, precision);
    if (result.ec != std::errc())
        return style == std::chars_format::fixed ? format(value, std::chars_format::general, 17)
                                                 : std::string();
    return std::string(text, result.ptr);
}

}  // namespace

std::string formatGeneral(double value, int precision) {
    return format(value, std::chars_format::general, std::clamp(precision, 1, 40));
}

std::string formatFixed(double value, int decimals) {
    return format(value, std::chars_format::fixed, std::clamp(decimals, 0, 40));
}

std::string formatRoundTrip(double value) {
    std::string text;
    for (int digits = 1; digits <= 17; ++digits) {
        text = formatGeneral(value, digits);
        double back = 0.0;
        if (readNumberPrefix(text, back) == text.size() && back == value) break;
    }
    return text;
}

const char* readNumberPrefix(const char* first, const char* last, double& value) {
    value = 0.0;
    const char* p = first;
    while (p != last && isBlank(*p))
        ++p;
    bool negative = false;
    if (p != last && (*p == '+' || *p == '-')) negative = *p++ == '-';
    // from_chars takes no '+' and reads "-" itself: hand it the unsigned part.
    if (p != last && *p == '-') return first;
    double result = 0.0;
    const auto [end, error] = std::from_chars(p, last, result, std::chars_format::general);
    if (end == p) return first;
    if (error == std::errc::result_out_of_range) result = magnitude(p, end) > 0 ? HUGE_VAL : 0.0;
    value = negative ? -result : result;
    return end;
}

std::size_t readNumberPrefix(std::string_view text, double& value) {
    const char* first = text.data();
    return static_cast<std::size_t>(readNumberPrefix(first, first + text.size(), value) - first);
}

double leadingNumber(std::string_view text) {
    double value = 0.0;
    readNumberPrefix(text, value);
    return value;
}

}  // namespace mtc::core
