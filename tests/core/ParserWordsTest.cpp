// Word-level tokenization of the MTC200 dialect: every case of
// docs/SEEDS.md "NC language facts", written as our own programs.
#include <gtest/gtest.h>

#include "ParserTestSupport.h"

using namespace mtc::core;
using namespace mtc::core::testing;

namespace {

/// Parses one line and returns its words; fails the test on diagnostics.
std::string words(const std::string& line) {
    Program p = parse(line);
    EXPECT_TRUE(p.diagnostics.empty())
        << line << " -> "
        << (p.diagnostics.empty() ? "" : formatDiagnostic(p.diagnostics.items()[0]));
    EXPECT_EQ(p.blocks.size(), 1u) << line;
    return p.blocks.empty() ? "" : describeBlock(p, 0);
}

TEST(ParserWords, MotionBlockWithNumberAndFeed) {
    EXPECT_EQ(words("N0123 G1 X12.345 Y-3.5 F2000"), "G1 X12.345 Y-3.5 F2000");
    Program p = parse("N0123 G1 X12.345 Y-3.5 F2000");
    EXPECT_EQ(p.blocks[0].number, 123);
    EXPECT_EQ(p.blockId(0), "N0123");
    EXPECT_EQ(p.words[1].kind, WordKind::Axis);
    EXPECT_EQ(p.words[1].letter, 'X');
    EXPECT_EQ(p.words[1].number, 12.345);  // exactly the double of "12.345"
    EXPECT_EQ(p.words[2].number, -3.5);
}

TEST(ParserWords, SwiftAuxiliaryFunctions) {
    EXPECT_EQ(words("G1 X5 MQ12 QQ340 M8 Q7 MQ=@3"), "G1 X5 MQ12 QQ340 M8 Q7 MQ=@3");
    Program p = parse("MQ12 QQ340");
    EXPECT_EQ(p.words[0].kind, WordKind::M);
    EXPECT_EQ(p.words[0].number, 12.0);
    EXPECT_TRUE(p.words[0].flags & kWordSwift);
    EXPECT_EQ(p.words[1].kind, WordKind::Q);
    EXPECT_EQ(p.words[1].number, 340.0);
    // Only MQ / QQ followed by a value; other names stay unknown words.
    for (const char* bad : {"MQX12", "QQQ5", "MQ_1"}) {
        Program wrong = parse(std::string("G1 ") + bad);
        ASSERT_FALSE(wrong.diagnostics.empty()) << bad;
        EXPECT_EQ(wrong.diagnostics.items()[0].code, "PARSE_UNKNOWN_WORD") << bad;
    }
    Program noValue = parse("MQ");
    ASSERT_FALSE(noValue.diagnostics.empty());
}

TEST(ParserWords, AxisLettersWithoutIndex) {
    EXPECT_EQ(words("X50 Z-36.15 U1.25 V+4 W0 A90 B-45 C360"),
              "X50 Z-36.15 U1.25 V4 W0 A90 B-45 C360");
}

TEST(ParserWords, IndexFollowedByBlankAndValue) {
    EXPECT_EQ(words("Y1 25 Z1 -36.5 C2 0"), "Y1=25 Z1=-36.5 C2=0");
}

TEST(ParserWords, IndexFollowedBySign) {
    EXPECT_EQ(words("Z1-42 Y2+7.5"), "Z1=-42 Y2=7.5");
}

TEST(ParserWords, IndexFollowedByEquals) {
    EXPECT_EQ(words("X2=0 Z2=@142 Y3 = 4"), "X2=0 Z2=@142 Y3=4");
}

TEST(ParserWords, DigitsWithoutSeparatorAreTheValue) {
    EXPECT_EQ(words("Y1.5 X12 Z3"), "Y1.5 X12 Z3");
    EXPECT_EQ(words("S2800"), "S2800");
    EXPECT_EQ(words("S20 M3"), "S20 M3");
}

TEST(ParserWords, SingleDigitBeforeAnotherWordIsTheValue) {
    // "X1 Y2": a blank follows the digit, but no value: X = 1, Y = 2.
    EXPECT_EQ(words("G1 X1 Y2"), "G1 X1 Y2");
    EXPECT_EQ(words("S2 M3"), "S2 M3");
}

TEST(ParserWords, SpindleIndexAgainstSpeed) {
    EXPECT_EQ(words("G92 S2 4000"), "G92 S2=4000");
    EXPECT_EQ(words("S2 3000 M203"), "S2=3000 M203");
    EXPECT_EQ(words("G92 S2800"), "G92 S2800");
    EXPECT_EQ(words("G77 S0 S2 0 M70"), "G77 S0 S2=0 M70");
    EXPECT_EQ(words("G77 S3 0"), "G77 S3=0");
    EXPECT_EQ(words("S1 3000"), "S1=3000");
}

TEST(ParserWords, ValueAfterBlank) {
    EXPECT_EQ(words("G1 X 2034 Z1 421"), "G1 X2034 Z1=421");
}

TEST(ParserWords, FeedWithoutLeadingZero) {
    EXPECT_EQ(words("G4 F.2"), "G4 F0.2");
    EXPECT_EQ(words("G4 F.5"), "G4 F0.5");
    EXPECT_EQ(words("F12."), "F12");
}

TEST(ParserWords, EffectiveRadius) {
    EXPECT_EQ(words("G32 RI 36.5"), "G32 RI=36.5");
    EXPECT_EQ(words("G32 RI=80"), "G32 RI=80");
    EXPECT_EQ(words("G32 RI=@120"), "G32 RI=@120");
    Program p = parse("G32 RI 36.5");
    EXPECT_EQ(p.words[1].kind, WordKind::EffectiveRadius);
}

TEST(ParserWords, CircleCentres) {
    EXPECT_EQ(words("G2 Y1 54.2426 Z1-30.7574 I-35 J50"), "G2 Y1=54.2426 Z1=-30.7574 I-35 J50");
    EXPECT_EQ(words("G3 X200 Z300 I200 K150"), "G3 X200 Z300 I200 K150");
}

TEST(ParserWords, FreePlaneSelectionWords) {
    EXPECT_EQ(words("G20 Z0 C0 X2=0 G32 RI=80"), "G20 Z0 C0 X2=0 G32 RI=80");
}

TEST(ParserWords, WordsWithoutBlanks) {
    EXPECT_EQ(words("G1X10Y-2F300"), "G1 X10 Y-2 F300");
}

TEST(ParserWords, LeadingZerosInCodes) {
    EXPECT_EQ(words("G00 G01 M03"), "G0 G1 M3");
}

TEST(ParserWords, OtherAddressLetters) {
    EXPECT_EQ(words("T12 E2 D3 Q9500 M6"), "T12 E2 D3 Q9500 M6");
}

TEST(ParserWords, SignedVariableAsValue) {
    EXPECT_EQ(words("X@100 Y-@101"), "X=@100 Y=-@101");
}

TEST(ParserWords, VariableAssignments) {
    EXPECT_EQ(words("@100=0 @101=@142 @1:120=5"), "@100=0 @101=@142 @1:120=5");
}

TEST(ParserWords, AddressAssignments) {
    EXPECT_EQ(words("G=@128 G=@129"), "G=@128 G=@129");
    EXPECT_EQ(words("M=@101"), "M=@101");
    EXPECT_EQ(words("M=M(5)"), "M=M(5)");
    EXPECT_EQ(words("M=69"), "M69");
    EXPECT_EQ(words("Q=@110"), "Q=@110");
    EXPECT_EQ(words("T=T"), "T=T");
    EXPECT_EQ(words("T= MTD(60,,5)"), "T=MTD(60,,,5)");
    EXPECT_EQ(words("S=@102 S2=@103"), "S=@102 S2=@103");
    EXPECT_EQ(words("G=@101+32"), "G=@101+32");
}

TEST(ParserWords, MtdAssignment) {
    EXPECT_EQ(words("MTD(180,,,1)=@141"), "MTD(180,,,1)=@141");
    EXPECT_EQ(words("MTD(180, 0, 1, 2) = 7"), "MTD(180,0,1,2)=7");
    Program p = parse("MTD(180,,,1)=@141");
    EXPECT_EQ(p.words[0].kind, WordKind::AssignMTD);
}

TEST(ParserWords, SeveralAssignmentsAndABranchInOneBlock) {
    EXPECT_EQ(words("@100=@141 @101=@142 BEQ .END"), "@100=@141 @101=@142 BEQ .END");
    EXPECT_EQ(words("T=@126 MTP"), "T=@126 CMD[MTP]");
}

TEST(ParserWords, ColumnsAreOneBased) {
    Program p = parse("N0010 G1 X5\n      Y7 ;c");
    EXPECT_EQ(p.words[0].column, 7);
    EXPECT_EQ(p.words[1].column, 10);
    EXPECT_EQ(p.words[2].column, 7);  // on the continuation line
}

TEST(ParserWords, NumbersThatDoNotPackStayExact) {
    Program p = parse("X0.123456789 Y123456789012 T9999999");
    ASSERT_TRUE(p.diagnostics.empty());
    EXPECT_EQ(p.words[0].number, 0.123456789);
    EXPECT_EQ(p.words[1].number, 123456789012.0);
    EXPECT_EQ(p.words[2].number, 9999999.0);
}

}  // namespace
