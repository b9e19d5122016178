#pragma once

/// Decimal digits written straight into a buffer, two per division: the
/// block numbers of the interpreter's outputs ("N0012", once per move) and
/// of the compiler's object files. No locale is involved (D-013).
#include <cstring>

namespace mtc::core {

/// "00" "01" ... "99".
inline constexpr char kDigitPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

/// Writes the two digits of `pair` (0..99) before `first`; returns the new first.
/// One 2-byte copy (a load and a store) instead of two bytes.
inline char* putDigitPair(char* first, unsigned pair) {
    first -= 2;
    std::memcpy(first, &kDigitPairs[2 * pair], 2);
    return first;
}

/// Writes the four digits of `number` (0..9999, leading zeros) to `at`.
inline void writeFourDigits(char* at, int number) {
    const auto n = static_cast<unsigned>(number);
    putDigitPair(putDigitPair(at + 4, n % 100), n / 100);
}

}  // namespace mtc::core
