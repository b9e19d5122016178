// The REPOS path the toolpath view draws (docs/decisions/toolpath.md TP-007):
// the remaining ADJUST / REPOS moves interpreted on a private interpreter.
#include <gtest/gtest.h>

#include "RestartStation.h"
#include "cnc_core/restart/ReposPreview.h"

namespace mtc::test {
namespace {

using core::ReposPreview;
using core::ReposPreviewStart;

/// What the panel hands the preview at this moment of the restart.
ReposPreview preview(RestartStation& mill) {
    ReposPreviewStart start;
    start.state = mill.cell.live.state();
    start.options = mill.cell.live.options();
    const auto& route = mill.sequence.computing().route();
    start.target = {route.targetProgram->number, mill.sequence.computing().selection().target.block,
                    1};
    start.targetChain = route.targetChain;
    start.beforeAdjust = mill.sequence.phase() == RestartPhase::TargetReached;
    return core::previewRepositioning(mill.cell.config, mill.cell.store, *mill.cell.machineData,
                                      start);
}

void expectSamePosition(const std::array<double, core::kMaxAxes>& a,
                        const std::array<double, core::kMaxAxes>& b, const char* what) {
    for (int axis = 0; axis < 3; ++axis)
        EXPECT_NEAR(a[axis], b[axis], 1e-9) << what << axis;
}

TEST(ReposPreview, BeforeStartItIsTheWayAdjustAndReposWillMoveTheAxes) {
    RestartStation mill(0);
    mill.addDemoPrograms();
    mill.cell.live.takeMachinePositions({5, 6, 7});
    ASSERT_EQ(mill.restartAtDemoTarget(), RestartPhase::TargetReached);
    const auto before = mill.cell.live.state().modal.machine;
    const ReposPreview path = preview(mill);
    EXPECT_TRUE(path.reachesTarget) << diagnosticsText(path.diagnostics);
    expectSamePosition(mill.cell.live.state().modal.machine, before, "nothing moved, axis ");
    EXPECT_TRUE(mill.cell.sps.motions.empty()) << "the machine saw no move";
    const auto& reentry = mill.sequence.reentry().machine;
    // Start, ADJUST's clear height Z90, G77 X Y (plane first), G77 Z.
    ASSERT_EQ(path.corners.size(), 4u);
    expectSamePosition(path.corners[0], {5, 6, 7}, "where the axes stand, axis ");
    expectSamePosition(path.corners[1], {5, 6, 90}, "clear height, axis ");
    expectSamePosition(path.corners[2], {reentry[0], reentry[1], 90}, "G77 X0 Y0, axis ");
    expectSamePosition(path.corners[3], reentry, "G77 Z0, axis ");
    EXPECT_EQ(path.blocks[1].block, "N0006");

    // The real run goes through the same corners (nobody jogs).
    mill.control.press(ControlKey::Start);
    ASSERT_EQ(mill.runUntilWaiting(), RestartPhase::ManualMode);
    mill.control.press(ControlKey::Automatic);
    mill.control.press(ControlKey::Start);
    ASSERT_EQ(mill.runUntilWaiting(), RestartPhase::Reestablished);
    const auto& moves = mill.cell.sps.motions;
    ASSERT_EQ(moves.size(), 3u);
    for (std::size_t m = 0; m < moves.size(); ++m)
        expectSamePosition(moves[m].end, path.corners[m + 1], "real move end, axis ");
}

TEST(ReposPreview, AfterAJogItStartsWhereTheOperatorLeftTheAxes) {
    RestartStation mill(0);
    mill.addDemoPrograms();
    ASSERT_EQ(mill.adjustUntilManualMode(), RestartPhase::ManualMode);
    ASSERT_TRUE(mill.sequence.jog(1, 40.0));
    const ReposPreview path = preview(mill);
    EXPECT_TRUE(path.reachesTarget) << diagnosticsText(path.diagnostics);
    ASSERT_EQ(path.corners.size(), 3u) << "only REPOS is left: G77 X Y, G77 Z";
    EXPECT_DOUBLE_EQ(path.corners[0][1], 40.0);
    EXPECT_DOUBLE_EQ(path.corners[1][2], 90.0) << "Z stays up while X and Y move";
    expectSamePosition(path.corners[2], mill.sequence.reentry().machine, "re-entry, axis ");
}

TEST(ReposPreview, WithoutAdjustThereIsNoPathAndNoCrash) {
    RestartStation mill(0);
    mill.cell.add(kMain, 1);
    DiagnosticList d;
    ASSERT_TRUE(mill.sequence.accept(mill.cell.selection(1, 1, 4), d));
    ASSERT_EQ(mill.runUntilWaiting(), RestartPhase::TargetReached);
    const ReposPreview path = preview(mill);
    EXPECT_FALSE(path.reachesTarget);
    EXPECT_EQ(path.corners.size(), 1u);
    EXPECT_FALSE(path.diagnostics.empty());
}

TEST(ReposPreview, AnEndlessReposStopsAtTheBudget) {
    RestartStation mill(0);
    mill.cell.add("N0000 M30\nN0001 .ADJUST\nN0002 .REPOS G77 X0\nN0003 BRA .REPOS\n", 99);
    mill.cell.add(kMain, 1);
    ASSERT_TRUE(mill.accept(mill.cell.selection(1, 1, 4)));
    ASSERT_EQ(mill.runUntilWaiting(), RestartPhase::TargetReached);
    const ReposPreview path = preview(mill);
    EXPECT_FALSE(path.reachesTarget);
    EXPECT_LE(path.corners.size(), 10'001u);
}

}  // namespace
}  // namespace mtc::test
