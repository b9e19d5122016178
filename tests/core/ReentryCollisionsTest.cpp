// The restart's way back checked against the part at the target (issue 19
// §4, D-021): the stock cut up to the target block, every ADJUST / REPOS move
// of the preview swept through it without cutting.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "RestartStation.h"
#include "cnc_core/removal/ReentryCollisions.h"
#include "cnc_core/removal/RemovalRun.h"
#include "tests/support/SlotRestartProgram.h"

namespace mtc::test {
namespace {

using core::removal::checkRestartReentry;
using core::removal::ReentryCheck;
using core::removal::ReentryCollision;

// The slot of tests/support/SlotRestartProgram.h (mill, T2, target N0050).
const char* kSlot = mtc::test::kSlotRestartProgram;

// The way back goes up first, then over the part, then down into the slot.
const char* kSafeReturn =
    "N0000 M30\n"
    "N0001 .ADJUST G0 G54 Z15 ;above the part\n"
    "N0002 .REPOS G77 X0 Y0 F2000\n"
    "N0003 G77 Z0 F500 RTS\n";

// The same way back without going up: the X Y move runs through the part.
const char* kStraightReturn =
    "N0000 M30\n"
    "N0001 .ADJUST @150=0\n"
    "N0002 .REPOS G77 X0 Y0 F2000\n"
    "N0003 G77 Z0 F500 RTS\n";

// ADJUST puts the tool down on the top face in rapid, then lifts it.
const char* kRapidOntoTop =
    "N0000 M30\n"
    "N0001 .ADJUST G0 G54 Z0 ;rapid onto the top face\n"
    "N0002 G0 Z1 ;one millimetre above: clear\n"
    "N0003 G0 Z15\n"
    "N0004 .REPOS G77 X0 Y0 F2000\n"
    "N0005 G77 Z0 F500 RTS\n";

/// Work coordinates of the mill's G54 to machine positions.
std::array<double, core::kMaxAxes> millMachine(double x, double y, double z) {
    return {x - 150.0, y - 80.0, z - 120.0};
}

/// Restarts program 1 at N`target` with `library` as program 99, the axes
/// standing at machine positions `at`; the check at the target reached.
ReentryCheck checkAt(RestartStation& station, const char* program, const char* library, int target,
                     const std::array<double, core::kMaxAxes>& at) {
    station.cell.add(library, 99);
    station.cell.add(program, 1);
    station.cell.live.takeMachinePositions(at);
    EXPECT_TRUE(station.accept(station.cell.selection(1, 1, target)));
    EXPECT_EQ(station.runUntilWaiting(), RestartPhase::TargetReached);
    const auto check = checkRestartReentry(station.sequence, station.cell.live, station.cell.store);
    EXPECT_TRUE(check.has_value());
    return check ? *check : ReentryCheck{};
}

TEST(ReentryCollisions, MillReposStraightThroughThePartIsFlaggedWhereItEntersTheMaterial) {
    RestartStation mill(0);
    // Beside the part (Y70: the R5 cutter clears the Y60 edge), 2 below the top.
    const ReentryCheck check = checkAt(mill, kSlot, kStraightReturn, 50, millMachine(50, 70, -2));
    ASSERT_TRUE(check.checked) << diagnosticsText(check.diagnostics);
    EXPECT_GT(check.removedVolume, 0.0) << "the slot was cut before the target";
    EXPECT_EQ(check.moves, 2u);
    ASSERT_EQ(check.collisions.size(), 1u) << "G77 X Y cuts, G77 Z goes down the slot";
    const ReentryCollision& c = check.collisions.front();
    EXPECT_TRUE(c.repos);
    EXPECT_FALSE(c.rapid);
    EXPECT_EQ(c.where.block, "N0002");
    EXPECT_EQ(c.where.program, 99);
    // From (50, 70) to the re-entry point (80, 30): the cutter's edge reaches
    // the first cell centres (Y 59.9) when its centre is at Y 64.9.
    const double t = (70.0 - 64.9) / 40.0;
    const auto expected = millMachine(50.0 + 30.0 * t, 64.9, -2.0);
    EXPECT_NEAR(c.position[0], expected[0], 0.3);
    EXPECT_NEAR(c.position[1], expected[1], 0.3);
    EXPECT_NEAR(c.position[2], expected[2], 1e-9);
    // Nothing of the station moved or changed phase.
    EXPECT_EQ(mill.sequence.phase(), RestartPhase::TargetReached);
    EXPECT_TRUE(mill.cell.sps.motions.empty());
}

TEST(ReentryCollisions, MillReposThatRetractsAboveThePartFirstIsClear) {
    RestartStation mill(0);
    const ReentryCheck check = checkAt(mill, kSlot, kSafeReturn, 50, millMachine(50, 70, -2));
    ASSERT_TRUE(check.checked) << diagnosticsText(check.diagnostics);
    EXPECT_EQ(check.moves, 3u);
    EXPECT_TRUE(check.collisions.empty()) << "first at " << check.collisions.front().where.block
                                          << " of " << check.collisions.front().where.program;
}

TEST(ReentryCollisions, ARapidOntoTheTopFaceTouchesOneMillimetreAboveDoesNot) {
    RestartStation mill(0);
    const ReentryCheck check = checkAt(mill, kSlot, kRapidOntoTop, 50, millMachine(50, 50, 20));
    ASSERT_TRUE(check.checked) << diagnosticsText(check.diagnostics);
    ASSERT_EQ(check.collisions.size(), 1u);
    const ReentryCollision& c = check.collisions.front();
    EXPECT_FALSE(c.repos) << "an ADJUST move";
    EXPECT_TRUE(c.rapid);
    EXPECT_EQ(c.where.block, "N0001");
    // It touches where its face reaches the top (within the tolerance above it).
    EXPECT_NEAR(c.position[2], -120.0, check.tolerance + 0.2);
    EXPECT_NEAR(c.position[0], -100.0, 1e-9);
}

// Lathe (process 1): bar R40 at G54 from Z2 back, turned to R30 from the
// face to Z-50 with T1 (nose 0.4, edge 3: the insert on the +Z side).
const char* kShaft =
    "N0010 : T1 S800 M4\n"
    "N0020 G0 G54 X45 Z5\n"
    "N0030 G1 X30 F200\n"
    "N0040 Z-50\n"
    "N0050 X45 ;target\n"
    "N0060 G0 Z5\n"
    "N0070 M30\n";

const char* kLatheXFirst =
    "N0000 M30\n"
    "N0001 .ADJUST @150=0\n"
    "N0002 .REPOS G77 X0 F1000\n"
    "N0003 G77 Z0 F500 RTS\n";

const char* kLatheZFirst =
    "N0000 M30\n"
    "N0001 .ADJUST @150=0\n"
    "N0002 .REPOS G77 Z0 F1000\n"
    "N0003 G77 X0 F500 RTS\n";

/// Lathe G54 (X0 Z255.5), radius programming: work X Z to machine X, Z.
std::array<double, core::kMaxAxes> latheMachine(double x, double z) {
    return {x, z + 255.5};
}

TEST(ReentryCollisions, LatheReposDownIntoTheUnturnedBarIsFlaggedAlongTheTurnedDiameterNot) {
    RestartStation lathe(1);
    // Behind the turned length, 5 above the bar: X first plunges into it.
    const ReentryCheck check = checkAt(lathe, kShaft, kLatheXFirst, 50, latheMachine(45, -100));
    ASSERT_TRUE(check.checked) << diagnosticsText(check.diagnostics);
    EXPECT_GT(check.removedVolume, 0.0);
    ASSERT_FALSE(check.collisions.empty());
    EXPECT_EQ(check.collisions.front().where.block, "N0002");
    EXPECT_TRUE(check.collisions.front().repos);
    // The nose enters the bar at radius 40 (its tip a nose radius further in).
    EXPECT_NEAR(check.collisions.front().position[0], 40.0, 0.5);

    RestartStation safe(1);
    const ReentryCheck clear = checkAt(safe, kShaft, kLatheZFirst, 50, latheMachine(45, -100));
    ASSERT_TRUE(clear.checked) << diagnosticsText(clear.diagnostics);
    EXPECT_TRUE(clear.collisions.empty()) << "Z outside the bar, then X down to the re-entry";
}

// Lathe under G32 (D-027): a groove 2 mm deep milled with T9 (R4.85) round
// the R40 bar at Z 200 from Y1 0 to Y1 50 (0 to 71.6 degrees on RI 40); the
// target continues it.
const char* kCylinderGroove =
    "N0010 : T9\n"
    "N0020 G0 G54 X45 Z-30\n"
    "N0025 G0 C0\n"
    "N0030 G20 Z0 C0 X0\n"
    "N0040 G32 RI 40\n"
    "N0045 G0 G56 Y1 0 Z1 200\n"
    "N0046 G1 X38 F100\n"
    "N0047 G1 Y1 50 F300\n"
    "N0050 G1 Y1 100 ;target\n"
    "N0060 G0 X45\n"
    "N0070 G30\n"
    "N0080 G18\n"
    "N0090 M30\n";

// ADJUST turns the part to 180 degrees and selects G32 again (page 60
// element 4, as the demo library does); REPOS plunges the infeed X first,
// into the bar half a turn from the groove.
const char* kCylinderInfeedFirst =
    "N0000 M30\n"
    "N0001 .ADJUST G0 C180\n"
    "N0002 G20 Z0 C0 X0\n"
    "N0003 G=MTD(60,,,4)\n"
    "N0004 .REPOS G77 X0 F1000\n"
    "N0005 G77 Y1=0 Z1=0 F5000 RTS\n";

// The demo library's order: the surface position first, the infeed last.
const char* kCylinderInfeedLast =
    "N0000 M30\n"
    "N0001 .ADJUST G0 C180\n"
    "N0002 G20 Z0 C0 X0\n"
    "N0003 G=MTD(60,,,4)\n"
    "N0004 .REPOS G77 Y1=0 Z1=0 F5000\n"
    "N0005 G77 X0 F1000 RTS\n";

TEST(ReentryCollisions, G32ReposIsCheckedAgainstTheDevelopedJacket) {
    // The axes stand 5 above the bar at Z 200.
    RestartStation lathe(1);
    const ReentryCheck check =
        checkAt(lathe, kCylinderGroove, kCylinderInfeedFirst, 50, {45.0, 200.0});
    ASSERT_TRUE(check.checked) << diagnosticsText(check.diagnostics);
    EXPECT_GT(check.removedVolume, 1000.0) << "the groove was cut before the target";
    ASSERT_EQ(check.collisions.size(), 2u) << "X into the bar, then round through it at X38";
    const ReentryCollision& plunge = check.collisions.front();
    EXPECT_EQ(plunge.where.block, "N0004");
    EXPECT_TRUE(plunge.repos);
    EXPECT_FALSE(plunge.rapid);
    // The face enters the bar at radius 40 (more than the tolerance into it).
    EXPECT_NEAR(plunge.position[0], 40.0 - check.tolerance, 0.1);
    EXPECT_NEAR(plunge.scene[0], -plunge.position[0], 0.1) << "half a turn: the scene's -X";
    EXPECT_EQ(check.collisions.back().where.block, "N0005");

    RestartStation safe(1);
    const ReentryCheck clear =
        checkAt(safe, kCylinderGroove, kCylinderInfeedLast, 50, {45.0, 200.0});
    ASSERT_TRUE(clear.checked) << diagnosticsText(clear.diagnostics);
    EXPECT_TRUE(clear.collisions.empty()) << "over the bar, then down into the groove's end";
}

TEST(ReentryCollisions, APartThatCannotBeModelledMeansNotCheckedWithTheReason) {
    RestartStation mill(0);
    checkAt(mill, kSlot, kSafeReturn, 50, millMachine(50, 70, -2));
    core::removal::RemovalSettings tiny;
    tiny.maxCells = 10;
    const auto check = checkRestartReentry(mill.sequence, mill.cell.live, mill.cell.store, tiny);
    ASSERT_TRUE(check);
    EXPECT_FALSE(check->checked);
    EXPECT_TRUE(check->collisions.empty());
    EXPECT_NE(diagnosticsText(check->diagnostics).find("REMOVAL_STOCK"), std::string::npos);
}

TEST(ReentryCollisions, FromInsideTheMaterialOnlyGoingDeeperOrSidewaysCounts) {
    std::string error;
    core::Stock stock;
    stock.shape = core::Stock::Shape::Block;
    stock.min = {0, 0, -10};
    stock.max = {100, 60, 0};
    const auto part = core::removal::PartModel::create(stock, {}, false, error);
    ASSERT_TRUE(part) << error;
    const core::removal::Cutter cutter{5.0, 0, false};
    // The tool stands 2 deep in the uncut block.
    EXPECT_FALSE(part->touches({50, 30, -2}, {50, 30, 20}, cutter, -0.1)) << "feed up: away";
    EXPECT_FALSE(part->touches({50, 30, -2}, {50, 30, 20}, cutter, 0.1)) << "rapid up: away";
    EXPECT_TRUE(part->touches({50, 30, -2}, {50, 30, -5}, cutter, -0.1)) << "deeper cuts";
    EXPECT_TRUE(part->touches({50, 30, -2}, {60, 30, -2}, cutter, -0.1)) << "sideways cuts";
    EXPECT_TRUE(part->touches({50, 30, 0}, {60, 30, 0}, cutter, 0.1)) << "a rapid along the top";
    EXPECT_FALSE(part->touches({50, 30, 0}, {60, 30, 0}, cutter, -0.1)) << "a feed along the top";
}

TEST(ReentryCollisions, HugeCoordinatesCostOneSweepAndNeverTouchOrHang) {
    // Part queries directly: a chord of 1e300 and non-finite ones.
    std::string error;
    core::Stock stock;
    stock.shape = core::Stock::Shape::Block;
    stock.min = {0, 0, -10};
    stock.max = {100, 60, 0};
    auto part = core::removal::PartModel::create(stock, {}, false, error);
    ASSERT_TRUE(part) << error;
    const core::removal::Cutter cutter{5.0, 0, false};
    const double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_TRUE(part->touches({-1e300, 30, -5}, {1e300, 30, -5}, cutter, -0.1));
    EXPECT_FALSE(part->touches({-1e300, 30, 1e300}, {1e300, 30, 1e300}, cutter, 0.1));
    EXPECT_FALSE(part->touches({inf, 30, -5}, {0, 30, -5}, cutter, 0.1));
    EXPECT_FALSE(part->touches({nan, 30, -5}, {0, 30, -5}, cutter, 0.1));
    EXPECT_FALSE(part->touches({0, 30, -5}, {1, 30, -5}, {nan, 0, false}, 0.1));
    EXPECT_DOUBLE_EQ(part->removedVolume(), 0.0) << "touches() changes nothing";
}

TEST(ReentryCollisions, ATravelLimitInAdjustEndsThePreviewAndIsReported) {
    RestartStation mill(0);
    const char* far =
        "N0000 M30\n"
        "N0001 .ADJUST G0 G53 X99999999 ;beyond the travel range\n"
        "N0002 .REPOS G77 X0 Y0 F2000\n"
        "N0003 G77 Z0 F500 RTS\n";
    const ReentryCheck check = checkAt(mill, kSlot, far, 50, millMachine(50, 30, -2));
    EXPECT_TRUE(check.checked);
    EXPECT_EQ(check.moves, 0u);
    EXPECT_NE(diagnosticsText(check.diagnostics).find("TRAVEL_LIMIT"), std::string::npos);
}

TEST(ReentryCollisions, MovesToHugeCoordinatesAreCheckedInBoundedWork) {
    RestartStation mill(0);
    checkAt(mill, kSlot, kSafeReturn, 50, millMachine(50, 30, -2));
    const auto start = core::reposPreviewStart(mill.sequence, mill.cell.live);
    ASSERT_TRUE(start);
    core::ReposPreview preview = core::previewRepositioning(mill.cell.config, mill.cell.store,
                                                            *mill.cell.machineData, *start);
    ASSERT_FALSE(preview.moves.empty());
    // Out to X 1e30 and back at Z-2 (work), as no interpreter would send it.
    core::PreviewMove out = preview.moves.front();
    out.motion.type = core::MotionType::Rapid;
    out.motion.start = millMachine(50, 30, -2);
    out.motion.end = out.motion.start;
    out.motion.end[0] = 1e30;  // the toolpath's float vertices hold it
    core::PreviewMove back = out;
    back.motion.type = core::MotionType::Linear;
    std::swap(back.motion.start, back.motion.end);
    back.repos = true;
    preview.moves = {out, back};
    core::removal::ReentryCheckInput input;
    input.config = &mill.cell.config;
    input.programs = &mill.cell.store;
    input.selection = &mill.sequence.computing().selection();
    input.route = &mill.sequence.computing().route();
    input.preview = &preview;
    const ReentryCheck check = core::removal::checkReentry(input);
    ASSERT_TRUE(check.checked) << diagnosticsText(check.diagnostics);
    ASSERT_EQ(check.collisions.size(), 2u) << "out through the slot's end, back through the part";
    // Out: from the slot at X50 the rapid meets the material beyond its end
    // (X80 + R5, cells from 85.1) when its centre reaches about X80.1.
    EXPECT_NEAR(check.collisions[0].position[0], millMachine(80.1, 0, 0)[0], 0.3);
    EXPECT_TRUE(check.collisions[0].rapid);
    // Back: it meets the +X face of the part (cells to 99.9) at X 104.9.
    EXPECT_NEAR(check.collisions[1].position[0], millMachine(104.9, 0, 0)[0], 0.3);
    EXPECT_TRUE(check.collisions[1].repos);
}

}  // namespace
}  // namespace mtc::test
