// Trajectory engine under the operator's hands (issue 16 §2): override
// changes mid-block, feed hold and resume mid-block, Control reset, the
// spindle ramps, and the same result whatever the tick.
#include <gtest/gtest.h>

#include <random>

#include "MotionTestSupport.h"

namespace {

using namespace mtc::core;
using namespace mtc::core::motion;
using namespace mtc::test;

constexpr double kA = 2500.0;  // X acceleration of threeAxes()

TEST(MotionOperator, FeedOverrideChangesMidBlockAtTheAxesAcceleration) {
    TrajectoryEngine engine(threeAxes());
    engine.pushMove(line({0, 0, 0}, {300, 0, 0}, 6000), {});
    drive(engine, 1.0);  // cruising at 100 mm/s since 0.04 s
    const double before = engine.position(0);
    EXPECT_NEAR(before, 100.0 * 1.0 - 100.0 * 0.04 / 2, 1e-9);
    engine.setFeedOverride(50);
    EXPECT_EQ(engine.position(0), before) << "an override change does not move the axes";
    drive(engine, 0.01);
    EXPECT_NEAR(engine.velocity(), 100.0 - kA * 0.01, 1e-9) << "brakes with the axis acceleration";
    drive(engine, 0.5);
    EXPECT_NEAR(engine.velocity(), 50.0, 1e-9);
    engine.setFeedOverride(120);
    drive(engine, 0.5);
    EXPECT_NEAR(engine.velocity(), 120.0, 1e-9);
    // Remaining time in closed form: position after the changes, then brake to 0 at 300.
    const double x = engine.position(0);
    const double rest = (300.0 - x - 120.0 * 120.0 / (2 * kA)) / 120.0 + 120.0 / kA;
    const double now = engine.seconds();
    EXPECT_NEAR(runToIdle(engine), now + rest, 1e-9);
    EXPECT_EQ(engine.position(0), 300.0);
}

TEST(MotionOperator, OverrideZeroStandsAndIsClampedToTheConfiguredMaximum) {
    TrajectoryEngine engine(threeAxes());
    engine.setFeedOverride(500);
    EXPECT_EQ(engine.feedOverride(), 150.0);
    engine.setFeedOverride(-3);
    EXPECT_EQ(engine.feedOverride(), 0.0);
    engine.pushMove(line({0, 0, 0}, {100, 0, 0}, 6000), {});
    drive(engine, 10.0);
    EXPECT_EQ(engine.position(0), 0.0);
    EXPECT_FALSE(engine.idle());
    engine.setFeedOverride(100);
    runToIdle(engine);
    EXPECT_EQ(engine.position(0), 100.0);
}

TEST(MotionOperator, HoldBrakesOnThePathAndResumeContinuesMidBlock) {
    TrajectoryEngine engine(threeAxes());
    engine.pushMove(line({0, 0, 0}, {60, 80, 0}, 6000), {});
    const double a = kA / 0.8;
    drive(engine, 0.5);
    const double s0 = engine.pathPosition();
    engine.hold();
    EXPECT_TRUE(engine.held());
    drive(engine, 5.0);
    const double stopAt = s0 + 100.0 * 100.0 / (2 * a);  // braking distance
    EXPECT_NEAR(engine.pathPosition(), stopAt, 1e-9);
    EXPECT_NEAR(engine.position(0), 0.6 * stopAt, 1e-9) << "stopped on the path";
    EXPECT_NEAR(engine.position(1), 0.8 * stopAt, 1e-9);
    EXPECT_EQ(engine.velocity(), 0.0);
    EXPECT_FALSE(engine.idle());
    const double heldAt = engine.seconds();
    engine.resume();
    const double rest = closedFormDuration(100.0 - stopAt, 100.0, a);
    EXPECT_NEAR(runToIdle(engine), heldAt + rest, 1e-9);
    EXPECT_EQ(engine.position(0), 60.0);
    EXPECT_EQ(engine.position(1), 80.0);
}

TEST(MotionOperator, HoldBrakesAcrossBlocksWhenTheBlockIsTooShort) {
    TrajectoryEngine engine(threeAxes());
    engine.pushMove(line({0, 0, 0}, {100, 0, 0}, 30000), {});
    engine.pushMove(line({100, 0, 0}, {200, 0, 0}, 30000), {});
    // At 500 mm/s the braking distance is 50 mm: hold 10 mm before the block end.
    while (engine.position(0) < 90.0)
        drive(engine, 0.001);
    const double x = engine.position(0), v = engine.velocity();
    engine.hold();
    drive(engine, 2.0);
    EXPECT_NEAR(engine.position(0), x + v * v / (2 * kA), 1e-9);
    EXPECT_EQ(engine.queuedCount(), 1u) << "stopped in the second block";
    EXPECT_EQ(engine.currentLocation().block, "N0001");
}

/// A move of block N000`line` (single block tells blocks apart by their line).
Motion blockMove(double from, double to, double feed, int lineNumber) {
    Motion m = line({from, 0, 0}, {to, 0, 0}, feed);
    m.where.line = lineNumber;
    return m;
}

TEST(MotionOperator, SingleBlockSwitchedOnMidBlockRestsAtTheEndOfThatBlock) {
    TrajectoryEngine engine(threeAxes());
    for (int n = 1; n <= 3; ++n)
        engine.pushMove(blockMove(100.0 * (n - 1), 100.0 * n, 6000, n), {});
    drive(engine, 0.5);
    ASSERT_LT(engine.position(0), 100.0);
    engine.setStopAtBlockEnds(true);
    drive(engine, 5.0);
    EXPECT_EQ(engine.position(0), 100.0) << "at rest exactly at the block's end";
    EXPECT_EQ(engine.velocity(), 0.0);
    EXPECT_TRUE(engine.atBlockStop());
    EXPECT_EQ(engine.queuedCount(), 2u) << "the next blocks wait in the queue";
    const double waited = engine.busySeconds();
    drive(engine, 3.0);
    EXPECT_EQ(engine.busySeconds(), waited) << "waiting for Start is no machine time";
    engine.continueAfterBlockStop();
    drive(engine, 5.0);
    EXPECT_EQ(engine.position(0), 200.0);
    EXPECT_TRUE(engine.atBlockStop());
    engine.setStopAtBlockEnds(false);
    EXPECT_FALSE(engine.atBlockStop()) << "switched off: the run goes on";
    runToIdle(engine);
    EXPECT_EQ(engine.position(0), 300.0);
}

TEST(MotionOperator, SingleBlockTooLateToBrakeRestsAtTheNextBlockEnd) {
    TrajectoryEngine engine(threeAxes());
    for (int n = 1; n <= 3; ++n)
        engine.pushMove(blockMove(100.0 * (n - 1), 100.0 * n, 30000, n), {});
    // At 500 mm/s the braking distance is 50 mm: 10 mm before the end is too late.
    while (engine.position(0) < 90.0)
        drive(engine, 0.001);
    engine.setStopAtBlockEnds(true);
    drive(engine, 5.0);
    EXPECT_EQ(engine.position(0), 200.0);
    EXPECT_EQ(engine.velocity(), 0.0);
    EXPECT_TRUE(engine.atBlockStop());
    EXPECT_EQ(engine.currentLocation().line, 2) << "the block just finished is shown";
    EXPECT_EQ(engine.distanceToGo(0), 0.0);
}

TEST(MotionOperator, ControlResetStopsAtOnceAndEmptiesTheQueue) {
    TrajectoryEngine engine(threeAxes());
    engine.pushMove(line({0, 0, 0}, {100, 0, 0}, 6000, false, "N0005"), {});
    engine.pushMove(line({100, 0, 0}, {100, 50, 0}, 6000, false, "N0006"), {});
    drive(engine, 0.3);
    const double x = engine.position(0);
    engine.hold();
    engine.stop();
    EXPECT_TRUE(engine.idle());
    EXPECT_FALSE(engine.held());
    EXPECT_EQ(engine.velocity(), 0.0);
    EXPECT_EQ(engine.position(0), x);
    EXPECT_EQ(engine.currentLocation().block, "N0005");
    drive(engine, 1.0);
    EXPECT_EQ(engine.position(0), x);
}

TEST(MotionOperator, SpindleRampsToItsSpeedAndTheProgramWaitsForIt) {
    ProcessConfig process;
    AxisConfig x;
    x.name = "X";
    x.definitions = {"X"};
    process.axes.push_back(x);
    AxisConfig s1;
    s1.name = "S1";
    s1.kind = AxisKind::Spindle;
    s1.spindleIndex = 1;
    s1.maxSpeed = 8000;
    s1.maxAcceleration = 6000;  // deg/s^2 = 1000 rpm/s
    process.axes.push_back(s1);
    TrajectoryEngine engine(MotionLimits::fromConfig(process));
    MachineAction speed;
    speed.spindle = 1;
    speed.speed = 20000;  // clamped to max_speed
    speed.stopsPath = false;
    engine.pushAction({}, speed);
    MachineAction m3;
    m3.spindle = 1;
    m3.rotation = static_cast<int>(SpindleSet::Rotation::Clockwise);
    m3.waitForSpindle = true;
    engine.pushAction({}, m3);
    drive(engine, 2.0);
    EXPECT_NEAR(engine.spindles().actualSpeed(1), 2000.0, 1e-9);
    EXPECT_FALSE(engine.idle()) << "waits for the spindle";
    EXPECT_NEAR(runToIdle(engine), 8.0, 1e-9);
    EXPECT_EQ(engine.spindles().actualSpeed(1), 8000.0);
    engine.stop();  // Control reset: the spindle ramps down
    drive(engine, 3.0);
    EXPECT_NEAR(engine.spindles().actualSpeed(1), 5000.0, 1e-9);
}

TEST(MotionOperator, TheResultDoesNotDependOnTheTick) {
    // A zig-zag with tangential and non-tangential transitions, longer than the look-ahead.
    std::vector<Motion> moves;
    double x = 0, y = 0;
    for (int i = 0; i < 200; ++i) {
        const double nx = x + 3.0 + (i % 7), ny = (i % 3 == 0) ? y : y + ((i % 2) ? 1.5 : -1.5);
        moves.push_back(line({x, y, 0}, {nx, ny, 0}, 4000 + 1000 * (i % 5)));
        x = nx;
        y = ny;
    }
    // Positions every 0.1 s and the end time, driven with the given ticks.
    auto run = [&](const std::function<double()>& tick, std::vector<double>& samples) {
        TrajectoryEngine engine(threeAxes(), 8);
        std::size_t next = 0;
        auto refill = [&] {
            while (engine.wantsMore() && next < moves.size())
                engine.pushMove(moves[next++], {});
        };
        double t = 0.0, sampleAt = 0.1;
        while (next < moves.size()) {
            double dt = tick();
            if (t + dt >= sampleAt) {  // cut the tick at the sample instant
                drive(engine, sampleAt - t, refill);
                samples.push_back(engine.position(0));
                samples.push_back(engine.position(1));
                dt -= sampleAt - t;
                t = sampleAt;
                sampleAt += 0.1;
            }
            drive(engine, dt, refill);
            t += dt;
        }
        samples.push_back(runToIdle(engine));
    };
    std::vector<double> even, ragged;
    run([] { return 0.02; }, even);
    std::mt19937 random(5);
    std::uniform_real_distribution<double> cut(0.0001, 0.05);
    run([&] { return cut(random); }, ragged);
    ASSERT_GT(even.size(), 20u);
    const std::size_t n = std::min(even.size(), ragged.size()) - 1;
    for (std::size_t i = 0; i < n; ++i)
        EXPECT_NEAR(even[i], ragged[i], 1e-9) << "sample " << i;
    EXPECT_NEAR(even.back(), ragged.back(), 1e-9) << "end time";
}

}  // namespace
