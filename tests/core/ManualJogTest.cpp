// Jogging in manual mode (issue 17 §2, MOT-017): increments and a held jog
// key move the axes through the station's machine in time, the travel
// limits refuse a jog with an alarm, the next program starts where the
// axes were jogged to.
#include <gtest/gtest.h>

#include <string>

#include "InterpTestSupport.h"
#include "cnc_core/cell/Cell.h"

namespace mtc::test {
namespace {

using core::ControlKey;

// Demo mill X: -400 ... 400 mm, max_velocity 30000 mm/min, 2500 mm/s^2.
constexpr double kJogFeed = 30000.0 * 0.2 / 60.0;  // mm/s

struct JogFixture {
    JogFixture() : cell(demoCell()) {}
    core::Station& manualMill() {
        core::Station& mill = cell.station(0);
        EXPECT_TRUE(mill.press(ControlKey::Manual));
        return mill;
    }
    void settle(core::Station& station) {
        for (int i = 0; i < 100'000 && station.jogging(); ++i)
            station.advance(0.02);
    }
    core::Cell cell;
};

TEST(ManualJog, OnlyInManualMode) {
    JogFixture f;
    core::Station& mill = f.cell.station(0);
    EXPECT_FALSE(mill.jogBy(0, 1.0));
    EXPECT_NE(mill.control().alarm().find("manual mode"), std::string::npos)
        << mill.control().alarm();
    EXPECT_FALSE(mill.jogging());
}

TEST(ManualJog, AnIncrementMovesInTimeAndEndsExactly) {
    JogFixture f;
    core::Station& mill = f.manualMill();
    ASSERT_TRUE(mill.jogBy(0, 10.0));
    mill.advance(0.05);
    EXPECT_GT(mill.machine().position(0), 0.0);
    EXPECT_LT(mill.machine().position(0), 10.0) << "the axis moves in time, no jump";
    ASSERT_TRUE(mill.jogBy(0, 0.001)) << "a second press adds to where the first one goes";
    f.settle(mill);
    EXPECT_NEAR(mill.machine().position(0), 10.001, 1e-12);
    EXPECT_NEAR(mill.interpreter().programmedPosition(0), 10.001, 1e-12)
        << "the interpreter takes the jogged position";
    ASSERT_TRUE(mill.jogBy(0, -10.001, true));  // rapid key
    f.settle(mill);
    EXPECT_NEAR(mill.machine().position(0), 0.0, 1e-12);
}

TEST(ManualJog, AHeldKeyMovesUntilReleasedAndBrakes) {
    JogFixture f;
    core::Station& mill = f.manualMill();
    ASSERT_TRUE(mill.jogStart(1, +1));
    mill.advance(1.0);
    const double accel = kJogFeed / 2500.0;  // seconds to reach the jog feed
    EXPECT_NEAR(mill.machine().position(1), kJogFeed * (1.0 - accel / 2), 1e-6);
    mill.jogRelease();
    f.settle(mill);
    const double braked = kJogFeed * (1.0 - accel / 2) + kJogFeed * kJogFeed / (2 * 2500.0);
    EXPECT_NEAR(mill.machine().position(1), braked, 1e-6) << "braked on the path";
    EXPECT_EQ(mill.machine().actualFeed(), 0.0);
    EXPECT_TRUE(mill.machine().idle());
    EXPECT_NEAR(mill.interpreter().programmedPosition(1), braked, 1e-9);
}

TEST(ManualJog, TravelLimitsRefuseAnIncrementAndStopAHeldKey) {
    JogFixture f;
    core::Station& mill = f.manualMill();
    EXPECT_FALSE(mill.jogBy(0, 400.5));
    EXPECT_NE(mill.control().alarm().find("Travel limit"), std::string::npos)
        << mill.control().alarm();
    EXPECT_FALSE(mill.jogging());
    EXPECT_EQ(mill.machine().position(0), 0.0);
    ASSERT_TRUE(mill.jogStart(0, -1, true));
    f.settle(mill);
    EXPECT_EQ(mill.machine().position(0), -400.0) << "a held key stops at the limit";
    EXPECT_FALSE(mill.jogStart(0, -1));
    EXPECT_NE(mill.control().alarm().find("travel limit"), std::string::npos);
}

TEST(ManualJog, TheNextProgramStartsWhereTheAxesWereJogged) {
    JogFixture f;
    core::Station& mill = f.manualMill();
    ASSERT_TRUE(mill.jogBy(0, 25.0));
    f.settle(mill);
    f.cell.addProgram(0, 7, "after-jog.nc", "N0001 G91 G1 X5 F3000\nN0002 M30\n");
    ASSERT_TRUE(mill.press(ControlKey::Automatic));
    ASSERT_TRUE(mill.selectProgram(7));
    ASSERT_TRUE(mill.press(ControlKey::Start));
    for (int i = 0; i < 10'000 && mill.busy(); ++i)
        mill.advance(0.02);
    EXPECT_NEAR(mill.machine().position(0), 30.0, 1e-9);
}

TEST(ManualJog, TheSpindleKeysStartChangeAndStopTheSpindle) {
    JogFixture f;
    core::Station& mill = f.cell.station(0);
    EXPECT_FALSE(mill.manualSpindle(1, 1, 800.0)) << "automatic mode";
    ASSERT_TRUE(mill.press(ControlKey::Manual));
    EXPECT_FALSE(mill.manualSpindle(3, 1, 800.0)) << "the mill has S1 only";
    ASSERT_TRUE(mill.manualSpindle(1, 1, 800.0));
    for (int i = 0; i < 500; ++i)
        mill.advance(0.02);
    const auto& spindles = mill.machine().spindles();
    EXPECT_DOUBLE_EQ(spindles.actualSpeed(1), 800.0);
    ASSERT_TRUE(mill.manualSpindle(1, -1, 900.0));
    for (int i = 0; i < 1000; ++i)
        mill.advance(0.02);
    EXPECT_DOUBLE_EQ(spindles.actualSpeed(1), -900.0) << "counter-clockwise";
    ASSERT_TRUE(mill.manualSpindle(1, 0));
    for (int i = 0; i < 1000; ++i)
        mill.advance(0.02);
    EXPECT_DOUBLE_EQ(spindles.actualSpeed(1), 0.0);
    EXPECT_DOUBLE_EQ(spindles.commandedSpeed(1), 900.0) << "M5 keeps the speed";
}

TEST(ManualJog, RefusedWhileAProgramRuns) {
    JogFixture f;
    f.cell.addProgram(0, 8, "long.nc", "N0001 G90 G1 X100 F600\nN0002 M30\n");
    core::Station& mill = f.cell.station(0);
    ASSERT_TRUE(mill.selectProgram(8));
    ASSERT_TRUE(mill.press(ControlKey::Start));
    mill.advance(0.5);
    EXPECT_FALSE(mill.jogBy(1, 1.0));
}

}  // namespace
}  // namespace mtc::test
