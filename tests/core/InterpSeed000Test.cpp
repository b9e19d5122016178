// Interpreter and parser rules of seed 000 outside the restart itself
// (issue 15): the last Q function read like M(16), BRF, the skip slash
// before the colon of a primary block, page 60 updated at a program stop.
#include <gtest/gtest.h>

#include "RestartTestSupport.h"

namespace {

using namespace mtc::core;
using namespace mtc::test;

double variable(const Interpreter& interpreter, int n) {
    return interpreter.state().variables.values[static_cast<std::size_t>(n)];
}

TEST(InterpSeed000, QReadsTheLastQFunction) {
    Station mill(demoCell(), 0);
    const RunResult r = mill.run(
        "N0001 @1=Q\n"
        "N0002 Q31 Q44\n"
        "N0003 @2=Q @3=Q+1\n"
        "N0004 M30\n"
        "N0005 PROGRAMMENDE\n");
    ASSERT_EQ(r.status, RunStatus::Ended) << diagnosticsText(r.diagnostics);
    EXPECT_EQ(variable(*mill.interpreter, 1), -1) << "no Q since the program start";
    EXPECT_EQ(variable(*mill.interpreter, 2), 44) << "the last Q of the block";
    EXPECT_EQ(variable(*mill.interpreter, 3), 45);
    EXPECT_EQ(mill.interpreter->state().lastQ, -1) << "M30 resets it";
}

TEST(InterpSeed000, QWithADigitIsNotARead) {
    const ProgramPtr p = parse("N0001 @1=Q5\n", 1);
    ASSERT_TRUE(p->diagnostics.hasErrors());
    EXPECT_EQ(p->diagnostics.items()[0].code, "PARSE_BAD_EXPRESSION");
}

TEST(InterpSeed000, SkipSlashAfterTheBlockNumberBeforeTheColon) {
    const ProgramPtr p = parse(
        "N0001 /: G0 X1\n"
        "/N0002 : X2\n"
        "N0003 / X3\n"
        "N0004 : X4\n",
        1);
    ASSERT_FALSE(p->diagnostics.hasErrors()) << diagnosticsText(p->diagnostics);
    const auto flags = [&](std::size_t b) { return p->blocks[b].flags; };
    EXPECT_TRUE((flags(0) & kBlockSkip) && (flags(0) & kBlockPrimary));
    EXPECT_TRUE((flags(1) & kBlockSkip) && (flags(1) & kBlockPrimary));
    EXPECT_TRUE((flags(2) & kBlockSkip) && !(flags(2) & kBlockPrimary));
    EXPECT_TRUE(!(flags(3) & kBlockSkip) && (flags(3) & kBlockPrimary));
    EXPECT_EQ(p->blocks[0].number, 1);
}

TEST(InterpSeed000, SkipSlashAfterTheColonIsRefused) {
    for (const char* text : {"N0001 :/ X1\n", "N0001 // X1\n", "N0001 X1 /\n"}) {
        const ProgramPtr p = parse(text, 1);
        ASSERT_TRUE(p->diagnostics.hasErrors()) << text;
        EXPECT_EQ(p->diagnostics.items()[0].code, "PARSE_MISPLACED_SKIP") << text;
    }
}

TEST(InterpSeed000, SkippedPrimaryBlockIsSkippedWithTheSwitch) {
    Station mill(demoCell(), 0);
    mill.interpreter->options().skipBlocks = true;
    const RunResult r = mill.run("N0001 @1=1\nN0002 /: @1=2\nN0003 M30\n");
    ASSERT_EQ(r.status, RunStatus::Ended) << diagnosticsText(r.diagnostics);
    EXPECT_EQ(variable(*mill.interpreter, 1), 1);
}

TEST(InterpSeed000, BrfChecksItsLabelAndGoesOn) {
    Station mill(demoCell(), 0);
    const RunResult r = mill.run(
        "N0001 @1=1 BRF .L\n"
        "N0002 @1=2\n"
        "N0003 .L @2=1\n"
        "N0004 M30\n");
    ASSERT_EQ(r.status, RunStatus::Ended) << diagnosticsText(r.diagnostics);
    EXPECT_EQ(variable(*mill.interpreter, 1), 2) << "BRF is not taken";
    Station missing(demoCell(), 0);
    const RunResult m = missing.run("N0001 BRF .NOWHERE\nN0002 M30\n");
    EXPECT_EQ(m.status, RunStatus::Error);
    EXPECT_EQ(errorCodes(m.diagnostics), std::vector<std::string>{"LABEL_NOT_FOUND"});
}

TEST(InterpSeed000, ProgramStopUpdatesTheRotaryAxisModesOfPage60) {
    RestartCell lathe(1);
    lathe.add("N0001 G0 C90\nN0002 M00\nN0003 S1 500 M3\nN0004 M01\nN0005 M00\nN0006 M30\n", 1);
    ASSERT_TRUE(lathe.live.select(1));
    EXPECT_EQ(lathe.page(60, 0, 1), 0);
    ASSERT_EQ(lathe.live.run().status, RunStatus::Stopped);
    EXPECT_EQ(lathe.page(60, 0, 1), 1) << "M00: S1 is in rotary axis mode";
    ASSERT_EQ(lathe.live.run().status, RunStatus::Stopped) << "M01 without optional stop runs on";
    EXPECT_EQ(lathe.page(60, 0, 1), 0) << "stopped at N0005 after M3";
}

}  // namespace
