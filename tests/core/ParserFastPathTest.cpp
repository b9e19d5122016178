// The parser's fast path for plain blocks (BlockParserPlain.cpp) must give
// exactly the program the general path gives: the same blocks, words (every
// field, the value bit for bit), expressions, labels and diagnostics. Every
// input here is parsed both ways and compared field by field.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "cnc_core/language/Parser.h"
#include "tests/support/ProgramDifference.h"

using namespace mtc::core;
using mtc::core::testing::differenceBetweenPaths;
using mtc::core::testing::parseWith;
namespace fs = std::filesystem;

namespace {

// Blocks at the edge of what the fast path takes: indexes, signs, points,
// long and inexact numbers, whole-number words, prefixes it leaves to the
// general path, missing blanks, tabs, comments and bad characters.
const std::vector<std::string> kEdgeBlocks = {
    "N0001 G1 X10 Y0 F1000",
    "N0001 G01 X-12.5 Y+3 Z.5 F.25",
    "N0002 X1 Y2 Z3",
    "N0003 X1 25 Y1-3 Z2=4 S1 3000 S2=800 S2800",
    "N0004 X1.5 Y1 .5 Z1 @1",
    "N0005 G1.0 G1.5 M3. T-1",
    "N0006 X1.2.3",
    "N0007 X 5 Y- 2 Z+-1",
    "N0008 X12345678901234567890 Y0.00000001 Z0.123456789 F99999999999",
    "N0009 X2147483648 Y-2147483647 Z2147483647.0 A0.10000000",
    "N0010 G1X10Y20F300",
    "N0011\tG1\tX1 ;comment after words",
    "N0012 ;only a comment",
    "N0013 G1 X1 (text) Y2 [more]",
    "N0014 /G1 X1",
    "N0015 :G1 X1",
    "N0016 .LABEL G1 X1",
    "N0017:0001 G1 X1",
    "N001 G1 X1",
    "N00001 G1 X1",
    "N0018.5 G1",
    "N0019",
    "N0020 N0021 G1",
    "N0022 H5 R3 L2",
    "N0023 GAX X1 MTD(1,,,2)=3",
    "N0024 X-0 Y-0.0 Z0",
    "N0025 G1 X1 Y",
    "N0026 X=5 Y=-2 F=@3",
    "N0027 x1 G1",
    "N0028 G1 X1 \x01",
    "G1 X1 Y2",
    "   N0029 G1 X1",
    "N0030 E5 D2 Q7 I-3.25 J0 K1.5 U1 V2 W3 A1 B2 C3",
    "N0031 X1\r",
    "N0032 G1 X1\n      Y2 Z3",
    "N0033 G1 X1 Y2 PROGRAMMENDE",
    // enhanced numbers of compiled programs and blocks without a number
    "N0034:0000 G1 X1",
    "N0034:0001",
    "N0034:00012 X1",
    "N0034:001 X1",
    "N0034:0001/X1",
    "N0034:0001 /X1",
    "N0034:0001 :X1",
    "N0034:0001 .L1 X1",
    "N0034:0001:0002 X1",
    "N0034:0001.5 X1",
    "N0034::0001 X1",
    "/N0034:0001 X1",
    "X1 Y2 RD1.5",
    "x1 y2",
    "/X1",
    ":X1",
    ".L2 X1",
    "\tX1",
    "(text) X1",
    ";comment",
    "@1=5",
    // numbers around the 17 digits of the fast path's own number scan
    "N0035 X99999999999999999 Y999999999999999999 Z9999999999999999999",
    "N0036 X1234567890.1234567 Y1234567890.12345678 Z.12345678901234567 A.123456789012345678",
    "N0037 X00000000000000000000001 Y0.00000000000000000000 Z1.",
    "N0038 X. Y.. Z1..2 A-. B+.5",
    // the block number and numbers at the block's very end, a word past column 255
    "N0039",
    "N004",
    "N00400",
    "N0041 X12.5",
    "N0042:0001",
    "N0043:000",
    "N0044" + std::string(260, ' ') + "X1 Y2",
    // words that turn the flow (WordList::flowTurningWords), also on a
    // line the fast path gives back (a continuation follows)
    "N0045 M02 M30 M2.0 M-2 M+30 M030 M3 M20 M300",
    "N0046 .L3 M30",
    "N0047 BSR .L3 M2",
    "N0048 M2\n      X1",
    "N0049 M30 ;end",
    "N0050 X1 M2 Y2 M30",
};

TEST(ParserFastPath, EdgeBlocksParseAsOnTheGeneralPath) {
    for (const std::string& block : kEdgeBlocks)
        EXPECT_EQ(differenceBetweenPaths(block + "\n"), "") << block;
    std::string all;
    for (const std::string& block : kEdgeBlocks)
        all += block + "\n";
    EXPECT_EQ(differenceBetweenPaths(all), "");
}

TEST(ParserFastPath, ProjectProgramsParseAsOnTheGeneralPath) {
    const fs::path root = MTC_SOURCE_DIR;
    int files = 0;
    for (const char* folder : {"resources/programs", "tests/golden/interp", "tests/golden/compiler",
                               "tests/golden/restart", "tests/golden/cli"}) {
        if (!fs::is_directory(root / folder)) continue;
        for (const auto& entry : fs::directory_iterator(root / folder)) {
            if (!entry.is_regular_file()) continue;
            std::ifstream in(entry.path(), std::ios::binary);
            std::stringstream text;
            text << in.rdbuf();
            EXPECT_EQ(differenceBetweenPaths(text.str()), "") << entry.path();
            ++files;
        }
    }
    EXPECT_GT(files, 50);
}

TEST(ParserFastPath, RandomPlainLikeBlocksParseAsOnTheGeneralPath) {
    // Mostly the characters of plain blocks, so that most blocks reach deep
    // into the fast path before something unusual sends them to the general one.
    const char alphabet[] = "NGXYZFSIJKMTEDQAUH0123456789012345678901234567890.-+ \t=@;(:/.x";
    std::mt19937 rng(20261126u);
    std::uniform_int_distribution<int> pick(0, static_cast<int>(sizeof alphabet) - 2);
    for (int program = 0; program < 400; ++program) {
        std::string text;
        for (int block = 0; block < 25; ++block) {
            char number[8];
            std::snprintf(number, sizeof number, "N%04d", static_cast<int>(rng() % 10000));
            if (rng() % 8 != 0) text += number;
            if (rng() % 4 == 0) text += rng() % 2 ? ":0001" : ":12";  // enhanced numbers
            for (int c = static_cast<int>(rng() % 30); c > 0; --c)
                text += alphabet[pick(rng)];
            text += '\n';
        }
        const std::string difference = differenceBetweenPaths(text);
        ASSERT_EQ(difference, "") << text;
    }
}

}  // namespace
