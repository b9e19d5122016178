// Macros DEFINE ... AS ... (seed 001 ch. 4) and the modal function
// MODF_ON/MODF_OFF (ch. 5).
#include <gtest/gtest.h>

#include "CompilerTestSupport.h"

using namespace mtc::core;
using namespace mtc::test;

namespace {

TEST(CompilerMacros, LocalMacroIsReplacedInTheFollowingBlocks) {
    const CompileResult r = compileText(
        "N0001 DEFINE RAPIDZ AS G0 Z100 ;retract\n"
        "N0002 G1 X5 F300\n"
        "N0003 RAPIDZ M5\n"
        "N0004 RAPIDZ\n");
    ASSERT_EQ(r.status, CompileStatus::Compiled) << codes(r).size();
    EXPECT_EQ(objectBlocks(r),
              (std::vector<std::string>{"N0001:0000 ;retract", "N0002:0000 G1 X5 F300",
                                        "N0003:0000 G0 Z100 M5", "N0004:0000 G0 Z100"}));
}

// A label of 16 or more characters is a heap string of its own: the block
// text it was cut from must stay alive while the comment is read (a
// use-after-free before; caught by the asan preset and valgrind).
TEST(CompilerMacros, LongLabelAndCommentOfADefineBlockStay) {
    const std::string label = ".LABELNUMBER12345678901234567890";
    const std::string comment = ";comment on the heap 123";
    const CompileResult r = compileText("N0001 " + label + " DEFINE MAC AS G1 X1 " + comment +
                                        "\nN0002 BRA " + label + "\nN0003 MAC\n");
    ASSERT_EQ(r.status, CompileStatus::Compiled) << codes(r).size();
    EXPECT_EQ(objectBlocks(r),
              (std::vector<std::string>{"N0001:0000 " + label + " " + comment,
                                        "N0002:0000 BRA " + label, "N0003:0000 G1 X1"}));
}

// More uses in one block than expandMacros keeps aside (16): the rest is
// appended use by use.
TEST(CompilerMacros, ManyUsesInOneBlock) {
    std::string uses, expanded;
    for (int i = 0; i < 18; ++i) {
        uses += "ZZ ";
        expanded += "M8 ";
    }
    const CompileResult r = compileText("N0001 DEFINE ZZ AS M8\nN0002 " + uses + "X1\n");
    ASSERT_EQ(r.status, CompileStatus::Compiled) << codes(r).size();
    EXPECT_EQ(objectBlocks(r)[1], "N0002:0000 " + expanded + "X1");
}

TEST(CompilerMacros, MacroNamesOnlyAsWholeWordsOutsideCommentsAndTexts) {
    const CompileResult r = compileText(
        "N0001 DEFINE M860 AS M86 M3 S10\n"
        "N0002 M860 (M860 stays in the text) ;M860 in the comment\n"
        "N0003 M86\n"
        "N0004 .M860 M8\n");
    ASSERT_EQ(r.status, CompileStatus::Compiled);
    EXPECT_EQ(objectBlocks(r)[1],
              "N0002:0000 M86 M3 S10 (M860 stays in the text) ;M860 in the comment");
    EXPECT_EQ(objectBlocks(r)[2], "N0003:0000 M86");
    EXPECT_EQ(objectBlocks(r)[3], "N0004:0000 .M860 M8");
}

TEST(CompilerMacros, GlobalMacrosApplyInEveryProgram) {
    const CompileResult r =
        compileText("N0001 QUICK X=ANPOS\n", {{"QUICK", "G1 F15000"}, {"ANPOS", "MTD(112,1,8,1)"}});
    ASSERT_EQ(r.status, CompileStatus::Compiled);
    EXPECT_EQ(objectBlocks(r)[0], "N0001:0000 G1 F15000 X=MTD(112,1,8,1)");
}

TEST(CompilerMacros, BadDefinitionsAreErrors) {
    const std::string longName(21, 'A');
    const CompileResult r = compileText("N0001 DEFINE " + longName +
                                        " AS M3\n"
                                        "N0002 DEFINE BSR AS M3\n"
                                        "N0003 DEFINE ONE AS M3\n"
                                        "N0004 DEFINE TWO AS ONE M4\n"
                                        "N0005 DEFINE SELF AS SELF M4\n"
                                        "N0006 DEFINE NOBODY AS\n"
                                        "N0007 M8 DEFINE LATE AS M9\n");
    EXPECT_EQ(codes(r), std::vector<std::string>(6, "COMPILER_BAD_MACRO"));
    EXPECT_EQ(r.errors[0].block, "N0001");
    EXPECT_NE(r.errors[0].details[0].find("20 characters"), std::string::npos);
    EXPECT_NE(r.errors[1].details[0].find("keyword BSR"), std::string::npos);
    EXPECT_NE(r.errors[2].details[0].find("nested (ONE)"), std::string::npos);
    EXPECT_NE(r.errors[3].details[0].find("nested (SELF)"), std::string::npos);
    EXPECT_EQ(r.errors[5].block, "N0007");
}

TEST(CompilerMacros, GlobalMacroLimits) {
    const CompileResult r = compileText("N0001 M8\n", {{"LONGBODY", std::string(157, 'M')},
                                                       {"OK", "M3" + std::string(150, ' ') + "M4"},
                                                       {"G1X", "OK"}});
    ASSERT_EQ(codes(r), std::vector<std::string>(2, "COMPILER_BAD_GLOBAL_MACRO"));
    EXPECT_EQ(r.errors[0].generalNumber, 1);
    EXPECT_NE(r.errors[0].details[0].find("156"), std::string::npos);
    EXPECT_NE(r.errors[1].details[0].find("nested"), std::string::npos);
}

TEST(CompilerMacros, RedefinitionWarnsAndTakesTheNewBody) {
    const CompileResult r = compileText("N0001 DEFINE A1 AS M3\nN0002 DEFINE A1 AS M4\nN0003 A1\n");
    EXPECT_EQ(codes(r), std::vector<std::string>{"COMPILER_MACRO_REDEFINED"});
    EXPECT_EQ(r.status, CompileStatus::Compiled);
    EXPECT_EQ(objectBlocks(r)[2], "N0003:0000 M4");
}

TEST(CompilerModalFunction, InsertedIntoBlocksWithAxisMotionOnly) {
    const CompileResult r = compileText(
        "N0001 G0 X10 Y10 Z5 MODF_ON (BSR .*DRILL)\n"
        "N0002 X20\n"
        "N0003 M8\n"
        "N0004 Y20\n"
        "N0005 MODF_OFF\n"
        "N0006 X0\n");
    ASSERT_EQ(r.status, CompileStatus::Compiled);
    EXPECT_EQ(objectBlocks(r),
              (std::vector<std::string>{
                  "N0001:0000 G0 X10 Y10 Z5 BSR .*DRILL", "N0002:0000 X20 BSR .*DRILL",
                  "N0003:0000 M8", "N0004:0000 Y20 BSR .*DRILL", "N0005:0000", "N0006:0000 X0"}));
}

TEST(CompilerModalFunction, OffInAMotionBlockEndsItThere) {
    const CompileResult r = compileText(
        "N0001 G1 X0 Y0 F100\nN0002 X10 MODF_ON(M8)\nN0003 Y10 ;keep\nN0004 X0 MODF_OFF\n");
    EXPECT_EQ(objectBlocks(r)[1], "N0002:0000 X10 M8");
    EXPECT_EQ(objectBlocks(r)[2], "N0003:0000 Y10 M8 ;keep");
    EXPECT_EQ(objectBlocks(r)[3], "N0004:0000 X0");
}

TEST(CompilerModalFunction, ModalRoundingFeedsTheChamferPass) {
    const CompileResult r =
        compileText("N0001 G1 X0 Y0 F100\nN0002 X10 MODF_ON(RD1)\nN0003 Y10\nN0004 X0 MODF_OFF\n");
    ASSERT_EQ(r.status, CompileStatus::Compiled);
    EXPECT_EQ(objectBlocks(r),
              (std::vector<std::string>{"N0001:0000 G1 X0 Y0 F100", "N0002:0000 X9 Y0",
                                        "N0002:0001 G3 X10 Y1 I9 J1", "N0003:0000 G1 X10 Y9",
                                        "N0003:0001 G3 X9 Y10 I9 J9", "N0004:0000 G1 X0"}));
}

TEST(CompilerModalFunction, ErrorsForLongEmptyOrNestedTexts) {
    const CompileResult r = compileText("N0001 MODF_ON(" + std::string(81, 'M') +
                                        ")\nN0002 MODF_ON()\nN0003 MODF_ON M8\n"
                                        "N0004 MODF_ON(MODF_OFF)\n");
    EXPECT_EQ(codes(r), std::vector<std::string>(4, "COMPILER_BAD_MODAL_FUNCTION"));
    EXPECT_NE(r.errors[0].details[0].find("81"), std::string::npos);
}

}  // namespace
