// The route of an NC program restart (issue 15, seed 000 2.4-2.6): a target
// behind a JMP starts at the beginning of the NC program, a block only a
// subroutine call runs through needs <Plane+>, the start warnings come from
// the NC for the CLI and the screen alike, BRF can be restarted past.
#include <gtest/gtest.h>

#include "RestartStation.h"
#include "cnc_core/restart/RestartRoute.h"

namespace {

using namespace mtc::core;
using namespace mtc::test;

std::unique_ptr<ComputingProcess> compute(RestartCell& cell, const RestartSelection& selection,
                                          DiagnosticList* failure = nullptr) {
    auto process =
        std::make_unique<ComputingProcess>(cell.config, cell.store, cell.sps, cell.services());
    DiagnosticList d;
    const bool begun =
        process->begin(selection, cell.live.state(), cell.live.options(), 100'000, d);
    if (failure) *failure = d;
    if (!begun) return process;
    while (process->runToEnd().status == ComputingStatus::Stopped) {
    }
    return process;
}

double var(const ComputingProcess& c, int n) {
    return c.state().variables.values[static_cast<std::size_t>(n)];
}

// Program 1 sets a tool, spindle, coolant, an offset and a variable, then
// leaves with JMP; program 7 uses them.
const char* kBeforeJump =
    "N0001 T3 G54 S1200 M3 M108\n"
    "N0002 @40=7\n"
    "N0003 : @41=1 ;primary block before the JMP\n"
    "N0004 JMP 7\n"
    "N0005 M30\n";
const char* kBehindJump =
    "N0000 G0 X10 Y10\n"
    "N0001 G1 X20 F300\n"
    "N0002 @42=@40+1\n"
    "N0003 M30\n";

TEST(RestartRoute, TargetBehindAJumpStartsAtTheBeginningOfTheProgram) {
    RestartCell mill(0);
    mill.add(kBeforeJump, 1);
    mill.add(kBehindJump, 7);
    RestartSelection s = mill.selection(1, 7, 2);
    s.path = {mill.ref(1, 4)};
    DiagnosticList d;
    auto c = compute(mill, s, &d);
    ASSERT_EQ(c->progress().status, ComputingStatus::TargetReached)
        << diagnosticsText(c->diagnostics());
    EXPECT_EQ(c->route().startProgram->number, 1) << "seed 000, 2.4: the beginning of program 1";
    EXPECT_EQ(c->route().startBlock, 0u);
    const InterpreterState& at = c->state();
    EXPECT_EQ(at.modal.tool, 3);
    EXPECT_EQ(at.modal.g[kGroupZeroOffset], 54) << "a JMP keeps the groups of seed 000";
    EXPECT_EQ(at.mGroups[2], 3);
    EXPECT_EQ(at.mGroups[5], 108);
    EXPECT_EQ(at.modal.spindleSpeed[1], 1200);
    EXPECT_EQ(var(*c, 40), 7);
    EXPECT_EQ(at.selected->number, 7) << "after the JMP program 7 is the selected one";
}

TEST(RestartRoute, PrimaryBlockSearchGoesOnBeforeTheJump) {
    RestartCell mill(0);
    mill.add(kBeforeJump, 1);
    mill.add(kBehindJump, 7);
    RestartSelection s = mill.selection(1, 7, 2);
    s.path = {mill.ref(1, 4)};
    s.fromLastPrimary = true;
    DiagnosticList d;
    auto c = compute(mill, s, &d);
    ASSERT_EQ(c->progress().status, ComputingStatus::TargetReached)
        << diagnosticsText(c->diagnostics());
    EXPECT_TRUE(c->route().primary);
    EXPECT_EQ(c->route().startProgram->number, 1);
    EXPECT_EQ(c->route().startBlock, mill.block(1, 3));
    EXPECT_TRUE(d.empty()) << diagnosticsText(d);
}

const char* kContour =
    "N0001 G0 X0 Y0\n"
    "N0002 BSR .LAP\n"
    "N0003 BSR .LAP\n"
    "N0004 M30\n"
    "N0005 .LAP G1 X10 F500\n"
    "N0006 Y10\n"
    "N0007 X0 RTS\n";

TEST(RestartRoute, SubroutineBodyWithoutPlanePlusIsRefusedWithTheCallToFollow) {
    RestartCell mill(0);
    mill.add(kContour, 1);
    DiagnosticList d;
    auto c = compute(mill, mill.selection(1, 1, 6), &d);
    EXPECT_EQ(c->progress().status, ComputingStatus::Idle) << "refused before it starts";
    ASSERT_EQ(errorCodes(d), std::vector<std::string>{"RESTART_TARGET_IN_SUBROUTINE"});
    const Diagnostic& refusal = d.items()[0];
    EXPECT_EQ(refusal.where.block, "N0006");
    EXPECT_NE(refusal.message.find(".LAP"), std::string::npos) << refusal.message;
    EXPECT_NE(refusal.message.find("N0002"), std::string::npos) << refusal.message;
    EXPECT_NE(refusal.message.find("<Plane+>"), std::string::npos) << refusal.message;
    // Following the second call with Plane+ reaches it.
    RestartSelection s = mill.selection(1, 1, 6);
    s.path = {mill.ref(1, 3)};
    auto through = compute(mill, s);
    ASSERT_EQ(through->progress().status, ComputingStatus::TargetReached)
        << diagnosticsText(through->diagnostics());
    EXPECT_EQ(through->state().callStack.at(0).callBlock, mill.block(1, 3));
}

TEST(RestartRoute, BlocksOfTheMainFlowAndConditionalBranchesAreReached) {
    RestartCell mill(0);
    mill.add(
        "N0001 @1=1 BEQ .SKIP\nN0002 BRA .E\nN0003 .SKIP @2=1\nN0004 .E @3=1\nN0005 M30\n"
        "N0006 .DEAD @4=1\nN0007 M30\n",
        1);
    for (int target : {2, 3, 4}) {
        DiagnosticList d;
        compute(mill, mill.selection(1, 1, target), &d);
        EXPECT_FALSE(d.hasErrors()) << "N000" << target << ": " << diagnosticsText(d);
    }
    // Dead code after M30 that no call runs through: the computing process
    // answers "target block cannot be found" (seed 000, 2.7).
    DiagnosticList dead;
    auto c = compute(mill, mill.selection(1, 1, 6), &dead);
    EXPECT_FALSE(dead.hasErrors()) << diagnosticsText(dead);
    EXPECT_EQ(errorCodes(c->diagnostics()), std::vector<std::string>{"RESTART_TARGET_NOT_FOUND"});
}

TEST(RestartRoute, StartWarningsComeFromTheNc) {
    RestartCell mill(0);
    mill.add("N0001 G91 X1\nN0002 : X1\nN0003 G90 X5\nN0004 M30\n", 1);
    RestartSelection s = mill.selection(1, 1, 3);
    s.fromLastPrimary = true;
    DiagnosticList d;
    auto c = compute(mill, s, &d);
    ASSERT_EQ(c->progress().status, ComputingStatus::TargetReached);
    ASSERT_EQ(d.size(), 1u) << diagnosticsText(d);
    EXPECT_EQ(d.items()[0].code, "RESTART_START_AFTER_G91");
    EXPECT_EQ(d.items()[0].severity, Severity::Warning);
}

TEST(RestartRoute, NoPrimaryBlockIsReportedOnce) {
    RestartStation mill(0);
    mill.cell.add(kLibrary, 99);
    mill.cell.add("N0001 G0 X1\nN0002 G1 X2 F100\nN0003 X3\nN0004 X4\nN0005 M30\n", 1);
    RestartSelection s = mill.cell.selection(1, 1, 4);
    s.fromLastPrimary = true;
    DiagnosticList accepted;
    ASSERT_TRUE(mill.sequence.accept(s, accepted, 100'000));
    ASSERT_EQ(mill.runUntilWaiting(), RestartPhase::TargetReached);
    int count = 0;
    for (const Diagnostic& d : mill.sequence.diagnostics().items())
        count += d.code == "RESTART_NO_PRIMARY_BLOCK";
    EXPECT_EQ(count, 1) << diagnosticsText(mill.sequence.diagnostics());
}

TEST(RestartRoute, TargetAfterBrf) {
    RestartCell mill(0);
    mill.add("N0001 @1=1 BRF .L\nN0002 @2=1\nN0003 .L @3=1\nN0004 M30\n", 1);
    auto c = compute(mill, mill.selection(1, 1, 3));
    ASSERT_EQ(c->progress().status, ComputingStatus::TargetReached)
        << diagnosticsText(c->diagnostics());
    EXPECT_EQ(var(*c, 2), 1) << "BRF is not taken (I-019)";
}

}  // namespace
