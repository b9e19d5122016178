#pragma once

#include <cstddef>
#include <string>
#include <string_view>

/// Number text of the core, the CLI and every file they write, independent
/// of the process locale (D-013). The panel's QApplication switches the C
/// library to the desk's locale; under de_DE `printf("%g")` writes "0,5" and
/// `strtod("0.5")` stops at the '.', so no core code may use them for
/// numbers. These functions use std::to_chars / std::from_chars, which are
/// defined "as in the C locale" whatever setlocale() says.
namespace mtc::core {

/// `value` as printf("%.<precision>g") prints it in the C locale
/// (precision 0 counts as 1): formatGeneral(0.5, 10) = "0.5",
/// formatGeneral(1e6, 6) = "1e+06".
std::string formatGeneral(double value, int precision = 6);

/// `value` as printf("%.<decimals>f") prints it in the C locale:
/// formatFixed(2.5, 4) = "2.5000".
std::string formatFixed(double value, int decimals);

/// The shortest "%.<n>g" text (n = 1 .. 17) that reads back as exactly
/// `value`: 0.1 -> "0.1", 1.0 / 3 -> "0.3333333333333333".
std::string formatRoundTrip(double value);

/// Reads the longest number at the start of [first, last) as strtod() does
/// in the C locale: leading blanks, an optional sign, digits with one '.',
/// an optional exponent, or inf / nan. Hexadecimal floats are not numbers
/// here ("0x10" reads as 0). Out of range gives ±HUGE_VAL or 0 as strtod.
/// Returns the end of the number, or `first` when there is none (value 0).
const char* readNumberPrefix(const char* first, const char* last, double& value);

/// readNumberPrefix() over a whole string_view; returns the characters read
/// (0 = no number).
std::size_t readNumberPrefix(std::string_view text, double& value);

/// strtod(text, nullptr) in the C locale: the leading number or 0.
double leadingNumber(std::string_view text);

}  // namespace mtc::core
