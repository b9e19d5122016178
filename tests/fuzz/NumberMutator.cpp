#include "NumberMutator.h"

namespace mtc::fuzz {
namespace {

bool isDigit(char c) {
    return c >= '0' && c <= '9';
}

/// A small deterministic mixer so that one seed picks both a place and a value.
std::uint32_t mix(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

}  // namespace

const std::vector<std::string_view>& extremeNumbers() {
    static const std::vector<std::string_view> numbers = {
        "1e308",
        "-1e308",
        "1.7976931348623157e308",
        "1e-300",
        "-1e-300",
        "4.9e-324",
        "0",
        "-0",
        "0.0000000001",
        "65537",
        "65536",
        "65535",
        "32768",
        "-32769",
        "2147483647",
        "2147483648",
        "-2147483649",
        "4294967296",
        "9223372036854775808",
        "18446744073709551617",
        "99999999999999999999",
        "8888888888",
        "1e9",
        "nan",
        "inf",
        "-inf",
        "1e400",
        "999999",
        "0.5",
        "1e15",
    };
    return numbers;
}

std::vector<NumberSpan> findNumbers(std::string_view text) {
    std::vector<NumberSpan> spans;
    std::size_t i = 0;
    while (i < text.size()) {
        const bool dotDigit = text[i] == '.' && i + 1 < text.size() && isDigit(text[i + 1]);
        if (!isDigit(text[i]) && !dotDigit) {
            ++i;
            continue;
        }
        std::size_t begin = i;
        if (begin > 0 && (text[begin - 1] == '-' || text[begin - 1] == '+')) --begin;
        while (i < text.size() && isDigit(text[i]))
            ++i;
        if (i < text.size() && text[i] == '.') {
            ++i;
            while (i < text.size() && isDigit(text[i]))
                ++i;
        }
        if (i + 1 < text.size() && (text[i] == 'e' || text[i] == 'E')) {
            std::size_t e = i + 1;
            if (e < text.size() && (text[e] == '-' || text[e] == '+')) ++e;
            if (e < text.size() && isDigit(text[e])) {
                i = e;
                while (i < text.size() && isDigit(text[i]))
                    ++i;
            }
        }
        spans.push_back({begin, i});
    }
    return spans;
}

bool replaceNumberByExtreme(std::string& text, std::uint32_t seed, std::size_t maxSize) {
    const std::vector<std::string_view>& extremes = extremeNumbers();
    const std::string_view value = extremes[mix(seed) % extremes.size()];
    const std::vector<NumberSpan> spans = findNumbers(text);
    NumberSpan at;
    if (spans.empty()) {
        at.begin = at.end = text.empty() ? 0 : mix(seed ^ 0x9e3779b9U) % (text.size() + 1);
    } else {
        at = spans[mix(seed ^ 0x85ebca6bU) % spans.size()];
    }
    const std::size_t size = text.size() - (at.end - at.begin) + value.size();
    if (size > maxSize) return false;
    text.replace(at.begin, at.end - at.begin, value);
    return true;
}

}  // namespace mtc::fuzz
