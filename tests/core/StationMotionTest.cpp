// The station's machine moves in time (issue 16 §2): overrides, dwell and
// auxiliary functions in machine time, spindle run-up, and results that do
// not depend on how the time is cut into advance() calls — with feed
// override, rapid override and adaptive feed control too.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "InterpTestSupport.h"
#include "cnc_core/afc/AdaptiveFeedControl.h"
#include "cnc_core/cell/Cell.h"

namespace mtc::test {
namespace {

using core::ControlKey;

struct MillFixture {
    MillFixture() : cell(demoCell()) {}
    core::Station& select(const std::string& source) {
        core::ProgramPtr program = cell.addProgram(0, 1, "test.nc", source);
        EXPECT_FALSE(program->diagnostics.hasErrors()) << diagnosticsText(program->diagnostics);
        core::Station& station = cell.station(0);
        EXPECT_TRUE(station.selectProgram(1));
        return station;
    }
    core::Station& mill() { return cell.station(0); }
    void runToEnd(double tick = 1e9) {
        for (int i = 0; i < 10'000'000 && mill().busy(); ++i)
            mill().advance(tick);
    }
    /// Path acceleration of a move along X (mm/s^2).
    double ax() { return mill().config().axes[0].maxAcceleration; }
    core::Cell cell;
};

/// From rest to rest over `length` mm at `v` mm/s with acceleration `a`
/// (trapezoid: the ramps cost v/a beyond length/v).
double trapezoid(double length, double v, double a) {
    return length / v + v / a;
}

TEST(StationMotion, OverridesAreClampedToTheirRanges) {
    MillFixture f;
    core::Station& mill = f.mill();
    EXPECT_EQ(mill.feedOverride(), 100);
    EXPECT_EQ(mill.rapidOverride(), 100);
    EXPECT_EQ(mill.feedOverrideMax(), 150) << "B074 default";
    mill.setFeedOverride(500);
    EXPECT_EQ(mill.feedOverride(), 150);
    mill.setFeedOverride(-3);
    EXPECT_EQ(mill.feedOverride(), 0);
    mill.setRapidOverride(120);
    EXPECT_EQ(mill.rapidOverride(), 100) << "rapid override never above 100 %";
    mill.setRapidOverride(25);
    EXPECT_EQ(mill.rapidOverride(), 25);
    EXPECT_EQ(mill.machine().rapidOverride(), 25.0) << "forwarded to the machine";
}

TEST(StationMotion, FeedOverrideOfFiftyPercentDoublesTheTimeOfAFeedMove) {
    MillFixture f;
    core::Station& mill = f.select("N0001 G1 G90 X50 F600\nN0002 M30\n");
    mill.setFeedOverride(50);
    ASSERT_TRUE(mill.press(ControlKey::Start));
    mill.advance(2.0);
    EXPECT_NEAR(mill.machine().actualFeed(), 300.0, 1e-9);
    EXPECT_NEAR(mill.machine().position(0), 5.0 * 2.0 - 25.0 / (2 * f.ax()), 1e-9);
    f.runToEnd();
    const double slow = mill.machine().seconds();
    EXPECT_NEAR(slow, trapezoid(50, 5, f.ax()), 1e-9);
    // The cruise part takes twice as long as at 100 %.
    EXPECT_NEAR(slow - 5 / f.ax(), 2 * (trapezoid(50, 10, f.ax()) - 10 / f.ax()), 1e-9);
    EXPECT_EQ(mill.machine().position(0), 50.0);
}

TEST(StationMotion, AnOverrideChangeActsMidBlock) {
    MillFixture f;
    core::Station& mill = f.select("N0001 G1 G90 X50 F600\nN0002 M30\n");
    ASSERT_TRUE(mill.press(ControlKey::Start));
    mill.advance(1.0);
    const double x = mill.machine().position(0);
    mill.setFeedOverride(150);
    mill.advance(1.0);
    EXPECT_NEAR(mill.machine().actualFeed(), 900.0, 1e-9);
    // 5 mm/s more after a ramp of 5/a seconds.
    const double ramp = 5.0 / f.ax();
    EXPECT_NEAR(mill.machine().position(0),
                x + 10 * ramp + 0.5 * f.ax() * ramp * ramp + 15 * (1.0 - ramp), 1e-9);
    mill.setFeedOverride(0);
    mill.advance(1.0);
    EXPECT_EQ(mill.machine().actualFeed(), 0.0) << "0 %: the axes stand, the program stays active";
    EXPECT_TRUE(mill.control().programActive());
    const double busy = mill.machine().seconds();
    mill.advance(5.0);
    EXPECT_EQ(mill.machine().seconds(), busy) << "standing at 0 % is no busy time";
    mill.setFeedOverride(100);
    f.runToEnd();
    EXPECT_EQ(mill.machine().position(0), 50.0);
}

TEST(StationMotion, RapidOverrideSlowsG0Only) {
    MillFixture f;
    core::Station& mill = f.select("N0001 G0 G90 X100\nN0002 M30\n");
    mill.setRapidOverride(50);
    mill.setFeedOverride(10);  // no effect on G0
    ASSERT_TRUE(mill.press(ControlKey::Start));
    f.runToEnd();
    const double v = mill.config().axes[0].maxVelocity / 60.0 * 0.5;  // mm/s
    EXPECT_NEAR(mill.machine().seconds(), trapezoid(100, v, f.ax()), 1e-9);
}

TEST(StationMotion, ADwellTakesItsTime) {
    MillFixture f;
    core::Station& mill = f.select("N0001 G4 F1.5\nN0002 M30\n");
    ASSERT_TRUE(mill.press(ControlKey::Start));
    mill.advance(1.0);
    EXPECT_TRUE(mill.control().programActive());
    EXPECT_EQ(mill.control().currentBlock(), "N0001");
    EXPECT_NEAR(mill.machine().seconds(), 1.0, 1e-9);
    mill.advance(1.0);
    EXPECT_FALSE(mill.control().programActive());
    EXPECT_NEAR(mill.machine().seconds(), 1.5, 1e-9);
}

std::vector<int> auxValues(const core::Station& station) {
    std::vector<int> values;
    for (const core::AuxOutput& aux : station.machine().recentAux())
        values.push_back(static_cast<int>(aux.value));
    return values;
}

TEST(StationMotion, AuxiliaryFunctionsHappenWhenTheMachineReachesThem) {
    MillFixture f;
    core::Station& mill =
        f.select("N0001 G1 G90 X10 F600\nN0002 M10\nN0003 X20\nN0004 M11\nN0005 M30\n");
    ASSERT_TRUE(mill.press(ControlKey::Start));
    mill.advance(0.5);
    EXPECT_GE(mill.runBlocks(), 4u) << "interpreted ahead (look-ahead)";
    EXPECT_TRUE(auxValues(mill).empty()) << "M10 comes after the move of N0001";
    mill.advance(1.0);  // N0001 ended (1 s + ramp), N0003 under way
    EXPECT_EQ(auxValues(mill), std::vector<int>{10});
    EXPECT_EQ(mill.control().currentBlock(), "N0003");
    f.runToEnd();
    EXPECT_EQ(auxValues(mill), (std::vector<int>{10, 11, 30}));
    // M10 stops the path: two moves from rest to rest.
    EXPECT_NEAR(mill.machine().seconds(), 2 * trapezoid(10, 10, f.ax()), 1e-9);
}

TEST(StationMotion, M3WaitsForTheSpindleToRunUp) {
    MillFixture f;
    core::Station& mill = f.select("N0001 S1=2000 M3\nN0002 G1 G90 X10 F600\nN0003 M30\n");
    double runUp = 0.0;
    for (const core::AxisConfig& axis : mill.config().axes)
        if (axis.kind == core::AxisKind::Spindle && axis.spindleIndex == 1)
            runUp = 2000.0 / (axis.maxAcceleration / 6.0);
    ASSERT_GT(runUp, 0.0);
    ASSERT_TRUE(mill.press(ControlKey::Start));
    mill.advance(runUp / 2);
    EXPECT_NEAR(mill.machine().spindles().actualSpeed(1), 1000.0, 1e-6);
    EXPECT_EQ(mill.machine().position(0), 0.0) << "the move waits for the spindle";
    f.runToEnd();
    EXPECT_NEAR(mill.machine().seconds(), runUp + trapezoid(10, 10, f.ax()), 1e-9);
    EXPECT_EQ(mill.machine().spindles().actualSpeed(1), 2000.0);
}

/// What a run leaves behind, to compare runs cut differently into ticks.
struct Outcome {
    double seconds = 0.0;
    std::vector<double> positions;
    std::vector<int> aux;
    double machiningTorque = 0.0;  ///< page 30 element 007
    std::map<int, double> page30;  ///< elements 008, 011, 012
    std::vector<int> signals;      ///< EXCTH, THMIS
    std::size_t trendSamples = 0;
};

Outcome runIn(double tick, const std::string& source, int feedOverride, bool keepTrend = true) {
    MillFixture f;
    core::Station& mill = f.select(source);
    mill.keepAfcTrend(keepTrend);
    mill.setFeedOverride(feedOverride);
    EXPECT_TRUE(mill.press(ControlKey::Start));
    f.runToEnd(tick);
    EXPECT_TRUE(mill.control().alarm().empty()) << mill.control().alarm();
    Outcome out;
    out.seconds = mill.machine().seconds();
    for (int axis = 0; axis < 3; ++axis)
        out.positions.push_back(mill.machine().position(axis));
    out.aux = auxValues(mill);
    f.cell.machineData().read({30, 0, 0, 7}, out.machiningTorque);
    for (int element : {8, 11, 12})
        f.cell.machineData().read({30, 0, 0, element}, out.page30[element]);
    out.signals = {mill.control().signalTable().get("P00SEXCTH"),
                   mill.control().signalTable().get("P00STHMIS")};
    out.trendSamples = mill.afcTrend().size();
    return out;
}

void expectSame(const Outcome& a, const Outcome& b) {
    EXPECT_NEAR(a.seconds, b.seconds, 1e-9);
    ASSERT_EQ(a.positions.size(), b.positions.size());
    for (std::size_t i = 0; i < a.positions.size(); ++i)
        EXPECT_NEAR(a.positions[i], b.positions[i], 1e-9) << "axis " << i;
    EXPECT_EQ(a.aux, b.aux);
    EXPECT_NEAR(a.machiningTorque, b.machiningTorque, 1e-9);
    EXPECT_EQ(a.page30, b.page30);
    EXPECT_EQ(a.signals, b.signals);
}

TEST(StationMotion, TicksDoNotChangeTheResultWithOverridesSpindlesAndAdaptiveFeed) {
    const std::string source =
        "N0001 S1=3000 M3\nN0002 G0 G90 X10 Y10 Z2\nN0003 G1 Z-1 F600 M108\n"
        "N0004 G2 X30 Y10 I20 J10 F1200\nN0005 G1 G26 X60 F1500\nN0006 G25\n"
        "N0007 G4 F0.5\nN0008 G1 X0 Y0 M109\nN0009 M30\n";
    for (int percent : {100, 70}) {
        const Outcome panel = runIn(0.02, source, percent);
        const Outcome cli = runIn(1e9, source, percent);
        EXPECT_GT(panel.seconds, 5.0);
        EXPECT_GT(panel.trendSamples, 0u);
        expectSame(panel, cli);
        EXPECT_EQ(panel.trendSamples, cli.trendSamples);
        const Outcome odd = runIn(0.0137, source, percent);
        expectSame(odd, cli);
        EXPECT_EQ(odd.trendSamples, cli.trendSamples);
    }
}

// MOT-019: the CLI's stations keep no trend; nothing else may change. The
// plain moves before the G26 block set the clock its torque noise is read at,
// so a trend clock that ran differently without the trend shows here.
TEST(StationMotion, AStationWithoutTrendGivesTheSameRunAsOneWithIt) {
    // Inside the demo mill's stock (X -150..-50, Y -80..-20, Z -132..-120).
    const std::string source =
        "N0001 S1=3000 M3\nN0002 G0 G90 X-145 Y-50 Z-110\nN0003 G1 Z-125 F600\n"
        "N0004 G2 X-125 Y-50 I-135 J-50 F1200\nN0005 G1 X-120 F900\n"
        "N0006 G1 G26 X-60 F1500\nN0007 G25\nN0008 G1 X-145 Y-30 F2000\nN0009 M30\n";
    for (int percent : {100, 70, 130}) {
        const Outcome withTrend = runIn(0.02, source, percent, true);
        const Outcome without = runIn(0.02, source, percent, false);
        EXPECT_GT(withTrend.trendSamples, 0u);
        EXPECT_EQ(without.trendSamples, 0u);
        EXPECT_GT(withTrend.page30.at(12), 0.0) << "G26 reduced the feed";
        expectSame(withTrend, without);
        expectSame(runIn(1e9, source, percent, false), without);
    }
}

TEST(StationMotion, SingleBlockSwitchedOnDuringARunHoldsAtTheEndOfTheRunningBlock) {
    MillFixture f;
    core::Station& mill = f.select("N0001 G90 G1 X10 F600\nN0002 X20\nN0003 X30\nN0004 M30\n");
    ASSERT_TRUE(mill.press(ControlKey::Start));
    mill.advance(0.5);
    ASSERT_LT(mill.machine().position(0), 10.0);
    ASSERT_TRUE(mill.press(ControlKey::SingleBlock));
    mill.advance(5.0);
    EXPECT_TRUE(mill.atSingleBlockStop());
    EXPECT_TRUE(mill.control().programHeld());
    EXPECT_EQ(mill.machine().position(0), 10.0) << "the look-ahead had queued N0002 already";
    EXPECT_EQ(mill.control().currentBlock(), "N0001");
    ASSERT_TRUE(mill.press(ControlKey::Start));
    mill.advance(5.0);
    EXPECT_TRUE(mill.atSingleBlockStop());
    EXPECT_EQ(mill.machine().position(0), 20.0);
    ASSERT_TRUE(mill.press(ControlKey::SingleBlock));  // off: Start runs to the end
    ASSERT_TRUE(mill.press(ControlKey::Start));
    f.runToEnd();
    EXPECT_EQ(mill.machine().position(0), 30.0);
    EXPECT_FALSE(mill.control().programActive());
}

}  // namespace
}  // namespace mtc::test
