// Jumps, branches, calls, NC commands and NC compiler keywords.
#include <gtest/gtest.h>

#include "ParserTestSupport.h"

using namespace mtc::core;
using namespace mtc::core::testing;

namespace {

std::string words(const std::string& line) {
    Program p = parse(line);
    EXPECT_TRUE(p.diagnostics.empty())
        << line << " -> "
        << (p.diagnostics.empty() ? "" : formatDiagnostic(p.diagnostics.items()[0]));
    return p.blocks.empty() ? "" : describeBlock(p, 0);
}

TEST(ParserCommand, BranchesWithLabels) {
    for (const char* name : {"BRA", "BEQ", "BNE", "BPL", "BMI", "BSR", "BRF", "BSE", "BTE"}) {
        std::string line = std::string(name) + " .TARGET_1";
        EXPECT_EQ(words(line), line);
    }
    EXPECT_EQ(words("BSR .*WSTCH"), "BSR .*WSTCH");
    EXPECT_EQ(words("BSR.M6"), "BSR .M6");
    Program p = parse("BRA .ADJ_G6");
    EXPECT_EQ(p.words[0].kind, WordKind::Jump);
    EXPECT_EQ(p.words[0].jump, JumpKind::BRA);
    EXPECT_EQ(p.text(p.words[0].text), "ADJ_G6");
}

TEST(ParserCommand, EndsAndReturns) {
    EXPECT_EQ(words("BST"), "BST");
    EXPECT_EQ(words("RET"), "RET");
    EXPECT_EQ(words("G77 Z0 F2000 RTS"), "G77 Z0 F2000 RTS");
}

TEST(ParserCommand, ProgramCalls) {
    EXPECT_EQ(words("JSR 17"), "JSR 17");
    EXPECT_EQ(words("JMP 3"), "JMP 3");
    EXPECT_EQ(words("JMP @2"), "JMP @2");
    EXPECT_EQ(words("JSR @10"), "JSR @10");
    Program p = parse("JMP @2");
    EXPECT_GE(p.words[0].expr, 0);
}

TEST(ParserCommand, EventJumps) {
    EXPECT_EQ(words("BES .BP1 1:15"), "BES .BP1 1:15");
    EXPECT_EQ(words("BER .WAIT 0:3"), "BER .WAIT 0:3");
    EXPECT_EQ(words("BEV .SUB 2:40"), "BEV .SUB 2:40");
    EXPECT_EQ(words("JEV 5 1:3"), "JEV 5 1:3");
    Program p = parse("BES .BP1 1:15");
    EXPECT_EQ(p.words[0].eventProcess, 1);
    EXPECT_EQ(p.words[0].eventNumber, 15);
}

TEST(ParserCommand, JumpErrors) {
    EXPECT_NE(find(parse("BRA"), "PARSE_MISSING_LABEL"), nullptr);
    EXPECT_NE(find(parse("BRA 12"), "PARSE_MISSING_LABEL"), nullptr);
    EXPECT_NE(find(parse("BEQ ."), "PARSE_MISSING_LABEL_NAME"), nullptr);
    EXPECT_NE(find(parse("BNE .A-B"), "PARSE_BAD_LABEL"), nullptr);
    EXPECT_NE(find(parse("BES .BP1"), "PARSE_MISSING_EVENT"), nullptr);
    EXPECT_NE(find(parse("BES .BP1 15"), "PARSE_BAD_EVENT"), nullptr);
    EXPECT_NE(find(parse("BEV .X 1:99999"), "PARSE_BAD_EVENT"), nullptr);
    EXPECT_NE(find(parse("JSR"), "PARSE_MISSING_PROGRAM"), nullptr);
    EXPECT_NE(find(parse("JMP .LABEL"), "PARSE_MISSING_PROGRAM"), nullptr);
    EXPECT_NE(find(parse("JSR 1.5"), "PARSE_BAD_NUMBER"), nullptr);
    EXPECT_NE(find(parse("JEV 5"), "PARSE_MISSING_EVENT"), nullptr);
}

TEST(ParserCommand, ToolStorageAndTransferCommands) {
    for (const char* name : {"MTP", "MMP", "MFP", "MHP", "MOP", "MRF", "MRY", "MRV", "TCH", "TMS",
                             "TSM", "TSE", "TPE", "PMP", "NMP"}) {
        Program p = parse(name);
        ASSERT_TRUE(p.diagnostics.empty()) << name;
        EXPECT_EQ(p.words[0].kind, WordKind::Command) << name;
        EXPECT_EQ(p.text(p.words[0].text), name);
        EXPECT_EQ(p.words[0].flags & kWordNeedsCompiler, 0) << name;
    }
    EXPECT_EQ(words("T12 MTP(2, 1)"), "T12 CMD[MTP(2, 1)]");
    EXPECT_EQ(words("TCH(1, 2) M3"), "CMD[TCH(1, 2)] M3");
    EXPECT_EQ(words("G77 S0 MTP"), "G77 S0 CMD[MTP]");
}

TEST(ParserCommand, ProcessAxisAndDriveCommands) {
    for (const char* line : {"DP 1", "SP 2", "RP 1", "AP 3", "WP 1", "LP 2", "POK", "WES 1:5",
                             "WER 2:7", "GAX(X1)", "FAX(X1)"})
        EXPECT_EQ(words(line), std::string("CMD[") + line + "]");
    Program p = parse("AXD (X:S-0-0104)=7000 ;new gain");
    ASSERT_TRUE(p.diagnostics.empty());
    EXPECT_EQ(p.text(p.words[0].text), "AXD (X:S-0-0104)=7000");
    EXPECT_EQ(p.text(p.words[0].args), "(X:S-0-0104)=7000");
    EXPECT_EQ(p.text(p.blocks[0].comment), "new gain");
}

TEST(ParserCommand, G77IsJustGAndAxisWords) {
    EXPECT_EQ(words("G77 X0 Y2 0 F5000"), "G77 X0 Y2=0 F5000");
    EXPECT_EQ(words("G77 C1=0"), "G77 C1=0");
}

TEST(ParserCommand, CompilerKeywordsAreMarked) {
    const char* lines[] = {"CF2",
                           "CF=1.5",
                           "RD 2.5",
                           "RD=@3",
                           "LA_ON",
                           "LA_OFF",
                           "MODF_OFF",
                           "METB=10",
                           "VFBT=2",
                           "BBTRC=3",
                           "TRC=1",
                           "ADTRC=1",
                           "ACC_EFF=90",
                           "END_CONT",
                           "CYCLE_11(1,2,3)",
                           "FORM_56(10,20)",
                           "WINDOW_01(0,100,0,50)",
                           "CONT(1,2)",
                           "MODF_ON (BSR .*G83)",
                           "TL_RADIUS[1234567,1]=24.995",
                           "TL_RADIUS [ ] = ACD_COMP[@200]"};
    for (const char* line : lines) {
        Program p = parse(line);
        ASSERT_TRUE(p.diagnostics.empty()) << line;
        ASSERT_EQ(p.words.size(), 1u) << line;
        EXPECT_EQ(describeWord(p, p.words[0]), std::string("COMPILER[") + line + "]");
        EXPECT_TRUE(p.usesCompilerKeywords);
    }
}

TEST(ParserCommand, CompilerKeywordBesideMotionWords) {
    EXPECT_EQ(words("G1 X20 CF2.0"), "G1 X20 COMPILER[CF2.0]");
    EXPECT_EQ(words("X20 MODF_ON (CF2.0)"), "X20 COMPILER[MODF_ON (CF2.0)]");
    EXPECT_EQ(words("G01 X 2034 Z1 421 FZ1=4500"), "G1 X2034 Z1=421 COMPILER[FZ1=4500]");
    EXPECT_EQ(words("T2 BSR .M6 [GRINDING WHEEL]"), "T2 BSR .M6");
}

TEST(ParserCommand, ContourElementsTakeTheRestOfTheBlock) {
    EXPECT_EQ(words("LINE X10 Y20 ;edge"), "COMPILER[LINE X10 Y20]");
    EXPECT_EQ(words("CW X5 Y5 R2"), "COMPILER[CW X5 Y5 R2]");
}

TEST(ParserCommand, DefineRegistersAMacro) {
    Program p = parse(
        "N0001 DEFINE TOOLCHG AS BSR .TCHG ;macro\n"
        "N0002 DEFINE FAST AS G01 F15000\n"
        "N0003 T4 TOOLCHG\n"
        "N0004 FAST X=ANPOS Y5\n"
        "N0005 G1 X5 ;TOOLCHG in a comment is no use\n"
        "N0006 BSR .TOOLCHG\n");
    ASSERT_TRUE(p.diagnostics.empty()) << formatDiagnostic(p.diagnostics.items()[0]);
    EXPECT_EQ(describeBlock(p, 0), "COMPILER[DEFINE TOOLCHG AS BSR .TCHG]");
    EXPECT_EQ(describeBlock(p, 2), "COMPILER[T4 TOOLCHG]");
    EXPECT_EQ(describeBlock(p, 3), "COMPILER[FAST X=ANPOS Y5]");
    EXPECT_EQ(describeBlock(p, 4), "G1 X5");
    EXPECT_EQ(describeBlock(p, 5), "BSR .TOOLCHG");  // a label of that name is no macro use
    EXPECT_TRUE(p.usesCompilerKeywords);
}

TEST(ParserCommand, MacroNamedLikeAnAddressWord) {
    Program p = parse("DEFINE M6 AS BSR .WZW\nT3 M6\nM60\n");
    ASSERT_TRUE(p.diagnostics.empty());
    EXPECT_EQ(describeBlock(p, 1), "COMPILER[T3 M6]");
    EXPECT_EQ(describeBlock(p, 2), "M60");
}

TEST(ParserCommand, GlobalMacroNamesOfTheNcOptions) {
    ParseOptions options;
    options.macroNames = {"FAST", "M6"};
    const Program p = parseProgram("N0001 FAST X5\nN0002 T3 M6\nN0003 M60 X1\n", options);
    ASSERT_TRUE(p.diagnostics.empty()) << formatDiagnostic(p.diagnostics.items()[0]);
    EXPECT_EQ(describeBlock(p, 0), "COMPILER[FAST X5]");
    EXPECT_EQ(describeBlock(p, 1), "COMPILER[T3 M6]");
    EXPECT_EQ(describeBlock(p, 2), "M60 X1");
    EXPECT_TRUE(p.usesCompilerKeywords);
    // Without the names the same text has an unknown word.
    EXPECT_NE(find(parse("N0001 FAST X5\n"), "PARSE_UNKNOWN_WORD"), nullptr);
}

TEST(ParserCommand, DefineErrors) {
    EXPECT_NE(find(parse("DEFINE AS X"), "PARSE_BAD_DEFINE"), nullptr);
    EXPECT_NE(find(parse("DEFINE FAST G1"), "PARSE_BAD_DEFINE"), nullptr);
    EXPECT_NE(find(parse("DEFINE FAST AS"), "PARSE_BAD_DEFINE"), nullptr);
    EXPECT_NE(find(parse("DEFINE ABCDEFGHIJKLMNOPQRSTU AS G1"), "PARSE_MACRO_NAME_TOO_LONG"),
              nullptr);
    EXPECT_EQ(find(parse("DEFINE ABCDEFGHIJKLMNOPQRST AS G1"), "PARSE_MACRO_NAME_TOO_LONG"),
              nullptr);
    EXPECT_NE(find(parse("DEFINE BSR AS G1"), "PARSE_MACRO_REDEFINES_KEYWORD"), nullptr);
    EXPECT_NE(find(parse("DEFINE M86 AS M86 M3 S10"), "PARSE_NESTED_MACRO"), nullptr);
    EXPECT_NE(find(parse("DEFINE A1 AS G1\nDEFINE B1 AS A1 X5"), "PARSE_NESTED_MACRO"), nullptr);
}

TEST(ParserCommand, ReadOnlyWordsCannotStandAlone) {
    EXPECT_NE(find(parse("SPC"), "PARSE_READ_ONLY_WORD"), nullptr);
    EXPECT_NE(find(parse("G1 TIME"), "PARSE_READ_ONLY_WORD"), nullptr);
}

TEST(ParserCommand, UnbalancedCommandArguments) {
    EXPECT_NE(find(parse("MTP(1,2"), "PARSE_UNBALANCED_PARENTHESES"), nullptr);
    EXPECT_NE(find(parse("TL_RADIUS[1,1=3"), "PARSE_UNBALANCED_PARENTHESES"), nullptr);
}

}  // namespace
