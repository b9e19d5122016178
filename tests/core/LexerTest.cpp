// The character-level scanner under the parser.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cnc_core/language/Lexer.h"

using namespace mtc::core;

namespace {

struct Scanned {
    TokenKind kind;
    std::string text;
    bool blankBefore;
};

std::vector<Scanned> tokens(const std::string& text) {
    Lexer lexer(text, 0, static_cast<std::uint32_t>(text.size()));
    std::vector<Scanned> result;
    for (int guard = 0; guard < 1000; ++guard) {
        Token t = lexer.next();
        if (t.kind == TokenKind::End) break;
        result.push_back({t.kind, text.substr(t.offset, t.length), t.blankBefore});
    }
    return result;
}

std::string kinds(const std::string& text) {
    std::string out;
    for (const Scanned& s : tokens(text)) {
        switch (s.kind) {
            case TokenKind::Identifier:
                out += "id";
                break;
            case TokenKind::Number:
                out += "num";
                break;
            case TokenKind::At:
                out += "@";
                break;
            case TokenKind::Plus:
                out += "+";
                break;
            case TokenKind::Minus:
                out += "-";
                break;
            case TokenKind::Star:
                out += "*";
                break;
            case TokenKind::Slash:
                out += "/";
                break;
            case TokenKind::LParen:
                out += "(";
                break;
            case TokenKind::RParen:
                out += ")";
                break;
            case TokenKind::LBracket:
                out += "[";
                break;
            case TokenKind::RBracket:
                out += "]";
                break;
            case TokenKind::Equals:
                out += "=";
                break;
            case TokenKind::Comma:
                out += ",";
                break;
            case TokenKind::Colon:
                out += ":";
                break;
            case TokenKind::Dot:
                out += ".";
                break;
            case TokenKind::Comment:
                out += "comment";
                break;
            case TokenKind::Bad:
                out += "bad";
                break;
            case TokenKind::End:
                break;
        }
        out += ' ';
    }
    return out;
}

TEST(Lexer, TokensOfABlock) {
    EXPECT_EQ(kinds("N0010 G1 X-12.5 ;go"), "id num id num id - num comment ");
    EXPECT_EQ(kinds("@1:120=MTD(60,,4)*2/3+.5"),
              "@ num : num = id ( num , , num ) * num / num + num ");
    EXPECT_EQ(kinds("BSR .*WSTCH [TEXT]"), "id . * id [ id ] ");
}

TEST(Lexer, IdentifiersTakeDigitsOnlyAfterAnUnderscore) {
    auto t = tokens("G1 FORM_20 MODF_ON TL_RADIUS MTD LA_ON2");
    ASSERT_EQ(t.size(), 7u);
    EXPECT_EQ(t[0].text, "G");
    EXPECT_EQ(t[1].text, "1");
    EXPECT_EQ(t[2].text, "FORM_20");
    EXPECT_EQ(t[3].text, "MODF_ON");
    EXPECT_EQ(t[4].text, "TL_RADIUS");
    EXPECT_EQ(t[5].text, "MTD");
    EXPECT_EQ(t[6].text, "LA_ON2");
}

TEST(Lexer, BlankBefore) {
    auto t = tokens("Y1 25 Z1-42");
    ASSERT_EQ(t.size(), 7u);
    EXPECT_FALSE(t[1].blankBefore);  // "1"
    EXPECT_TRUE(t[2].blankBefore);   // "25"
    EXPECT_FALSE(t[5].blankBefore);  // "-"
}

TEST(Lexer, NumbersKeepMantissaAndScale) {
    std::string text = "12.345 .5 7. 0042 123456789012345678901234";
    Lexer lexer(text, 0, static_cast<std::uint32_t>(text.size()));
    Token a = lexer.next(), b = lexer.next(), c = lexer.next(), d = lexer.next(), e = lexer.next();
    EXPECT_EQ(a.number.mantissa, 12345);
    EXPECT_EQ(a.number.scale, 3u);
    EXPECT_EQ(a.number.value(text), 12.345);
    EXPECT_EQ(b.number.value(text), 0.5);
    EXPECT_EQ(c.number.value(text), 7.0);
    EXPECT_EQ(c.length, 2u);
    EXPECT_EQ(d.number.value(text), 42.0);
    EXPECT_FALSE(e.number.exact);
    EXPECT_DOUBLE_EQ(e.number.value(text), 123456789012345678901234.0);
    EXPECT_EQ(lexer.next().kind, TokenKind::End);
}

TEST(Lexer, LongFractionsStayExact) {
    std::string text = "0.1234567890123456789";
    Lexer lexer(text, 0, static_cast<std::uint32_t>(text.size()));
    Token t = lexer.next();
    EXPECT_EQ(t.number.value(text), 0.1234567890123456789);
}

TEST(Lexer, BadCharacters) {
    std::string text = std::string("G1") + '\0' + "x\x80#";
    EXPECT_EQ(kinds(text), "id num bad bad bad bad ");
}

TEST(Lexer, CommentRunsToTheEndOfTheBlockText) {
    std::string text = "G1 ;a ( [ \n more";
    auto t = tokens(text);
    ASSERT_EQ(t.size(), 3u);
    EXPECT_EQ(t[2].text, ";a ( [ \n more");
}

TEST(Lexer, ScansStayInsideTheirRange) {
    std::string text = "G1 X5 ;rest";
    Lexer lexer(text, 3, 5);  // only "X5"
    EXPECT_EQ(lexer.next().kind, TokenKind::Identifier);
    EXPECT_EQ(lexer.next().kind, TokenKind::Number);
    EXPECT_EQ(lexer.next().kind, TokenKind::End);
    EXPECT_EQ(lexer.peek(), -1);
}

TEST(Lexer, BalancedGroups) {
    std::string text = "(a (b) c) tail";
    Lexer lexer(text, 0, static_cast<std::uint32_t>(text.size()));
    EXPECT_TRUE(lexer.skipBalanced('(', ')'));
    EXPECT_EQ(lexer.position(), 9u);
    std::string open = "(never closed";
    Lexer unclosed(open, 0, static_cast<std::uint32_t>(open.size()));
    EXPECT_FALSE(unclosed.skipBalanced('(', ')'));
    EXPECT_TRUE(unclosed.atEnd());
}

TEST(Lexer, RawTokens) {
    std::string text = "ACD_COMP[@1:120]-0,2;x (a b)c d";
    Lexer lexer(text, 0, static_cast<std::uint32_t>(text.size()));
    EXPECT_TRUE(lexer.skipRawToken());
    EXPECT_EQ(lexer.position(), 20u);  // stops at ';'
    lexer.seek(23);
    EXPECT_TRUE(lexer.skipRawToken());  // blanks inside brackets belong to the token
    EXPECT_EQ(text.substr(23, lexer.position() - 23), "(a b)c");
    std::string open = "X[1 2";
    Lexer unclosed(open, 0, static_cast<std::uint32_t>(open.size()));
    EXPECT_FALSE(unclosed.skipRawToken());
}

TEST(Lexer, LabelNames) {
    std::string text = "*WSTCH_2 rest";
    Lexer lexer(text, 0, static_cast<std::uint32_t>(text.size()));
    EXPECT_EQ(lexer.scanLabelName(), "*WSTCH_2");
}

}  // namespace
