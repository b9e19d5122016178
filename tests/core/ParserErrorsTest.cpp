// Every parser error path: stable code, position, recovery at the next block.
#include <gtest/gtest.h>

#include "ParserTestSupport.h"

using namespace mtc::core;
using namespace mtc::core::testing;

namespace {

struct ErrorCase {
    const char* line;
    const char* code;
    int column;
};

TEST(ParserErrors, EachCodeWithItsColumn) {
    const ErrorCase cases[] = {
        {"N0001 G1 H5", "PARSE_UNKNOWN_WORD", 10},
        {"N0001 XYZ5", "PARSE_UNKNOWN_WORD", 7},
        {"N0001 G1 N0002", "PARSE_MISPLACED_BLOCK_NUMBER", 10},
        {"N12345 G1", "PARSE_BAD_BLOCK_NUMBER", 1},
        {"N0001 G1.5", "PARSE_BAD_NUMBER", 8},
        {"N0001 M-3", "PARSE_BAD_NUMBER", 9},
        {"N0001 T=2.5", "PARSE_BAD_NUMBER", 7},
        {"N0001 X1.2.3", "PARSE_BAD_NUMBER", 8},
        {"N0001 X99999999999999999999", "PARSE_BAD_NUMBER", 8},
        {"N0001 G1 X", "PARSE_MISSING_VALUE", 10},
        {"N0001 RI", "PARSE_MISSING_VALUE", 7},
        {"N0001 G1 25", "PARSE_UNEXPECTED_NUMBER", 10},
        {"N0001 G1 -5", "PARSE_UNEXPECTED_NUMBER", 10},
        {"N0001 G1 .5", "PARSE_UNEXPECTED_NUMBER", 10},
        {"N0001 G1 ----", "PARSE_UNEXPECTED_CHARACTER", 10},
        {"N0001 G1 =5", "PARSE_UNEXPECTED_CHARACTER", 10},
        {"N0001 G1 x5", "LEX_BAD_CHAR", 10},
        {"N0001 G1 #", "LEX_BAD_CHAR", 10},
        {"N0001 G1 :", "PARSE_MISPLACED_PRIMARY", 10},
        {"N0001 G1 / X5", "PARSE_MISPLACED_SKIP", 10},
        {"N0001 G1 )", "PARSE_UNBALANCED_PARENTHESES", 10},
        {"N0001 G1 (open text", "PARSE_UNBALANCED_TEXT", 10},
        {"N0001 G1 [open", "PARSE_UNBALANCED_TEXT", 10},
        {"N0001 . G1", "PARSE_MISSING_LABEL_NAME", 7},
        {"N0001 BRA", "PARSE_MISSING_LABEL", 7},
        {"N0001 @1", "PARSE_EXPECTED_ASSIGNMENT", 9},
        {"N0001 SPC", "PARSE_READ_ONLY_WORD", 7},
    };
    for (const ErrorCase& c : cases) {
        Program p = parse(std::string(c.line) + "\nN0002 G1 X1\n", 7);
        ASSERT_FALSE(p.diagnostics.empty()) << c.line;
        const Diagnostic& d = p.diagnostics.items()[0];
        EXPECT_EQ(d.code, c.code) << c.line;
        EXPECT_EQ(d.severity, Severity::Error) << c.line;
        EXPECT_EQ(d.where.program, 7) << c.line;
        EXPECT_EQ(d.where.line, 1) << c.line;
        EXPECT_EQ(d.where.column, c.column) << c.line << ": " << d.message;
        EXPECT_FALSE(d.message.empty());
        // Recovery: the block is flagged, the next block parses cleanly.
        ASSERT_EQ(p.blocks.size(), 2u) << c.line;
        EXPECT_TRUE(p.blocks[0].flags & kBlockHasError) << c.line;
        EXPECT_FALSE(p.blocks[1].flags & kBlockHasError) << c.line;
        EXPECT_EQ(describeBlock(p, 1), "G1 X1") << c.line;
        EXPECT_EQ(p.diagnostics.size(), 1u) << c.line;
    }
}

TEST(ParserErrors, WordsBeforeTheErrorAreKept) {
    Program p = parse("N0001 G1 X5 H7 Y3 ;still shown");
    EXPECT_EQ(describeBlock(p, 0), "G1 X5");
    EXPECT_TRUE(p.blocks[0].flags & kBlockHasError);
    EXPECT_EQ(p.text(p.blocks[0].comment), "still shown");
}

TEST(ParserErrors, BlockIdInDiagnostics) {
    Program p = parse("N0012 G1 H\n");
    EXPECT_EQ(p.diagnostics.items()[0].where.block, "N0012");
    EXPECT_EQ(
        formatDiagnostic(p.diagnostics.items()[0]).find("N0012 line 1:10") != std::string::npos,
        true);
}

TEST(ParserErrors, NulBytesAndBinaryGarbage) {
    std::string text = "N0001 G1";
    text += '\0';
    text += "X5\nN0002 \x01\x02\xff\xfe\nN0003 G0\n";
    Program p = parse(text);
    ASSERT_EQ(p.blocks.size(), 3u);
    ASSERT_EQ(codes(p), (std::vector<std::string>{"LEX_BAD_CHAR", "LEX_BAD_CHAR"}));
    EXPECT_EQ(p.diagnostics.items()[0].where.column, 9);
    EXPECT_NE(p.diagnostics.items()[0].message.find("0x00"), std::string::npos);
    EXPECT_EQ(describeBlock(p, 2), "G0");
}

TEST(ParserErrors, DiagnosticsAreCapped) {
    std::string text;
    for (int i = 0; i < 5000; ++i)
        text += "H1\n";
    Program p = parse(text);
    EXPECT_EQ(p.blocks.size(), 5000u);
    EXPECT_EQ(p.diagnostics.size(), 1001u);
    EXPECT_EQ(p.diagnostics.items().back().code, "PARSE_TOO_MANY_DIAGNOSTICS");
}

TEST(ParserErrors, MegabyteLinesParse) {
    std::string words;
    for (int i = 0; i < 60000; ++i)
        words += "X1 ";  // 180 kB of words in one block
    Program a = parse("N0001 " + words);
    EXPECT_TRUE(a.diagnostics.empty());
    EXPECT_EQ(a.blocks[0].wordCount, 60000);
    EXPECT_EQ(a.words[59999].column, 65535);  // saturated beyond 65535

    Program b = parse("N0001 G1 (" + std::string(1 << 20, 'A'));  // unclosed text
    EXPECT_NE(find(b, "PARSE_UNBALANCED_TEXT"), nullptr);
    Program c = parse("@1=" + std::string(1 << 20, '('));
    EXPECT_NE(find(c, "PARSE_EXPRESSION_TOO_DEEP"), nullptr);
    Program d = parse(std::string(1 << 20, ')'));
    EXPECT_NE(find(d, "PARSE_UNBALANCED_PARENTHESES"), nullptr);
    Program e = parse(std::string(1 << 20, 'G'));
    EXPECT_NE(find(e, "PARSE_UNKNOWN_WORD"), nullptr);
    Program f = parse(std::string(1 << 20, ' ') + "G1");
    EXPECT_TRUE(f.diagnostics.empty());
    EXPECT_EQ(f.words[0].column, 65535);
}

TEST(ParserErrors, TooManyWordsInOneBlock) {
    std::string words;
    for (int i = 0; i < 70000; ++i)
        words += "X1";
    Program p = parse(words);
    EXPECT_NE(find(p, "PARSE_TOO_MANY_WORDS"), nullptr);
    EXPECT_EQ(p.blocks[0].wordCount, 65535);
}

TEST(ParserErrors, EmptyAndWhitespaceOnlySources) {
    EXPECT_TRUE(parse("").blocks.empty());
    EXPECT_TRUE(parse("\n\n   \n").blocks.empty());
    EXPECT_TRUE(parse("").diagnostics.empty());
}

}  // namespace
