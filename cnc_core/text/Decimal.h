#pragma once

#include <cstdint>

namespace mtc::core {

/// 10^0 .. 10^18, each exact as a double.
inline constexpr double kPowersOfTen[19] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,
                                            1e7,  1e8,  1e9,  1e10, 1e11, 1e12, 1e13,
                                            1e14, 1e15, 1e16, 1e17, 1e18};

/// The value of a decimal written as `mantissa` digits with `scale` of them
/// after the point. Precondition: |mantissa| < 2^53 and scale <= 18. Both
/// operands are then exact doubles, so the one correctly rounded division
/// gives the same double as parsing the text (std::from_chars).
inline double exactDecimal(std::int64_t mantissa, unsigned scale) {
    return static_cast<double>(mantissa) / kPowersOfTen[scale];
}

}  // namespace mtc::core
