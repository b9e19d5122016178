// Block structure: numbers, skip, primary blocks, labels, comments, texts,
// continuation lines, PROGRAMMENDE.
#include <gtest/gtest.h>

#include "ParserTestSupport.h"

using namespace mtc::core;
using namespace mtc::core::testing;

namespace {

TEST(ParserStructure, BlockNumbersAndIds) {
    Program p = parse("N0000 G0\nN9999 G1\nG2\n");
    ASSERT_EQ(p.blocks.size(), 3u);
    EXPECT_EQ(p.blockId(0), "N0000");
    EXPECT_EQ(p.blockId(1), "N9999");
    EXPECT_EQ(p.blockId(2), "");
    EXPECT_EQ(p.blocks[2].number, -1);
    EXPECT_EQ(p.blocks[2].line, 3u);
}

TEST(ParserStructure, CompiledBlockNumbers) {
    Program p = parse("N0053:0000 G1 X5\nN0053:0001 G1 X6\n");
    ASSERT_TRUE(p.diagnostics.empty());
    EXPECT_EQ(p.blockId(1), "N0053:0001");
    EXPECT_EQ(p.blocks[1].subNumber, 1);
    EXPECT_EQ(describeBlock(p, 1), "G1 X6");
}

TEST(ParserStructure, ShortBlockNumberIsAWarning) {
    Program p = parse("N12 G1");
    ASSERT_EQ(codes(p), std::vector<std::string>{"PARSE_SHORT_BLOCK_NUMBER"});
    EXPECT_FALSE(p.diagnostics.hasErrors());
    EXPECT_EQ(p.blocks[0].number, 12);
}

TEST(ParserStructure, SkipAndPrimaryBlocks) {
    Program p = parse(
        "/N0001 G1\n"
        "N0002 : T12 M6\n"
        ": N0003 G0\n"
        "/:N0004 G0\n"
        "/ : N0005 X1\n"
        ":\n"
        "N0006 G1\n");
    ASSERT_TRUE(p.diagnostics.empty()) << formatDiagnostic(p.diagnostics.items()[0]);
    EXPECT_EQ(p.blocks[0].flags, kBlockSkip);
    EXPECT_EQ(p.blocks[1].flags, kBlockPrimary);
    EXPECT_EQ(describeBlock(p, 1), "T12 M6");
    EXPECT_EQ(p.blocks[2].flags, kBlockPrimary);
    EXPECT_EQ(p.blocks[3].flags, kBlockSkip | kBlockPrimary);
    EXPECT_EQ(p.blocks[4].flags, kBlockSkip | kBlockPrimary);
    EXPECT_EQ(p.blocks[4].number, 5);
    EXPECT_EQ(p.blocks[5].flags, kBlockPrimary);  // a ':' alone is an empty primary block
    EXPECT_EQ(p.blocks[5].wordCount, 0);
    EXPECT_EQ(p.blocks[6].flags, 0);
}

TEST(ParserStructure, LabelsAreIndexed) {
    Program p = parse(
        "N0000 .ADJUST\n"
        ".INI_G5 M109 ;coolant\n"
        "N0013 .*WSTCH G4 F1\n"
        ".REPOS : @100=1\n"
        ".ADJG15 @100=M(15)-1 BMI .INIG15\n");
    ASSERT_TRUE(p.diagnostics.empty()) << formatDiagnostic(p.diagnostics.items()[0]);
    EXPECT_EQ(p.findLabel("ADJUST"), 0);
    EXPECT_EQ(p.findLabel("INI_G5"), 1);
    EXPECT_EQ(p.findLabel("*WSTCH"), 2);
    EXPECT_EQ(p.findLabel("REPOS"), 3);
    EXPECT_EQ(p.findLabel("ADJG15"), 4);
    EXPECT_EQ(p.findLabel("NONE"), -1);
    EXPECT_EQ(p.text(p.blocks[2].label), "*WSTCH");
    EXPECT_EQ(describeBlock(p, 2), "G4 F1");
    EXPECT_EQ(p.blocks[3].flags, kBlockPrimary);
    EXPECT_EQ(describeBlock(p, 4), "@100=M(15)-1 BMI .INIG15");
}

TEST(ParserStructure, DuplicateLabel) {
    Program p = parse(".LOOP G1\nG2\n.LOOP G3\n");
    const Diagnostic* d = find(p, "PARSE_DUPLICATE_LABEL");
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->where.line, 3);
    EXPECT_EQ(d->where.column, 1);
    EXPECT_EQ(p.findLabel("LOOP"), 0);  // the first one counts
    EXPECT_TRUE(p.blocks[2].flags & kBlockHasError);
}

TEST(ParserStructure, LabelErrors) {
    EXPECT_NE(find(parse(". G1"), "PARSE_MISSING_LABEL_NAME"), nullptr);
    EXPECT_NE(find(parse(".AB-C G1"), "PARSE_BAD_LABEL"), nullptr);
    EXPECT_NE(find(parse("G1 .LATE"), "PARSE_MISPLACED_LABEL"), nullptr);
}

TEST(ParserStructure, CommentsAndTexts) {
    Program p = parse(
        "N0001 G1 X5 ;move in X\n"
        "N0002 (parts name : stairs)\n"
        "N0003 T3 BSR .M6 (ROUGHING TOOL)\n"
        "N0004 [TOOL: angle head D9.7]\n"
        "N0005 M30 []\n"
        "N0006 G0 (first) ;second\n");
    ASSERT_TRUE(p.diagnostics.empty()) << formatDiagnostic(p.diagnostics.items()[0]);
    EXPECT_EQ(p.text(p.blocks[0].comment), "move in X");
    EXPECT_EQ(p.text(p.blocks[1].comment), "parts name : stairs");
    EXPECT_EQ(p.blocks[1].wordCount, 0);
    EXPECT_EQ(describeBlock(p, 2), "T3 BSR .M6");
    EXPECT_EQ(p.text(p.blocks[2].text), "ROUGHING TOOL");
    EXPECT_EQ(p.text(p.blocks[3].text), "TOOL: angle head D9.7");
    EXPECT_EQ(describeBlock(p, 4), "M30");
    EXPECT_EQ(p.text(p.blocks[5].comment), "second");
    EXPECT_EQ(p.text(p.blocks[5].text), "first");
}

TEST(ParserStructure, CommentAndBlankLinesMakeNoBlocks) {
    Program p = parse("; header comment\n\nN0001 G1\n   \n;---\nN0002 G2\n");
    ASSERT_EQ(p.blocks.size(), 2u);
    EXPECT_EQ(p.blocks[0].line, 3u);
    EXPECT_EQ(p.blocks[1].line, 6u);
}

TEST(ParserStructure, ContinuationLines) {
    Program p = parse(
        "N0003 G0 G17 X-0.19306\n"
        "      Y3.49431 S1 3000 M3 ;initial state\n"
        "N0004 G1 X1\n");
    ASSERT_TRUE(p.diagnostics.empty());
    ASSERT_EQ(p.blocks.size(), 2u);
    EXPECT_EQ(describeBlock(p, 0), "G0 G17 X-0.19306 Y3.49431 S1=3000 M3");
    EXPECT_EQ(p.blocks[0].lineCount, 2);
    EXPECT_EQ(p.blocks[1].line, 3u);
    EXPECT_EQ(p.text(p.blocks[0].comment), "initial state");
    EXPECT_EQ(p.text(p.blocks[0].sourceText),
              "N0003 G0 G17 X-0.19306\n      Y3.49431 S1 3000 M3 ;initial state");
}

TEST(ParserStructure, CommentRunsOnOverContinuationLines) {
    Program p = parse(
        "N0004 @101=200 ;loop counter for the\n"
        "                number of strokes\n"
        "N0005 G1\n");
    ASSERT_TRUE(p.diagnostics.empty());
    EXPECT_EQ(describeBlock(p, 0), "@101=200");
    EXPECT_EQ(p.text(p.blocks[0].comment),
              "loop counter for the\n                number of strokes");
}

TEST(ParserStructure, FiveBlanksStartANewBlock) {
    Program p = parse("N0001 G1\n     X5\n");
    ASSERT_EQ(p.blocks.size(), 2u);
    EXPECT_EQ(describeBlock(p, 1), "X5");
}

TEST(ParserStructure, ContinuationAfterABlankLineStartsABlock) {
    Program p = parse("N0001 G1\n\n      X5\n");
    ASSERT_EQ(p.blocks.size(), 2u);
    EXPECT_EQ(p.blocks[1].line, 3u);
}

TEST(ParserStructure, ErrorOnAContinuationLineReportsThatLine) {
    Program p = parse("N0007 G1 X1\n      Y2 H5\n");
    const Diagnostic* d = find(p, "PARSE_UNKNOWN_WORD");
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->where.line, 2);
    EXPECT_EQ(d->where.column, 10);
    EXPECT_EQ(d->where.block, "N0007");
}

TEST(ParserStructure, WindowsLineEndings) {
    Program p = parse("N0001 G1 X5 ;a\r\nN0002 G2\r\n      Y3\r\n");
    ASSERT_TRUE(p.diagnostics.empty());
    EXPECT_EQ(p.text(p.blocks[0].comment), "a");
    EXPECT_EQ(describeBlock(p, 1), "G2 Y3");
}

TEST(ParserStructure, ProgramEnd) {
    Program p = parse("N0001 G1\nN0002 M30\nN0003 PROGRAMMENDE\n");
    ASSERT_TRUE(p.diagnostics.empty());
    ASSERT_EQ(p.blocks.size(), 3u);
    EXPECT_EQ(p.blocks[2].flags, kBlockProgramEnd);
    EXPECT_EQ(p.blocks[2].wordCount, 0);
}

TEST(ParserStructure, TextAfterProgramEndIsIgnoredWithAWarning) {
    Program p = parse("N0001 G1\nN0002 PROGRAMMENDE\n\nN0003 G1\nN0004 G2\n");
    EXPECT_EQ(p.blocks.size(), 2u);
    ASSERT_EQ(codes(p), std::vector<std::string>{"PARSE_TEXT_AFTER_PROGRAMMENDE"});
    EXPECT_EQ(p.diagnostics.items()[0].where.line, 4);
}

TEST(ParserStructure, ProgramEndMustStandAlone) {
    EXPECT_NE(find(parse("G1 PROGRAMMENDE"), "PARSE_MISPLACED_PROGRAMMENDE"), nullptr);
    EXPECT_NE(find(parse("PROGRAMMENDE G1"), "PARSE_MISPLACED_PROGRAMMENDE"), nullptr);
}

TEST(ParserStructure, DiagnosticsCarryProgramBlockLineColumn) {
    Program p = parse("N0001 G1\nN0012 G1 X5 H7\n", 42);
    ASSERT_EQ(p.diagnostics.size(), 1u);
    const Diagnostic& d = p.diagnostics.items()[0];
    EXPECT_EQ(d.code, "PARSE_UNKNOWN_WORD");
    EXPECT_EQ(d.where.program, 42);
    EXPECT_EQ(d.where.block, "N0012");
    EXPECT_EQ(d.where.line, 2);
    EXPECT_EQ(d.where.column, 13);
    EXPECT_EQ(p.number, 42);
}

}  // namespace
