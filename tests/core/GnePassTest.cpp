// The GNE as a pass of the NC compiler: cycles become intermediate blocks
// with enhanced numbers, geometry blocks become comments, errors name the
// block, and RD/CF inside a contour are the contour's (not the CF/RD pass's).

#include <gtest/gtest.h>

#include <random>

#include "CompilerTestSupport.h"
#include "cnc_core/contour/ToolCheck.h"

namespace mtc::core::gne {
namespace {

using mtc::test::codes;
using mtc::test::compileText;
using mtc::test::objectBlocks;

const char* kProgram =
    "N0001 G0 G18 G90 G95 X50 Z10\n"
    "N0002 WINDOW_01 (-30, 1, 20)\n"
    "N0003 CONT (1)\n"
    "N0004 START Z0 X0\n"
    "N0005 LINE Z0 X10\n"
    "N0006 RD 1\n"
    "N0007 LINE Z-20 X10\n"
    "N0008 CF 0.5\n"
    "N0009 LINE Z-20 X18\n"
    "N0010 LINE A180 L5\n"
    "N0011 END_CONT\n"
    "N0012 CYCLE_10 (1, 4, 0.1)\n"
    "N0013 G0 X50 Z10\n"
    "N0014 M30\n";

TEST(GnePass, CyclesBecomeIntermediateBlocks) {
    const CompileResult r = compileText(kProgram);
    ASSERT_TRUE(r.errors.empty()) << r.errors[0].code << " " << r.errors[0].message;
    const std::vector<std::string> blocks = objectBlocks(r);
    ASSERT_GT(blocks.size(), 20u);
    EXPECT_EQ(blocks[2], "N0003:0000 ;CONT (1)");
    EXPECT_EQ(blocks[5], "N0006:0000 ;RD 1");
    EXPECT_EQ(blocks[11], "N0012:0000 ;CYCLE_10 (1, 4, 0.1)");
    EXPECT_EQ(blocks[12], "N0012:0001 G90 G18 G40 G15");
    EXPECT_EQ(blocks[13], "N0012:0002 T4 ;GNE TOOL EDGE 3 TR 0 CA 80 SA 95");
    // The rounding of N0006 as a G2/G3 block with its absolute centre.
    bool rounding = false;
    for (const std::string& b : blocks)
        rounding = rounding || b.find(" X10 Z-1 I9 K-1") != std::string::npos;
    EXPECT_TRUE(rounding);
    EXPECT_EQ(blocks.back().substr(0, 10), "N0014:0000");
}

TEST(GnePass, ErrorsNameTheBlockAndStopTheCascade) {
    std::string text = kProgram;
    text.replace(text.find("N0010 LINE A180 L5"), 18, "N0010 LINE A180 L5 Q4");
    CompileResult r = compileText(text);
    EXPECT_EQ(codes(r), std::vector<std::string>{"GNE_BAD_WORD"});
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].block, "N0010");
    EXPECT_EQ(r.errors[0].sourceLine, 10);

    text = kProgram;
    text.replace(text.find("N0011 END_CONT"), 14, "N0011");
    r = compileText(text);
    EXPECT_EQ(codes(r), std::vector<std::string>{"GNE_CONT_NOT_CLOSED"});
}

/// Random edits of the GNE program through the whole compiler: never a
/// crash or hang; a clean compile gives an object program whose inserted
/// blocks carry enhanced numbers.
TEST(GnePass, FuzzedProgramsCompileOrReport) {
    std::mt19937 random(71);
    const std::string alphabet = "0123456789.-, ()ZXAKILRT\n";
    int clean = 0;
    for (int round = 0; round < 400; ++round) {
        std::string text = kProgram;
        for (int e = 0; e < 1 + static_cast<int>(random() % 4); ++e) {
            const std::size_t at = random() % text.size();
            if (random() % 2)
                text[at] = alphabet[random() % alphabet.size()];
            else
                text.erase(at, 1 + random() % 4);
        }
        const CompileResult r = compileText(text);
        for (const CompilerError& e : r.errors)
            EXPECT_FALSE(e.message.empty());
        if (!r.errors.empty()) continue;
        ++clean;
        EXPECT_FALSE(r.objectText.empty());
    }
    EXPECT_GT(clean, 20);
}

TEST(GnePass, ProgramsWithoutGneAreUntouched) {
    const CompileResult r = compileText(
        "N0001 G0 G17 G90 X0 Y0\nN0002 G1 X20 Y0 F100 RD 2\nN0003 X20 Y20\nN0004 M30\n");
    EXPECT_TRUE(r.errors.empty()) << r.errors[0].code;
    EXPECT_EQ(objectBlocks(r)[2].substr(0, 10), "N0002:0001");  // the CF/RD pass's rounding
}

}  // namespace
}  // namespace mtc::core::gne

namespace mtc::core::gne {
namespace {

TEST(GneToolCheck, AssumptionAgainstTheToolList) {
    ToolConfig turn{1, 0.4, 61.5, 3, "turn1"};
    ToolAssumption assumed{1, true, 0.4, 3, 80, 95, 0};
    EXPECT_TRUE(checkToolAssumption(assumed, &turn).empty());
    assumed.radius = 0.8;
    assumed.edge = 2;
    const auto problems = checkToolAssumption(assumed, &turn);
    ASSERT_EQ(problems.size(), 2u);
    EXPECT_NE(problems[0].find("radius 0.4"), std::string::npos);
    EXPECT_NE(problems[1].find("orientation 3"), std::string::npos);
    EXPECT_EQ(checkToolAssumption(assumed, nullptr),
              std::vector<std::string>{"T1 is not in the tool list"});
    ToolAssumption mill{7, false, 3.5, 0, 0, 0, 0};
    ToolConfig cutter{7, 3.5, 97.5, 0, "mill7"};
    EXPECT_TRUE(checkToolAssumption(mill, &cutter).empty());  // no edge for milling tools
}

}  // namespace
}  // namespace mtc::core::gne
