// The cell and its stations driven directly, as the CLI and the panel do:
// machine keys through Station::press, time through advance().
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "InterpTestSupport.h"
#include "cnc_core/cell/Cell.h"

namespace mtc::test {
namespace {

using core::Cell;
using core::ControlKey;

/// The demo cell with program `number` of station `slot` selected.
struct CellFixture {
    CellFixture() : cell(demoCell()) {}
    core::Station& select(int slot, int number, const std::string& source) {
        core::ProgramPtr program = cell.addProgram(slot, number, "test.nc", source);
        EXPECT_FALSE(program->diagnostics.hasErrors()) << diagnosticsText(program->diagnostics);
        core::Station& station = cell.station(slot);
        EXPECT_TRUE(station.selectProgram(number));
        return station;
    }
    /// Advances the whole cell in ticks of `tick` seconds until every
    /// station stands (bounded).
    void runInTicks(double tick) {
        for (int i = 0; i < 1'000'000 && (cell.station(0).busy() || cell.station(1).busy()); ++i)
            cell.advance(tick);
    }
    Cell cell;
};

// 10 mm at F600 = 1 s per move; the three moves are collinear, so the
// look-ahead crosses their ends at full feed.
const char* kThreeMoves =
    "N0001 G1 G90 X10 F600\n"
    "N0002 X20\n"
    "N0003 X30\n"
    "N0004 M30\n";

constexpr double kFeed = 10.0;  // mm/s

/// Path acceleration of a move along X on the demo mill (mm/s^2).
double xAcceleration(const core::Station& station) {
    return station.config().axes[0].maxAcceleration;
}

/// X after `t` seconds of a move from rest at kFeed (past the ramp).
double xAfter(double t, double a) {
    return kFeed * t - kFeed * kFeed / (2 * a);
}

TEST(Station, StartRunsTheProgramInSimulatedTime) {
    CellFixture f;
    core::Station& mill = f.select(0, 1, kThreeMoves);
    const double a = xAcceleration(mill);
    ASSERT_TRUE(mill.press(ControlKey::Start));
    EXPECT_TRUE(mill.control().programActive());
    EXPECT_EQ(mill.control().signalTable().get("P00SACTIV"), 1);
    mill.advance(0.5);
    EXPECT_EQ(mill.control().currentBlock(), "N0001") << "the block the machine executes";
    EXPECT_NEAR(mill.machine().seconds(), 0.5, 1e-9);
    EXPECT_NEAR(mill.machine().position(0), xAfter(0.5, a), 1e-9) << "on the way, not at X10";
    EXPECT_NEAR(mill.machine().distanceToGo(0), 10.0 - xAfter(0.5, a), 1e-9);
    EXPECT_NEAR(mill.machine().actualFeed(), 600.0, 1e-9);
    mill.advance(1.0);
    EXPECT_EQ(mill.control().currentBlock(), "N0002");
    EXPECT_NEAR(mill.machine().position(0), xAfter(1.5, a), 1e-9);
    mill.advance(10.0);
    EXPECT_FALSE(mill.control().programActive());
    // 30 mm at 10 mm/s plus the ramps up and down (v/a) once: no stop at N0001/N0002.
    EXPECT_NEAR(mill.machine().seconds(), 3.0 + kFeed / a, 1e-9) << "busy time only";
    EXPECT_EQ(mill.machine().position(0), 30.0);
    EXPECT_EQ(mill.machine().actualFeed(), 0.0);
    EXPECT_TRUE(mill.control().alarm().empty()) << mill.control().alarm();
}

TEST(Station, StopBrakesMidBlockAndStartResumes) {
    CellFixture f;
    core::Station& mill = f.select(0, 1, kThreeMoves);
    const double a = xAcceleration(mill);
    ASSERT_TRUE(mill.press(ControlKey::Start));
    mill.advance(1.5);
    const double busy = mill.machine().seconds();
    const double x = mill.machine().position(0);
    ASSERT_TRUE(mill.press(ControlKey::Stop));
    EXPECT_TRUE(mill.control().programHeld());
    EXPECT_EQ(mill.control().signalTable().get("P00SHOLD"), 1);
    for (int i = 0; i < 50; ++i)
        mill.advance(0.1);
    // The axes brake on the path (v/a seconds, v^2/2a mm) and then stand.
    EXPECT_NEAR(mill.machine().seconds(), busy + kFeed / a, 1e-9) << "standing is no busy time";
    EXPECT_NEAR(mill.machine().position(0), x + kFeed * kFeed / (2 * a), 1e-9);
    EXPECT_EQ(mill.machine().actualFeed(), 0.0);
    EXPECT_EQ(mill.control().currentBlock(), "N0002") << "held mid-block";
    EXPECT_TRUE(mill.control().programActive());
    ASSERT_TRUE(mill.press(ControlKey::Start));
    EXPECT_FALSE(mill.control().programHeld());
    mill.advance(0.5);
    EXPECT_NEAR(mill.machine().actualFeed(), 600.0, 1e-9) << "on its way again";
    mill.advance(10.0);
    EXPECT_FALSE(mill.control().programActive());
    EXPECT_EQ(mill.machine().position(0), 30.0) << "the same end";
    // One extra stop: braking and starting again cost v/a more than cruising.
    EXPECT_NEAR(mill.machine().seconds(), 3.0 + 2 * kFeed / a, 1e-9);
}

TEST(Station, ProgrammedStopAndSingleBlockHoldWhenTheMachineStands) {
    CellFixture f;
    core::Station& mill = f.select(0, 1, "N0001 G1 G90 X10 F600\nN0002 M00\nN0003 X0\nN0004 M30\n");
    ASSERT_TRUE(mill.press(ControlKey::Start));
    mill.advance(0.5);
    EXPECT_FALSE(mill.control().programHeld()) << "M00 waits for the move of N0001";
    mill.advance(1.0);
    EXPECT_TRUE(mill.control().programHeld());
    EXPECT_EQ(mill.control().currentBlock(), "N0002");
    ASSERT_TRUE(mill.press(ControlKey::SingleBlock));
    ASSERT_TRUE(mill.press(ControlKey::Start));
    mill.advance(0.5);
    EXPECT_FALSE(mill.control().programHeld()) << "the block's move runs";
    mill.advance(1.0);
    EXPECT_TRUE(mill.control().programHeld()) << "single block: held after N0003";
    EXPECT_EQ(mill.machine().position(0), 0.0);
    ASSERT_TRUE(mill.press(ControlKey::Start));
    mill.advance(1.0);
    EXPECT_FALSE(mill.control().programActive());
}

TEST(Station, ControlResetEndsTheRunAtOnce) {
    CellFixture f;
    core::Station& mill = f.select(0, 1, kThreeMoves);
    ASSERT_TRUE(mill.press(ControlKey::Start));
    mill.advance(0.5);
    const double x = mill.machine().position(0);
    ASSERT_TRUE(mill.press(ControlKey::ControlReset));
    EXPECT_FALSE(mill.control().programActive());
    EXPECT_TRUE(mill.machine().idle());
    EXPECT_FALSE(mill.busy());
    mill.advance(5.0);
    EXPECT_EQ(mill.machine().position(0), x) << "the axes stay where they are, mid-block";
    EXPECT_EQ(mill.interpreter().state().modal.machine[0], x) << "the next move starts there";
    // A new run starts from where the axes stopped: no jump.
    ASSERT_TRUE(mill.press(ControlKey::Start));
    mill.advance(0.01);
    EXPECT_GE(mill.machine().position(0), x);
    EXPECT_LT(mill.machine().position(0), x + 0.2);
}

TEST(Station, ARuntimeErrorEndsTheRunWithTheAlarm) {
    CellFixture f;
    core::Station& mill = f.select(0, 1, "N0001 G1 G90 X10 F600\nN0002 T999\nN0003 M30\n");
    ASSERT_TRUE(mill.press(ControlKey::Start));
    mill.advance(0.5);
    EXPECT_TRUE(mill.control().programActive()) << "the move before the error finishes first";
    mill.advance(1.0);
    EXPECT_FALSE(mill.control().programActive());
    EXPECT_NE(mill.control().alarm().find("N0002"), std::string::npos) << mill.control().alarm();
}

TEST(Station, TwoStationsRunAtOnce) {
    CellFixture f;
    core::Station& mill = f.select(0, 1, kThreeMoves);
    core::Station& lathe = f.select(1, 1, "N0001 G1 G90 X20 F600\nN0002 M30\n");
    ASSERT_TRUE(mill.press(ControlKey::Start));
    ASSERT_TRUE(lathe.press(ControlKey::Start));
    f.cell.advance(0.5);
    EXPECT_TRUE(mill.control().programActive());
    EXPECT_TRUE(lathe.control().programActive());
    f.runInTicks(0.02);
    EXPECT_NEAR(mill.machine().seconds(), 3.0 + kFeed / xAcceleration(mill), 1e-9);
    EXPECT_GT(lathe.machine().seconds(), 0.0);
    EXPECT_FALSE(lathe.control().programActive());
}

TEST(Station, OneEventTableAndTheOtherProcessesVariables) {
    CellFixture f;
    EXPECT_EQ(&f.cell.station(0).interpreter().events(), &f.cell.station(1).interpreter().events());
    core::Station& lathe = f.select(1, 1, "N0001 @10=7\nN0002 M30\n");
    ASSERT_TRUE(lathe.press(ControlKey::Start));
    f.runInTicks(0.02);
    core::Station& mill = f.select(0, 1, "N0001 @1=@1:10*2 @1:11=3\nN0002 M30\n");
    ASSERT_TRUE(mill.press(ControlKey::Start));
    f.runInTicks(0.02);
    EXPECT_TRUE(mill.control().alarm().empty()) << mill.control().alarm();
    EXPECT_EQ(mill.interpreter().state().variables.values[1], 14.0);
    EXPECT_EQ(lathe.interpreter().state().variables.values[11], 3.0);
}

/// What a run leaves behind: simulated time, positions, signal changes.
struct RunRecord {
    double seconds = 0.0;
    std::vector<double> positions;
    std::vector<std::string> signals;
};

RunRecord runWith(double tick, const std::string& source) {
    CellFixture f;
    core::Station& mill = f.select(0, 1, source);
    mill.control().signalTable().clearLog();
    EXPECT_TRUE(mill.press(ControlKey::Start));
    for (int i = 0; i < 10'000'000 && mill.busy(); ++i)
        mill.advance(tick);
    RunRecord record;
    record.seconds = mill.machine().seconds();
    for (int axis = 0; axis < mill.interpreter().axes().count(); ++axis)
        record.positions.push_back(mill.machine().position(axis));
    for (const auto& change : mill.control().signalTable().log())
        record.signals.push_back(change.name + "=" + std::to_string(change.value));
    return record;
}

TEST(Station, TheResultDoesNotDependOnHowTimeIsCut) {
    const std::string source =
        "N0001 G0 G90 X10 Y10 Z5\nN0002 G1 Z-1 F600\nN0003 G2 X30 Y10 I20 J10 F1200\n"
        "N0004 G4 F1.5\nN0005 G1 X0 Y0\nN0006 M30\n";
    const RunRecord panel = runWith(0.02, source);  // the panel's 50 Hz ticks at x1
    const RunRecord cli = runWith(1e9, source);     // the CLI: as fast as possible
    EXPECT_GT(panel.seconds, 3.0);
    EXPECT_NEAR(panel.seconds, cli.seconds, 1e-9);
    ASSERT_EQ(panel.positions.size(), cli.positions.size());
    for (std::size_t i = 0; i < panel.positions.size(); ++i)
        EXPECT_NEAR(panel.positions[i], cli.positions[i], 1e-9) << "axis " << i;
    EXPECT_EQ(panel.signals, cli.signals);
}

TEST(Station, AProgramThatNeverMovesIsBoundedPerAdvance) {
    CellFixture f;
    core::Station& mill = f.select(0, 1, "N0001 .LOOP @1=@1+1\nN0002 BRA .LOOP\n");
    ASSERT_TRUE(mill.press(ControlKey::Start));
    EXPECT_EQ(mill.advance(1.0, 1000), 0.0) << "no time passes without work done";
    EXPECT_EQ(mill.runBlocks(), 1000u);
    EXPECT_TRUE(mill.running());
}

}  // namespace
}  // namespace mtc::test
