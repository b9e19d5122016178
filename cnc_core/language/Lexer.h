#pragma once

#include <cstdint>
#include <string_view>

namespace mtc::core {

/// A decimal number as written: value = mantissa / 10^scale (sign not
/// included; signs are separate tokens). `exact` is false when the digits do
/// not fit 18 significant digits; then `value()` parses the text itself.
struct NumberText {
    std::int64_t mantissa = 0;
    unsigned scale = 0;  ///< digits after the decimal point
    bool exact = true;
    std::uint32_t begin = 0;
    std::uint32_t end = 0;
    /// The value as a double (correctly rounded).
    double value(std::string_view source) const;
};

enum class TokenKind : std::uint8_t {
    End,         ///< end of the block text
    Identifier,  ///< letters/'_' run ("G", "MTD", "MODF_ON", "FORM_20")
    Number,      ///< 12, 12.5, .5 (no sign)
    At,          ///< '@'
    Plus,
    Minus,
    Star,
    Slash,
    LParen,
    RParen,
    LBracket,
    RBracket,
    Equals,
    Comma,
    Colon,
    Dot,      ///< '.' not starting a number (label marker)
    Comment,  ///< ';' up to the end of the block text
    Bad,      ///< a character that is no part of the NC language
};

struct Token {
    TokenKind kind = TokenKind::End;
    bool blankBefore = false;  ///< blanks (or a line break) precede the token
    std::uint32_t offset = 0;
    std::uint32_t length = 0;
    NumberText number;  ///< for TokenKind::Number
};

/// Character-level scanner over one block's text [begin, end) of the source.
/// Blanks are ' ', '\t', '\r' and '\n' (line breaks only occur inside a block
/// through continuation lines). Lowercase letters, control characters, NUL
/// and bytes >= 0x80 are not NC characters (TokenKind::Bad). Never reads
/// outside [begin, end); every scan terminates.
class Lexer {
  public:
    Lexer(std::string_view source, std::uint32_t begin, std::uint32_t end)
        : text_(source.data()), pos_(begin), end_(end) {}

    /// Offset of the next character in the source.
    std::uint32_t position() const { return pos_; }
    /// End of the scanned range.
    std::uint32_t end() const { return end_; }
    /// Moves to `offset` (clamped to the end).
    void seek(std::uint32_t offset) { pos_ = offset < end_ ? offset : end_; }
    /// True when the range is used up.
    bool atEnd() const { return pos_ >= end_; }
    /// The character at position()+ahead, or -1 past the end.
    int peek(std::uint32_t ahead = 0) const {
        return pos_ + ahead < end_ ? static_cast<unsigned char>(text_[pos_ + ahead]) : -1;
    }
    /// Moves forward by `count` characters (not past the end).
    void advance(std::uint32_t count = 1) { seek(pos_ + count); }

    static bool isBlank(int c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }
    static bool isDigit(int c) { return c >= '0' && c <= '9'; }
    static bool isUpper(int c) { return c >= 'A' && c <= 'Z'; }
    static bool isLabelChar(int c) { return isUpper(c) || isDigit(c) || c == '_' || c == '*'; }

    /// Skips blanks; returns true when at least one was skipped.
    bool skipBlanks() {
        std::uint32_t start = pos_;
        while (pos_ < end_ && isBlank(static_cast<unsigned char>(text_[pos_])))
            ++pos_;
        return pos_ != start;
    }

    /// Scans an identifier at position(): an uppercase letter, then letters and
    /// '_'; digits belong to it only after a '_' ("FORM_20"). Empty view when
    /// no identifier starts here.
    std::string_view scanIdentifier() {
        std::uint32_t start = pos_;
        if (!isUpper(peek())) return {};
        bool underscore = false;
        while (pos_ < end_) {
            int c = static_cast<unsigned char>(text_[pos_]);
            if (isUpper(c)) {
            } else if (c == '_') {
                underscore = true;
            } else if (!(underscore && isDigit(c))) {
                break;
            }
            ++pos_;
        }
        return {text_ + start, pos_ - start};
    }

    /// Scans an unsigned decimal number at position() ("12", "12.5", ".5",
    /// "12."). Returns false (and does not move) when none starts here.
    bool scanNumber(NumberText& number) {
        std::uint32_t after = scanNumberAt(text_, pos_, end_, number);
        if (after == pos_) return false;
        pos_ = after;
        return true;
    }

    /// The number rule itself, on raw text [pos, end): digits with at most
    /// one '.', at least one digit. Fills `number` and returns the offset
    /// after it; returns `pos` (and leaves `number` alone) when none starts
    /// there. Shared by scanNumber and the parser's plain-word fast path.
    static std::uint32_t scanNumberAt(const char* text, std::uint32_t pos, std::uint32_t end,
                                      NumberText& number) {
        std::uint32_t p = pos;
        std::int64_t mantissa = 0;
        unsigned scale = 0, digits = 0;
        bool exact = true, point = false;
        for (; p < end; ++p) {
            int c = static_cast<unsigned char>(text[p]);
            if (isDigit(c)) {
                ++digits;
                if (mantissa < 100000000000000000LL) {
                    mantissa = mantissa * 10 + (c - '0');
                    if (point) ++scale;
                } else if (!point || c != '0') {
                    exact = false;  // a digit the mantissa cannot hold
                }
            } else if (c == '.' && !point) {
                point = true;
            } else {
                break;
            }
        }
        if (digits == 0) return pos;
        number.mantissa = mantissa;
        number.scale = scale;
        number.exact = exact;
        number.begin = pos;
        number.end = p;
        return p;
    }

    /// Scans label characters (letters, digits, '_', '*') at position().
    std::string_view scanLabelName() {
        std::uint32_t start = pos_;
        while (pos_ < end_ && isLabelChar(static_cast<unsigned char>(text_[pos_])))
            ++pos_;
        return {text_ + start, pos_ - start};
    }

    /// At an opening `open`, skips to just past the matching `close`
    /// (same-kind nesting counted). Returns false at the block end (then
    /// position() is the block end).
    bool skipBalanced(char open, char close) {
        int depth = 0;
        while (pos_ < end_) {
            char c = text_[pos_++];
            if (c == open) {
                ++depth;
            } else if (c == close && --depth == 0) {
                return true;
            }
        }
        return false;
    }

    /// Skips a run of non-blank characters in which ( ) and [ ] are balanced,
    /// stopping at a blank or ';' outside brackets. Returns false when a
    /// bracket is not closed within the block.
    bool skipRawToken();

    /// The next token (blanks skipped, `blankBefore` set).
    Token next();

  private:
    const char* text_;
    std::uint32_t pos_;
    std::uint32_t end_;
};

}  // namespace mtc::core
