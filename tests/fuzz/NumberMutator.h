#pragma once

// The custom mutation of the fuzz campaign (issue 22 §7): a number of the
// input is replaced by an extreme one. libFuzzer's own mutations change
// digits one at a time and rarely reach 1e308 or 65537; these are the
// numbers that found the hangs and the undefined conversions so far.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace mtc::fuzz {

/// The replacements: ±1e308, 1e-300, huge integers, 65537, -0, nan, ...
const std::vector<std::string_view>& extremeNumbers();

/// Where a number is in `text`: [begin, end) of an optional sign, digits,
/// a decimal point and an exponent ("12", "-3.5", ".2", "1e-300").
struct NumberSpan {
    std::size_t begin = 0;
    std::size_t end = 0;
};

/// Every number of `text`, in order.
std::vector<NumberSpan> findNumbers(std::string_view text);

/// Replaces the number chosen by `seed` (or, when `text` has none, inserts
/// at a position chosen by `seed`) by the extreme number chosen by `seed`.
/// Returns false (text unchanged) when the result would exceed `maxSize`.
bool replaceNumberByExtreme(std::string& text, std::uint32_t seed, std::size_t maxSize);

}  // namespace mtc::fuzz
