#pragma once

#include <limits>
#include <optional>
#include <type_traits>

/// Conversions of a double that may come from input (a programmed number, a
/// configuration value, a computed expression) to an integer type. A plain
/// static_cast of NaN, an infinity or a value outside the integer's range is
/// undefined behaviour; these test the range first, with comparisons that
/// are exact for every double. The one place this rule lives: a cast from
/// double to an integer elsewhere needs a range check right before it.
namespace mtc::core {

/// True when `value` lies in the range of `Int` after truncation toward zero
/// (false for NaN and the infinities): then static_cast<Int>(value) is defined.
template <typename Int>
constexpr bool fitsInteger(double value) {
    static_assert(std::is_integral_v<Int>);
    // lowest() and max()+1 are powers of two (or 0): exact as doubles. max()
    // itself may not be (2^63-1), but it rounds to 2^63 and adding 1 keeps it.
    constexpr double below = static_cast<double>(std::numeric_limits<Int>::lowest()) - 1.0;
    constexpr double above = static_cast<double>(std::numeric_limits<Int>::max()) + 1.0;
    return value > below && value < above;
}

/// `value` as an `Int` when it is a whole number that `Int` holds; nullopt
/// for NaN, infinities, fractions and numbers out of range.
template <typename Int = int>
constexpr std::optional<Int> exactInteger(double value) {
    if (!fitsInteger<Int>(value)) return std::nullopt;
    const Int whole = static_cast<Int>(value);
    if (static_cast<double>(whole) != value) return std::nullopt;
    return whole;
}

/// `value` truncated toward zero and clamped to [low, high]; NaN gives `low`.
/// For values whose size the caller bounds anyway (a count, a pixel, a
/// number shown) where "as far as it goes" is the right answer.
template <typename Int>
constexpr Int clampedInteger(double value, Int low, Int high) {
    if (!(value > static_cast<double>(low))) return low;  // also NaN
    if (!(value < static_cast<double>(high))) return high;
    return static_cast<Int>(value);  // strictly inside [low, high]: defined
}

/// `value` truncated toward zero and clamped to the range of `Int`; NaN gives
/// its lowest value.
template <typename Int>
constexpr Int clampedInteger(double value) {
    return clampedInteger<Int>(value, std::numeric_limits<Int>::lowest(),
                               std::numeric_limits<Int>::max());
}

}  // namespace mtc::core
