#include "cnc_core/language/Lexer.h"

#include <charconv>
#include <cmath>
#include <string>

#include "cnc_core/text/Decimal.h"

namespace mtc::core {

double NumberText::value(std::string_view source) const {
    // Exact small cases: mantissa < 2^53 and 10^scale exact -> one correctly
    // rounded division gives the same double as parsing the text.
    if (exact && mantissa < (std::int64_t{1} << 53) && scale < 19)
        return exactDecimal(mantissa, scale);
    double result = 0.0;
    std::string_view digits = source.substr(begin, end - begin);
    // from_chars does not accept a trailing '.', which NC allows ("12.").
    if (!digits.empty() && digits.back() == '.') digits.remove_suffix(1);
    std::string buffer;
    if (!digits.empty() && digits.front() == '.') {
        buffer = "0";
        buffer += digits;
        digits = buffer;
    }
    auto [ptr, error] = std::from_chars(digits.data(), digits.data() + digits.size(), result);
    (void)ptr;
    if (error == std::errc::result_out_of_range) return HUGE_VAL;
    return result;
}

bool Lexer::skipRawToken() {
    while (pos_ < end_) {
        char c = text_[pos_];
        if (isBlank(static_cast<unsigned char>(c)) || c == ';') return true;
        if (c == '(') {
            if (!skipBalanced('(', ')')) return false;
        } else if (c == '[') {
            if (!skipBalanced('[', ']')) return false;
        } else {
            ++pos_;
        }
    }
    return true;
}

Token Lexer::next() {
    Token token;
    token.blankBefore = skipBlanks();
    token.offset = pos_;
    if (atEnd()) return token;
    int c = peek();
    if (isUpper(c)) {
        token.kind = TokenKind::Identifier;
        token.length = static_cast<std::uint32_t>(scanIdentifier().size());
        return token;
    }
    if (isDigit(c) || (c == '.' && isDigit(peek(1)))) {
        token.kind = TokenKind::Number;
        scanNumber(token.number);
        token.length = pos_ - token.offset;
        return token;
    }
    if (c == ';') {
        token.kind = TokenKind::Comment;
        token.length = end_ - pos_;
        pos_ = end_;
        return token;
    }
    switch (c) {
        case '@':
            token.kind = TokenKind::At;
            break;
        case '+':
            token.kind = TokenKind::Plus;
            break;
        case '-':
            token.kind = TokenKind::Minus;
            break;
        case '*':
            token.kind = TokenKind::Star;
            break;
        case '/':
            token.kind = TokenKind::Slash;
            break;
        case '(':
            token.kind = TokenKind::LParen;
            break;
        case ')':
            token.kind = TokenKind::RParen;
            break;
        case '[':
            token.kind = TokenKind::LBracket;
            break;
        case ']':
            token.kind = TokenKind::RBracket;
            break;
        case '=':
            token.kind = TokenKind::Equals;
            break;
        case ',':
            token.kind = TokenKind::Comma;
            break;
        case ':':
            token.kind = TokenKind::Colon;
            break;
        case '.':
            token.kind = TokenKind::Dot;
            break;
        default:
            token.kind = TokenKind::Bad;
            break;
    }
    token.length = 1;
    advance();
    return token;
}

}  // namespace mtc::core
