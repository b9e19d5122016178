#pragma once

#include <cstdint>

#include "cnc_core/language/Keywords.h"
#include "cnc_core/language/Lexer.h"
#include "cnc_core/language/Word.h"

// The rules of an address word ("G1", "X-12.5", "S1=800") that both of the
// parser's paths use: the general word parser (BlockParser.cpp) and the fast
// path for plain blocks (BlockParserPlain.cpp). Inline: the fast path runs
// them for every word of a million-block program.
namespace mtc::core::word_rules {

/// The word kind of an address letter that takes a value (G, X, S, I, ...)
/// and whether it may carry an axis or spindle index; false for 'N' and for
/// letters that are no address.
constexpr bool addressKind(char letter, WordKind& kind, bool& indexed) {
    indexed = false;
    switch (letter) {
        case 'G':
            kind = WordKind::G;
            return true;
        case 'M':
            kind = WordKind::M;
            return true;
        case 'Q':
            kind = WordKind::Q;
            return true;
        case 'T':
            kind = WordKind::T;
            return true;
        case 'E':
            kind = WordKind::E;
            return true;
        case 'F':
            kind = WordKind::F;
            return true;
        case 'D':
            kind = WordKind::D;
            return true;
        case 'S':
            kind = WordKind::S;
            indexed = true;
            return true;
        case 'I':
        case 'J':
        case 'K':
            kind = WordKind::CircleCenter;
            return true;
        default:
            if (!isAxisLetter(letter)) return false;
            kind = WordKind::Axis;
            indexed = true;
            return true;
    }
}

/// Words whose value is a positive whole number.
constexpr bool valueMustBeWhole(WordKind kind) {
    switch (kind) {
        case WordKind::G:
        case WordKind::M:
        case WordKind::Q:
        case WordKind::T:
        case WordKind::E:
        case WordKind::D:
            return true;
        default:
            return false;
    }
}

/// The index digit (1..3) of an axis or spindle word at `pos` of raw text
/// [.., end), or 0 when the digit there starts the value instead. An index
/// is followed by '=', a sign, or blanks and then a value: "Y1 25",
/// "Z1-42", "X2=0"; but "S2800", "Y1.5", "X1 Y2" have none.
inline std::uint8_t axisIndexAt(const char* text, std::uint32_t pos, std::uint32_t end) {
    auto at = [&](std::uint32_t offset) {
        return offset < end ? static_cast<unsigned char>(text[offset]) : -1;
    };
    int digit = at(pos);
    if (digit < '1' || digit > '3') return 0;
    int next = at(pos + 1);
    bool isIndex = next == '=' || next == '+' || next == '-';
    if (!isIndex && (next == ' ' || next == '\t')) {
        std::uint32_t ahead = pos + 2;
        while (Lexer::isBlank(at(ahead)))
            ++ahead;
        int after = at(ahead);
        isIndex = Lexer::isDigit(after) || after == '.' || after == '+' || after == '-' ||
                  after == '@' || after == '=';
    }
    return isIndex ? static_cast<std::uint8_t>(digit - '0') : 0;
}

/// A block number has this many digits ("N0012"); fewer get a warning, more
/// are an error.
constexpr std::uint32_t kBlockNumberDigits = 4;

/// The digits of a block number from `pos` of raw text [.., end) (after its
/// 'N'): the value of the first nine and how many there are.
struct BlockNumberDigits {
    std::int64_t value = 0;
    std::uint32_t count = 0;
    std::uint32_t end = 0;  ///< offset after the last digit
};

inline BlockNumberDigits blockNumberDigitsAt(const char* text, std::uint32_t pos,
                                             std::uint32_t end) {
    BlockNumberDigits digits;
    std::uint32_t p = pos;
    for (; p < end && Lexer::isDigit(static_cast<unsigned char>(text[p])); ++p) {
        if (digits.count < 9) digits.value = digits.value * 10 + (text[p] - '0');
        ++digits.count;
    }
    digits.end = p;
    return digits;
}

/// Why a written number cannot be the value of its word.
enum class NumberCheck { Ok, NegativeWhole, NotWhole };

/// Drops trailing decimal zeros the packed word form cannot hold (more than
/// 7 decimals, or a mantissa beyond 31 bits) and checks the whole-number
/// words (G, M, Q, T, E, D).
inline NumberCheck normalizeNumber(WordKind kind, bool negative, std::int64_t& mantissa,
                                   unsigned& scale) {
    while ((scale > 7 || mantissa > 2147483647) && scale > 0 && mantissa % 10 == 0) {
        mantissa /= 10;
        --scale;
    }
    if ((!negative && scale == 0) || !valueMustBeWhole(kind)) return NumberCheck::Ok;
    if (negative) return NumberCheck::NegativeWhole;
    while (scale > 0 && mantissa % 10 == 0) {
        mantissa /= 10;
        --scale;
    }
    return scale > 0 ? NumberCheck::NotWhole : NumberCheck::Ok;
}

}  // namespace mtc::core::word_rules
