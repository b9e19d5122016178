#pragma once

#include <string>
#include <string_view>

/// Strict readers for the values of configuration files (machine
/// configuration, tool and offset tables): numbers in plain decimal notation
/// whatever the locale, and the quoting that puts a value into a message
/// without ever copying raw control or binary bytes to a terminal.
namespace mtc::core {

/// What is wrong with a number's text ("" = nothing).
enum class NumberProblem {
    None,
    Empty,        ///< no text
    NotANumber,   ///< letters, a decimal comma, hex, several numbers ...
    NotFinite,    ///< nan, inf, or too large for a double
    Denormal,     ///< so close to 0 that it cannot be held exactly
    NotWhole,     ///< a fraction where a whole number is required
};

/// Reads `text` (all of it) as a decimal number: optional sign, digits with
/// at most one '.', optional exponent (`1e3`). Refuses hex (`0x10`),
/// `nan`, `inf`, a decimal comma (`5,5`), blanks inside, overflow to
/// infinity and denormal results (`1e-320`). Locale independent.
NumberProblem readDecimal(std::string_view text, double& value);

/// readDecimal() plus "whole number": `12`, `-3`, `1e3`; not `2.5`.
/// Whole numbers beyond ±2^53 are refused as NotWhole as well: they cannot
/// be held exactly.
NumberProblem readWholeNumber(std::string_view text, double& value);

/// One sentence for a problem: "is not a number (decimal notation, '.' as
/// decimal point)", "is not a finite number", ...
const char* describeNumberProblem(NumberProblem problem);

/// `text` quoted for a message: 'value', with control characters, bytes that
/// are not UTF-8 and the quote itself escaped (\x00, \x7f, \'), cut to
/// `limit` characters with "..." after it.
std::string quotedValue(std::string_view text, std::size_t limit = 60);

/// True when `text` is valid UTF-8 without control characters (tab allowed).
bool isPrintableText(std::string_view text);

/// `value` as short text: "30000", "0.01", "1e+06" (%g with up to 10 digits).
std::string formatConfigNumber(double value);

}  // namespace mtc::core
