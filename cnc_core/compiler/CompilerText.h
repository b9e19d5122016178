#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

/// Small text helpers of the NC compiler (block numbers, message limits,
/// names in block texts).
namespace mtc::core {

constexpr std::size_t kMaxBriefMessage = 52;    ///< seed 001 ch. 9
constexpr std::size_t kMaxDetailLines = 14;     ///< seed 001 ch. 9
constexpr std::size_t kMaxDetailLength = 65;    ///< seed 001 ch. 9
constexpr std::size_t kMaxObjectLine = 71;      ///< seed 001 ch. 10/11
constexpr std::size_t kMaxBlockChars = 230;     ///< seed 001 ch. 10/11
constexpr std::size_t kMaxBlockLines = 4;       ///< seed 001 ch. 10/11
constexpr std::size_t kMaxObjectLines = 10000;  ///< seed 001 ch. 11

/// "0053" (four digits, more when the number is larger).
std::string formatFourDigits(int number);
/// "N0053".
std::string formatBlockNumber(int number);
/// The message cut to 52 characters.
std::string limitMessage(std::string_view message);
/// Detail lines wrapped at blanks to <= 65 characters, at most 14 lines.
std::vector<std::string> limitDetails(const std::vector<std::string>& details);
/// Wraps `text` at blanks into lines of at most `width` characters (a word
/// longer than `width` is cut).
std::vector<std::string> wrapWords(std::string_view text, std::size_t width);

/// True for A-Z, 0-9 and '_' (one table look-up: the macro and keyword
/// scans call it for every character of every block).
inline bool isNameChar(char c) {
    static constexpr std::array<bool, 256> kNameChars = [] {
        std::array<bool, 256> table{};
        for (int k = 0; k < 256; ++k)
            table[static_cast<std::size_t>(k)] =
                (k >= 'A' && k <= 'Z') || (k >= '0' && k <= '9') || k == '_';
        return table;
    }();
    return kNameChars[static_cast<unsigned char>(c)];
}

/// Offset of the ';' comment of a block text outside brackets, or text.size().
std::size_t commentOffset(std::string_view text);

/// The number formatted for a block text: up to 4 decimals, no trailing
/// zeros, "-0" written as "0".
std::string formatCoordinate(double value);
/// Appends formatCoordinate(value) to `out` (no temporary string).
void appendCoordinate(std::string& out, double value);
/// std::llround for finite values of magnitude at most 1e18 (halves away
/// from zero), computed inline.
inline long long roundHalfAway(double value) {
    // the fraction is exact (|value| <= 1e18 < 2^63, and a double with a
    // fraction is below 2^52)
    const auto whole = static_cast<long long>(value);  // towards zero
    const double fraction = value - static_cast<double>(whole);
    if (fraction >= 0.5) return whole + 1;
    if (fraction <= -0.5) return whole - 1;
    return whole;
}
/// `value` in whole steps of 0.0001 (the resolution written), rounded; 0
/// for values that are not finite or beyond 1e14 (inline: the CF/RD pass
/// rounds every corner point several times).
inline long long coordinateTicks(double value) {
    if (!std::isfinite(value) || std::fabs(value) > 1e14) return 0;
    return roundHalfAway(value * 10000.0);
}
/// Appends a number of 0.0001 steps as formatCoordinate does. Incremental
/// words written as differences of ticks add up exactly along a chain.
void appendTicks(std::string& out, long long ticks);
/// Longest text `writeTicks` writes ("-9223372036854775808" without its
/// fraction is 20 characters, with ".dddd" 25).
constexpr std::size_t kMaxTicksText = 26;
/// Writes the text appendTicks(ticks) appends so that it ends right before
/// `end`; returns its first character (at most kMaxTicksText before `end`).
char* writeTicksBefore(char* end, long long ticks);

/// Keywords (written in capitals) looked for in block texts, letters of the
/// text compared without case. A cheap pre-check of passes that act only on
/// blocks naming one of their keywords: built once per pass, it reads each
/// text once and compares a keyword only where a character can start one.
class CaselessNeedles {
  public:
    /// At most 32 non-empty needles in capitals ('_' and digits as they are).
    explicit CaselessNeedles(std::initializer_list<std::string_view> upperNeedles);
    /// True when `text` contains one of the needles.
    bool foundIn(std::string_view text) const;

  private:
    /// First position from `from` on where a needle may start (text.size(): none).
    std::size_t nextStart(std::string_view text, std::size_t from) const;
    bool matchesAt(std::string_view text, std::size_t at, const std::string& needle) const;

    std::vector<std::string> needles_;
    /// Bit n set: needle n starts with this character (either case).
    std::array<std::uint32_t, 256> startingHere_{};
    /// Bit n set: needle n has this character second (either case), or
    /// has one character only.
    std::array<std::uint32_t, 256> secondHere_{};
};

/// True when `text` contains one of `upperNeedles` (CaselessNeedles for one text).
bool containsAnyCaseless(std::string_view text,
                         std::initializer_list<std::string_view> upperNeedles);

}  // namespace mtc::core
