// The parser's fast path for whole lines (BlockParser::parseLine, issue 21):
// a line is scanned once, its plain words stored as they are found, and the
// line end found on the way. Every input is parsed both ways (the general
// path with ParseOptions::plainBlockFastPath off) and must give the same
// program; a few tests check the values themselves.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "cnc_core/language/Parser.h"
#include "tests/support/ProgramDifference.h"

using namespace mtc::core;
using mtc::core::testing::differenceBetweenPaths;
using mtc::core::testing::parseWith;

namespace {

// Line ends, blanks and what may follow a line the fast path has taken.
const std::vector<std::string> kLineShapes = {
    "N0001 G1 X1",  // no final newline
    "N0001 G1 X1\n",
    "N0001 G1 X1\r\nN0002 X2\r\n",
    "N0001 G1 X1\r",      // a '\r' and the end of the text
    "N0001 G1\rX1\n",     // a '\r' inside the line is a blank
    "N0001\r/X1\n",       // ... and then the skip slash is misplaced
    "N0001 \r\nN0002\r",  // blanks before the line end
    "N0001 X1\r\r\n",
    "N0001\tG1\tX1\t\n",
    "N0001 \t G1  X1   \n",
    "N0001 G1 X1 ; comment\nN0002 X2\n",
    "N0001 G1 X1 (text) Y2\n",
    "N0001 G1 X1\n      Y2 Z3\nN0002 X4\n",       // a continuation line
    "N0001 G1 X1\n      \nN0002 X4\n",            // six blanks only: no continuation
    "N0001 G1 X1\n ;comment\nN0002 X4\n",         // a blank first: comment line
    "N0001 G1 X1\n       ; comment\nN0002 X4\n",  // continuation with a comment
    "N0001 X1\nN0002 PROGRAMMENDE\nN0003 X1\n",
    "N0001 X1\nN0002 PROGRAMMENDE ; end\n\n  \n",
    "N0001 DEFINE FOO AS G1\nN0002 FOO X1\nN0003 X2\n",
    // a DEFINE the per-block path takes (short block number) just before a
    // use of its macro: fuzz finding of 2026-11-27
    "N00DEFINE FAST AS G01 F15000\nFAST X5\nN0003 X2\n",
    "DEFINE FAST AS G01\nFAST X5\n",
    "N0001 .L1 X1\nN0002 BRA .L1\nN0003 .L1 X2\n",
    "G1 X1 Y2\nX1\nF1000\n",
    "\n\nN0001 X1\n\n\nN0002 X2",
    "N0001\nN0002 \nN0003",
    "N0001:0002 X1\nN0001 X1\n",
    std::string("N0001 X1\0Y2\nN0002 X2\n", 21),  // a NUL inside the line
    "N0001 x1\nN0002 GAX X1\nN0003 X1 @1=2\n",
    "N0001 X1 \n5\n",         // an axis index looked for past the line end
    "N0001 X1\t\r\n25 Y1\n",  // ... and past a '\r'
    "N0001 X1 25 Y1-3 Z2=4 S1 3000 S2=800 S2800\n",
    "n0001 X1\nN001 X1\nN00001 X1\nN0001X1\nN0001.5 X1\n",
    "N0001 X1\n\tN0002 X2\n  N0003 X3\n",
};

// Numbers around the limits of the common case: nine digits, seven decimals,
// 2^31, 17 digits; signs; whole-number words; no exponents in NC ("1E5" is X1 E5).
const std::vector<std::string> kNumbers = {
    "N0001 X999999999 Y1000000000 Z-999999999 A2147483647 B2147483648 C-2147483648\n",
    "N0002 X0.1234567 Y0.12345678 Z1.00000000 A1234567.8901 B.5 C5. U-.5 V+.5\n",
    "N0003 X12345678901234567 Y123456789012345678 Z12345678901234567890\n",
    "N0004 X00000000000000000000001 Y0.000000000000000000001 Z-0 A-0.0 B+0\n",
    "N0005 G1 G01 G1.0 G1.5 G-1 G+1 M3. M-3 T1.00 T0.10 D1.5 E+2 Q007\n",
    "N0006 X1E5 Y1e5 Z1.5E-3\n",
    "N0007 X- Y+ Z. A.. B1..2 C1.2.3 U-+1 V+-1\n",
    "N0008 F99999999 F999999999 F9999999999 S12.3456789\n",
    // around the narrow form's 27-bit mantissa (|m| < 2^26 = 67108864)
    "N0009 X67108863 Y-67108863 Z67108864 A-67108864 B67108.863 C-67108.864 U.67108863\n",
    "N0010 F67108863 F67108864 S67108863 S-1 I-6710.8863 J67108864.0 K0.67108864 T67108864\n",
    "N0011 X64986.000 Y-9999.999 Z33554.432 A-33554.431 B6710.8864 C9999.9999 U99999.999\n",
    // and the old 18-bit one (|m| <= 131071)
    "N0012 X131071 Y-131071 Z131072 A-131072 B13.1071 C-1.31072 U.0131071 V1310.710\n",
};

TEST(ParserWholeLine, LineShapesParseAsOnTheGeneralPath) {
    for (const std::string& text : kLineShapes)
        EXPECT_EQ(differenceBetweenPaths(text), "") << text;
    std::string all;
    for (const std::string& text : kLineShapes)
        all += text + "\n";
    EXPECT_EQ(differenceBetweenPaths(all), "");
}

TEST(ParserWholeLine, NumbersParseAsOnTheGeneralPath) {
    for (const std::string& text : kNumbers) {
        EXPECT_EQ(differenceBetweenPaths(text), "") << text;
        std::string crlf = text;
        crlf.insert(crlf.size() - 1, "\r");
        EXPECT_EQ(differenceBetweenPaths(crlf), "") << crlf;
        EXPECT_EQ(differenceBetweenPaths(text.substr(0, text.size() - 1)), "") << text;
    }
}

TEST(ParserWholeLine, MoreHeadsThanTheNarrowFormCodes) {
    // 14 letters with 8 scales each: 112 heads, beyond the word list's 30
    // codes; the words after the 30th head are stored in the wide form.
    const std::string letters = "XYZABCUVWIJKFS";
    std::string text;
    int block = 0;
    for (unsigned scale = 0; scale < 8; ++scale) {
        for (int round = 0; round < 2; ++round) {
            text += "N" + std::to_string(1000 + block++);
            for (char letter : letters)
                text += std::string(" ") + letter + "1" +
                        (scale == 0 ? "" : "." + std::string(scale - 1, '0') + "5");
            text += "\n";
        }
    }
    EXPECT_EQ(differenceBetweenPaths(text), "");
    const Program program = parseWith(text, true);
    ASSERT_EQ(program.words.size(), 16 * letters.size());
    EXPECT_EQ(program.words[0].number, 1.0);
    EXPECT_EQ(program.words[program.words.size() - 1].number, 1.0000005);
}

TEST(ParserWholeLine, LongLinesParseAsOnTheGeneralPath) {
    // a word past column 255, a line of more than 65535 bytes, more than
    // 65535 words in one line (PARSE_TOO_MANY_WORDS)
    EXPECT_EQ(differenceBetweenPaths("N0001" + std::string(300, ' ') + "X1 Y2\nN0002 X3\n"), "");
    EXPECT_EQ(differenceBetweenPaths("N0001 X1" + std::string(70000, ' ') + "\nN0002 X3\n"), "");
    std::string manyWords = "N0001";
    for (int i = 0; i < 66000; ++i)
        manyWords += " X1";
    const Program program = parseWith(manyWords + "\nN0002 X3\n", true);
    EXPECT_EQ(differenceBetweenPaths(manyWords + "\nN0002 X3\n"), "");
    ASSERT_EQ(program.diagnostics.size(), 1u);
    EXPECT_EQ(program.diagnostics.items()[0].code, "PARSE_TOO_MANY_WORDS");
    EXPECT_EQ(program.blocks.size(), 2u);
}

// Lines once a macro is known (takeMacroLine): a use makes the whole block
// one macro word; a comment, a label, a skip, an enhanced number or a line
// that may be continued go to the general path.
const std::vector<std::string> kMacroLines = {
    "N0001 X1 FEED COOL CF0.8\nN0002 X2 Y3\n",
    "N0001 FEED ;comment\nN0002 FEED;c\nN0003 ;FEED\n",
    "N0001 X1 (FEED) COOL\nN0002 X1 (FEED)\nN0003 @1=FEED\nN0004 X.FEED\nN0005 XFEED\n",
    "N0001 .L1 FEED\n/N0002 FEED\nN0003 /FEED\nN0004 :FEED\n:N0005 FEED\n",
    "N0001:0002 FEED\nN0001:0003 X1\n",
    "FEED X1\nX1 FEED\nfeed X1\nN0001FEED\nN001 FEED\n",
    "N0001   FEED  \r\nN0002\tFEED\t\nN0003 FEED\rX1\nN0004 FEED\r",
    "N0001 FEED\n      X2\nN0002 FEED\n       ;c\n",
    "N0001 DEFINE SLOW AS F10\nN0002 SLOW X1\nN0003 DEFINESLOW\nN0004 X1 DEFINE FEED AS F1\n",
    "N0001 DEFINE FEED AS F10\nN0002 FEED X1\nN0003 FEEDS\n",
    "N0001 G1 X1 COOL\nN0002 PROGRAMMENDE\nN0003 FEED\n",
    "N0001 COOL PROGRAMMENDE\nN0002 FEED\n",
    std::string("N0001 FEED\0X\nN0002 FEED\n", 24),
};

TEST(ParserWholeLine, MacroLinesParseAsOnTheGeneralPath) {
    const std::vector<std::string> macros = {"FEED", "COOL"};
    for (const std::string& text : kMacroLines) {
        EXPECT_EQ(differenceBetweenPaths(text, macros), "") << text;
        EXPECT_EQ(differenceBetweenPaths(text), "") << text;
    }
    EXPECT_EQ(
        differenceBetweenPaths("N0001 X1 FEED" + std::string(70000, ' ') + "\nN0002 X3\n", macros),
        "");
    EXPECT_EQ(
        differenceBetweenPaths("N0001" + std::string(70000, ' ') + "FEED\nN0002 X3\n", macros), "");
    const Program program = parseWith("N0001 X1  FEED COOL  \nN0002 X2\n", true, macros);
    ASSERT_EQ(program.blocks.size(), 2u);
    ASSERT_EQ(program.blocks[0].wordCount, 1u);
    const Word word = program.words[program.blocks[0].firstWord];
    EXPECT_EQ(word.kind, WordKind::Command);
    EXPECT_EQ(program.text(word.text), "X1  FEED COOL");
    EXPECT_EQ(word.column, 7);
    EXPECT_TRUE(program.usesCompilerKeywords);
}

// A chamfer or rounding as the last word of a line (takeCornerWord) and the
// shapes the general path reads.
TEST(ParserWholeLine, CornerWordsParseAsOnTheGeneralPath) {
    const std::string text =
        "N0001 X1 CF0.8\nX1 RD1.5  \nN0002 X1 CF0.8 ;c\nX1 CF1A\nX1 CF.\nX1 CF\nX1 CF \n"
        "X1 CF=1\nX1 CF 1\nX1 RD1.5 X1\nX1 RD1.5\r\nX1 RD1.5\r X\nN0001:0001 X1 CF1\n"
        "X1 CF1(x)\nX1 CFX\nX1 RD_1\nX1 CF0.8\t\nCF2\nN0003 RD3\nX1 CF1.2.3\nX1 CF1 -2\n"
        "X1 RD1 @1\nX1 CF1 (A)\nX1 RD1\n      Y2\nX1 CFRD1\nX1 RDCF1\nX1 CF1;\nX1 RD1";
    EXPECT_EQ(differenceBetweenPaths(text), "");
    EXPECT_EQ(differenceBetweenPaths("N0001" + std::string(300, ' ') + "X1 RD2\n"), "");
    const Program program = parseWith("N0001 X1 Y2 RD1.5\n", true);
    ASSERT_EQ(program.blocks.size(), 1u);
    ASSERT_EQ(program.blocks[0].wordCount, 3u);
    const Word word = program.words[program.blocks[0].firstWord + 2];
    EXPECT_EQ(word.kind, WordKind::Command);
    EXPECT_EQ(program.text(word.text), "RD1.5");
    EXPECT_EQ(program.text(word.args), "1.5");
    EXPECT_EQ(word.column, 13);
    EXPECT_TRUE(word.flags & kWordNeedsCompiler);
}

// The enhanced numbers of a compiled program ("N0053:0001", the object
// check of the compiler) and what is no enhanced number.
TEST(ParserWholeLine, EnhancedNumbersParseAsOnTheGeneralPath) {
    const std::string text =
        "N0001:0002 X1\nN0001:0003 G1 X2 Y3\r\nN0001:00021 X1\nN0001:002 X1\n"
        "N0001: X1\nN0001:0002\nN0001:0002 ;c\n N0001:0002\nN0001:0002/X1\n"
        "N0001:0002 .L X1\nN0001:0002 :X1\nN0001:0002 / X1\nN0001:0002\tX1 RD1\n"
        "N9999:9999 X1\nN0001:0002 X1\n      Y2\nN0001:0002";
    EXPECT_EQ(differenceBetweenPaths(text), "");
    const Program program = parseWith("N0053:0001 G1 X2\n", true);
    ASSERT_EQ(program.blocks.size(), 1u);
    EXPECT_EQ(program.blocks[0].number, 53);
    EXPECT_EQ(program.blocks[0].subNumber, 1);
    EXPECT_EQ(program.blocks[0].wordCount, 2u);
}

TEST(ParserWholeLine, ValuesColumnsAndSpans) {
    const Program program =
        parseWith("N0001 G1 X-12.5 Y+3 F1000\r\nN0002\tX1234567890 Z0.12345678\r\nG2 I.5", true);
    ASSERT_TRUE(program.diagnostics.empty());
    ASSERT_EQ(program.blocks.size(), 3u);
    const Block first = program.blocks[0];
    EXPECT_EQ(first.number, 1);
    EXPECT_EQ(first.line, 1u);
    EXPECT_EQ(first.sourceText.offset, 0u);
    EXPECT_EQ(first.sourceText.length, 25u);  // without the "\r"
    ASSERT_EQ(first.wordCount, 4u);
    const Word x = program.words[first.firstWord + 1];
    EXPECT_EQ(x.kind, WordKind::Axis);
    EXPECT_EQ(x.letter, 'X');
    EXPECT_EQ(x.column, 10);
    EXPECT_EQ(x.number, -12.5);
    EXPECT_EQ(program.words[first.firstWord + 2].number, 3.0);
    EXPECT_EQ(program.words[first.firstWord + 3].kind, WordKind::F);
    EXPECT_EQ(program.words[first.firstWord + 3].number, 1000.0);
    const Block second = program.blocks[1];
    EXPECT_EQ(second.line, 2u);
    ASSERT_EQ(second.wordCount, 2u);
    EXPECT_EQ(program.words[second.firstWord].number, 1234567890.0);
    EXPECT_EQ(program.words[second.firstWord].column, 7);
    EXPECT_EQ(program.words[second.firstWord + 1].number, 0.12345678);
    const Block third = program.blocks[2];
    EXPECT_EQ(third.number, -1);
    EXPECT_EQ(third.line, 3u);
    EXPECT_EQ(third.sourceText.length, 6u);  // no newline at the end of the text
    ASSERT_EQ(third.wordCount, 2u);
    EXPECT_EQ(program.words[third.firstWord + 1].kind, WordKind::CircleCenter);
    EXPECT_EQ(program.words[third.firstWord + 1].number, 0.5);
}

TEST(ParserWholeLine, AFullWordListGrowsInPlace) {
    // More words than the counting pass reserves: blanks are tabs here.
    std::string text;
    for (int i = 0; i < 2000; ++i)
        text += "G1\tX1\tY2\tZ3\tF4\n";
    const Program program = parseWith(text, true);
    EXPECT_EQ(program.words.size(), 10000u);
    EXPECT_EQ(differenceBetweenPaths(text), "");
}

TEST(ParserWholeLine, LargeProgramsKeepEveryValue) {
    // 20,000 lines of numbers of every size (narrow and wide words), with
    // now and then a comment, a label, a blank line or a long line: every
    // value, column, block field and group of 64 blocks read back.
    std::uint32_t seed = 12345;
    const auto next = [&seed] {
        seed = seed * 1103515245u + 12345u;
        return seed >> 8;
    };
    std::string text;
    std::vector<std::string> numbers;
    std::vector<std::uint16_t> columns;
    for (int line = 0; line < 20000; ++line) {
        if (line % 97 == 5) text += "\n";  // a line without a block
        std::string block = "N" + std::to_string(1000 + line % 9000);
        if (line % 211 == 7) block += " .L" + std::to_string(line);
        const int count = 1 + static_cast<int>(next() % 6);
        for (int w = 0; w < count; ++w) {
            const std::uint32_t digits = 1 + next() % 9, decimals = next() % (digits + 1);
            std::string number;
            for (std::uint32_t d = 0; d < digits; ++d) {
                if (d == digits - decimals) number += '.';
                number += static_cast<char>('0' + next() % 10);
            }
            if (next() % 3 == 0) number = "-" + number;
            block += " ";
            columns.push_back(static_cast<std::uint16_t>(block.size() + 1));
            block += "XYZUVW"[w];
            block += number;
            numbers.push_back(number);
        }
        if (line % 389 == 11) block += std::string(300, ' ') + ";";
        text += block + "\n";
    }
    const Program program = parseWith(text, true);
    ASSERT_TRUE(program.diagnostics.empty());
    ASSERT_EQ(program.words.size(), numbers.size());
    for (std::size_t i = 0; i < numbers.size(); ++i) {
        const Word word = program.words[i];
        ASSERT_EQ(word.number, std::strtod(numbers[i].c_str(), nullptr)) << i << " " << numbers[i];
        ASSERT_EQ(word.column, columns[i]) << i;
    }
    ASSERT_EQ(program.blocks.size(), 20000u);
    std::uint32_t firstWord = 0;
    for (std::size_t i = 0; i < program.blocks.size(); ++i) {
        const Block block = program.blocks[i];
        ASSERT_EQ(block.firstWord, firstWord) << i;
        ASSERT_EQ(block.number, static_cast<std::int32_t>(1000 + i % 9000)) << i;
        ASSERT_EQ(text.compare(block.sourceText.offset, 1, "N"), 0) << i;
        firstWord += block.wordCount;
    }
    EXPECT_EQ(differenceBetweenPaths(text), "");
}

}  // namespace
