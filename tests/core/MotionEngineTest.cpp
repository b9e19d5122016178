// Trajectory engine (issue 16 §2): positions in time along a line and an arc
// against the closed-form acceleration-limited profile, per-axis limits of
// G0 and of the path feed (issue 22 §6), corners, dwell.
#include <gtest/gtest.h>

#include <vector>

#include "MotionTestSupport.h"
#include "cnc_core/motion/SegmentProfile.h"

namespace {

using namespace mtc::core;
using namespace mtc::core::motion;
using namespace mtc::test;

constexpr double kExact = 1e-6;

TEST(SegmentProfile, TrapezoidAndTriangleMatchTheClosedForm) {
    for (double length : {100.0, 3.0, 0.5}) {
        SegmentProfile p;
        p.plan(0.0, 0.0, length, 100.0, 0.0, 2500.0);
        EXPECT_NEAR(p.duration(), closedFormDuration(length, 100.0, 2500.0), 1e-12) << length;
        for (int step = 0; step * 0.0007 <= p.duration() + 0.01; ++step) {
            const double t = step * 0.0007;
            double s = 0, v = 0;
            p.sample(t, s, v);
            EXPECT_NEAR(s, closedFormDistance(length, 100.0, 2500.0, t), 1e-9)
                << length << " " << t;
        }
    }
}

TEST(SegmentProfile, FromAboveTheCapItBrakesFirstAndCanCarryExcessVelocity) {
    SegmentProfile p;
    p.plan(0.0, 200.0, 100.0, 50.0, 0.0, 1000.0);  // override cut from 200 to 50 mm/s
    double s = 0, v = 0;
    p.sample(0.15, s, v);
    EXPECT_NEAR(v, 50.0, 1e-9);
    EXPECT_TRUE(p.reachesEnd());
    EXPECT_NEAR(p.endVelocity(), 0.0, 1e-12);
    SegmentProfile shortOne;
    shortOne.plan(0.0, 200.0, 5.0, 50.0, 0.0, 1000.0);  // cannot brake in 5 mm
    EXPECT_TRUE(shortOne.reachesEnd());
    EXPECT_NEAR(shortOne.endVelocity(), std::sqrt(200.0 * 200.0 - 2 * 1000.0 * 5.0), 1e-9);
}

TEST(SegmentProfile, CapZeroComesToRestInsideTheSegment) {
    SegmentProfile p;
    p.plan(10.0, 100.0, 100.0, 0.0, 0.0, 1000.0);
    EXPECT_FALSE(p.reachesEnd());
    EXPECT_NEAR(p.endPosition(), 15.0, 1e-12);  // 10 + 100^2 / 2000
    double s = 0, v = 0;
    p.sample(1000.0, s, v);
    EXPECT_NEAR(s, 15.0, 1e-12);
    EXPECT_EQ(v, 0.0);
}

TEST(TrajectoryEngine, LinePositionsFollowTheTrapezoidTo1e6) {
    TrajectoryEngine engine(threeAxes());
    // X and Y together: the path acceleration is limited by both axes (2500 / 0.6, 2500 / 0.8).
    engine.pushMove(line({0, 0, 0}, {60, 80, 0}, 6000), {});
    const double v = 100.0, a = 2500.0 / 0.8, length = 100.0;
    const double total = closedFormDuration(length, v, a);
    double t = 0.0;
    while (!engine.idle()) {
        drive(engine, 0.0137);
        t += 0.0137;
        const double s = closedFormDistance(length, v, a, t);
        EXPECT_NEAR(engine.position(0), 0.6 * s, kExact) << t;
        EXPECT_NEAR(engine.position(1), 0.8 * s, kExact) << t;
        if (t < total) {
            EXPECT_NEAR(engine.distanceToGo(0), 60.0 - 0.6 * s, kExact);
        }
    }
    EXPECT_NEAR(runToIdle(engine), t, 1e-9);
    EXPECT_EQ(engine.position(0), 60.0);
    EXPECT_EQ(engine.position(1), 80.0);
}

TEST(TrajectoryEngine, ArcPositionsFollowTheTrapezoidAlongTheCircleTo1e6) {
    TrajectoryEngine engine(threeAxes());
    // Half circle of radius 50 clockwise around (0, 0) from (-50, 0) over (0, 50) to (50, 0).
    engine.pushMove(arc({-50, 0, 0}, {50, 0, 0}, 0, 0, true, 3000), {});
    const double radius = 50.0, length = radius * M_PI, v = 50.0;
    const double a = 0.5 * 2500.0;  // half of the weaker axis for the tangential part
    const double total = closedFormDuration(length, v, a);
    for (int step = 1; step * 0.05 < total + 0.1; ++step) {
        const double t = step * 0.05;
        drive(engine, 0.05);
        const double s = closedFormDistance(length, v, a, std::min(t, total));
        const double angle = M_PI - s / radius;
        EXPECT_NEAR(engine.position(0), radius * std::cos(angle), kExact) << t;
        EXPECT_NEAR(engine.position(1), radius * std::sin(angle), kExact) << t;
        if (t > 0.1 && t < total - 0.1) {
            EXPECT_NEAR(engine.velocity() * 60.0, 3000.0, 1e-9);
        }
    }
    EXPECT_TRUE(engine.idle());
    EXPECT_EQ(engine.position(0), 50.0);
}

TEST(TrajectoryEngine, HelixMovesTheThirdAxisInStep) {
    TrajectoryEngine engine(threeAxes());
    Motion m = arc({50, 0, 0}, {50, 0, -10}, 0, 0, false, 6000);  // full turn, 10 mm down
    engine.pushMove(m, {});
    drive(engine, 0.5);
    const double arcLen = 2 * M_PI * 50.0, length = std::hypot(arcLen, 10.0);
    const QueueItem* move = engine.currentMove();
    ASSERT_NE(move, nullptr);
    EXPECT_NEAR(move->geometry.length(), length, 1e-9);
    const double s = engine.pathPosition();
    EXPECT_NEAR(engine.position(2), -10.0 * s / length, kExact);
    const double angle = 2 * M_PI * s / length;
    EXPECT_NEAR(engine.position(0), 50.0 * std::cos(angle), kExact);
    EXPECT_NEAR(engine.position(1), 50.0 * std::sin(angle), kExact);
}

TEST(TrajectoryEngine, RapidUsesEveryAxisLimitAndTheSlowestAxisSetsTheDuration) {
    // Z is the weak axis: 6000 mm/min, 500 mm/s^2.
    TrajectoryEngine engine(threeAxes(30000, 30000, 6000, 2500, 2500, 500));
    engine.pushMove(line({0, 0, 0}, {100, 0, -100}, 0, true), {});
    const double length = std::sqrt(2.0) * 100.0, share = 1.0 / std::sqrt(2.0);
    const double v = 100.0 / share, a = 500.0 / share;  // Z at 100 mm/s, 500 mm/s^2
    const double total = closedFormDuration(length, v, a);
    drive(engine, total / 2);
    EXPECT_NEAR(engine.velocity() * share, 100.0, 1e-9) << "Z moves at its max_velocity";
    EXPECT_NEAR(engine.position(0), -engine.position(2), kExact) << "a straight line";
    EXPECT_NEAR(runToIdle(engine), total, 1e-9);
    // Cruise duration = travel of the slowest axis / its max velocity (+ one ramp).
    EXPECT_NEAR(total, 100.0 / 100.0 + 100.0 / 500.0, 1e-12);
}

TEST(TrajectoryEngine, RapidOverrideScalesTheRapidOnly) {
    TrajectoryEngine engine(threeAxes());
    engine.setRapidOverride(25);
    engine.setFeedOverride(150);
    engine.pushMove(line({0, 0, 0}, {300, 0, 0}, 0, true), {});
    drive(engine, 0.5);
    EXPECT_NEAR(engine.velocity() * 60.0, 30000 * 0.25, 1e-9);
}

TEST(TrajectoryEngine, FeedIsLimitedByTheAxesMaxVelocity) {
    // Issue 22 §6: F60000 on a 30000 mm/min axis must not halve the time.
    TrajectoryEngine engine(threeAxes());
    engine.pushMove(line({0, 0, 0}, {500, 0, 0}, 60000), {});
    drive(engine, 0.5);
    EXPECT_NEAR(engine.velocity() * 60.0, 30000.0, 1e-9);
    EXPECT_NEAR(runToIdle(engine), closedFormDuration(500.0, 500.0, 2500.0), 1e-9);
    // Above 100 % override the axes' maximum still holds.
    TrajectoryEngine fast(threeAxes());
    fast.setFeedOverride(150);
    fast.pushMove(line({0, 0, 0}, {500, 0, 0}, 25000), {});
    drive(fast, 0.5);
    EXPECT_NEAR(fast.velocity() * 60.0, 30000.0, 1e-9);
}

TEST(TrajectoryEngine, ArcVelocityRespectsCentripetalAcceleration) {
    TrajectoryEngine engine(threeAxes());
    engine.pushMove(arc({2, 0, 0}, {2, 0, 0}, 0, 0, false, 30000), {});  // full circle r = 2
    drive(engine, 0.2);
    // v^2 / r <= a / 2: sqrt(0.5 * 2500 * 2) = 50 mm/s.
    EXPECT_NEAR(engine.velocity(), 50.0, 1e-9);
}

TEST(TrajectoryEngine, NonTangentialCornerStopsUnderG8AndTangentialDoesNot) {
    const double a = 2500.0, v = 100.0;
    TrajectoryEngine corner(threeAxes());
    corner.pushMove(line({0, 0, 0}, {50, 0, 0}, 6000), {});
    corner.pushMove(line({50, 0, 0}, {50, 50, 0}, 6000), {});
    EXPECT_NEAR(runToIdle(corner), 2 * closedFormDuration(50.0, v, a), 1e-9);

    TrajectoryEngine straight(threeAxes());
    straight.pushMove(line({0, 0, 0}, {50, 0, 0}, 6000), {});
    straight.pushMove(line({50, 0, 0}, {100, 0, 0}, 6000), {});
    EXPECT_NEAR(runToIdle(straight), closedFormDuration(100.0, v, a), 1e-9);
}

TEST(TrajectoryEngine, G9EndsEveryBlockAtAVelocityTheAxesCanStopFrom) {
    MotionLimits limits = threeAxes();
    TrajectoryEngine engine(limits);
    BlockTransition g9;
    g9.exactStop = true;
    engine.pushMove(line({0, 0, 0}, {50, 0, 0}, 6000), g9);
    engine.pushMove(line({50, 0, 0}, {100, 0, 0}, 6000), g9);
    while (engine.queuedCount() == 2)
        engine.advance(1.0);
    // Velocity step of X: 2 * 2500 mm/s^2 * VFBT 1 * 2 ms = 10 mm/s.
    EXPECT_NEAR(engine.velocity(), limits.axes[0].velocityStep, 1e-9);
    EXPECT_NEAR(limits.axes[0].velocityStep, 10.0, 1e-12);
}

TEST(TrajectoryEngine, G7WithG9CrossesACornerSlowlyButNotAtRest) {
    TrajectoryEngine engine(threeAxes());
    BlockTransition blend;
    blend.exactStop = true;
    blend.blendCorners = true;
    engine.pushMove(line({0, 0, 0}, {50, 0, 0}, 6000), blend);
    engine.pushMove(line({50, 0, 0}, {50, 50, 0}, 6000), blend);
    while (engine.queuedCount() == 2)
        engine.advance(1.0);
    // 90 degrees: the X tangent drops by 1, Y rises by 1: v <= 10 mm/s.
    EXPECT_NEAR(engine.velocity(), 10.0, 1e-9);
}

TEST(TrajectoryEngine, DwellTakesItsTimeAtRest) {
    TrajectoryEngine engine(threeAxes());
    engine.pushMove(line({0, 0, 0}, {10, 0, 0}, 6000), {});
    engine.pushDwell({}, 2.5);
    engine.pushMove(line({10, 0, 0}, {20, 0, 0}, 6000), {});
    const double one = closedFormDuration(10.0, 100.0, 2500.0);
    drive(engine, one + 1.0);
    EXPECT_EQ(engine.position(0), 10.0);
    EXPECT_EQ(engine.velocity(), 0.0);
    EXPECT_NEAR(runToIdle(engine), 2 * one + 2.5, 1e-9);
}

TEST(TrajectoryEngine, ActionsStopThePathAndAreReportedWhenReached) {
    TrajectoryEngine engine(threeAxes());
    engine.pushMove(line({0, 0, 0}, {10, 0, 0}, 6000), {});
    MachineAction action;
    action.tag = 7;
    engine.pushAction({}, action);
    engine.pushMove(line({10, 0, 0}, {20, 0, 0}, 6000), {});
    drive(engine, 0.05);
    EXPECT_TRUE(engine.takeReached().empty());
    const double one = closedFormDuration(10.0, 100.0, 2500.0);
    EXPECT_NEAR(runToIdle(engine), 2 * one, 1e-9);
    EXPECT_EQ(engine.takeReached(), std::vector<std::uint32_t>{7});
}

TEST(TrajectoryEngine, ZeroLengthMovesTakeNoTime) {
    TrajectoryEngine engine(threeAxes());
    engine.pushMove(line({5, 5, 5}, {5, 5, 5}, 6000), {});
    EXPECT_TRUE(engine.idle());
}

}  // namespace

namespace {

void expectSameGeometry(const SegmentGeometry& a, const SegmentGeometry& b) {
    EXPECT_EQ(a.arc(), b.arc());
    EXPECT_EQ(a.length(), b.length());
    EXPECT_EQ(a.axisCount(), b.axisCount());
    EXPECT_EQ(a.planeStart(), b.planeStart());
    EXPECT_EQ(a.planeEnd(), b.planeEnd());
    EXPECT_EQ(a.machineEnd(), b.machineEnd());
    EXPECT_EQ(a.startTangent(), b.startTangent());
    EXPECT_EQ(a.endTangent(), b.endTangent());
    EXPECT_EQ(a.radius(), b.radius());
    EXPECT_EQ(a.sweep(), b.sweep());
    EXPECT_EQ(a.planeAxis1(), b.planeAxis1());
    EXPECT_EQ(a.planeAxis2(), b.planeAxis2());
    for (int axis = 0; axis < 3; ++axis)
        EXPECT_EQ(a.maxTangentComponent(axis), b.maxTangentComponent(axis)) << axis;
}

}  // namespace

// The engine works a move's geometry out in its reused queue slot: what an
// earlier move left there (a helix's Z tangent, an arc's radius) must not
// show through.
TEST(SegmentGeometry, DescribedOverAnotherItIsTheSameAsAFreshOne) {
    Motion helix = arc({10, 0, 0}, {0, 10, 5}, 0, 0, false, 3000);
    Motion flat = line({0, 0, 0}, {30, 40, 0}, 3000);
    flat.axisCount = 2;
    SegmentGeometry reused = SegmentGeometry::of(helix, threeAxes());
    reused.describe(flat, threeAxes());
    expectSameGeometry(reused, SegmentGeometry::of(flat, threeAxes()));
    EXPECT_EQ(reused.startTangent()[2], 0.0);
    reused.describe(helix, threeAxes());
    expectSameGeometry(reused, SegmentGeometry::of(helix, threeAxes()));
}

TEST(TrajectoryEngine, APreparedMoveRunsAsOneQueuedAtOnce) {
    const std::vector<Motion> moves = {line({0, 0, 0}, {50, 0, 0}, 6000),
                                       arc({50, 0, 0}, {50, 20, 0}, 50, 10, false, 3000),
                                       line({50, 20, 0}, {0, 20, 0}, 6000)};
    TrajectoryEngine direct(threeAxes()), prepared(threeAxes());
    for (const Motion& m : moves) {
        direct.pushMove(m, {});
        const SegmentGeometry& geometry = prepared.prepareMove(m);
        EXPECT_EQ(geometry.length(), SegmentGeometry::of(m, threeAxes()).length());
        prepared.pushMove(m, {});
    }
    // A preparation that a dwell overtook is not taken: the move's geometry
    // is worked out again in the slot after the dwell.
    const Motion back = line({0, 20, 0}, {0, 0, 0}, 6000);
    prepared.prepareMove(back);
    prepared.pushDwell({}, 0.5);
    direct.pushDwell({}, 0.5);
    prepared.pushMove(back, {});
    direct.pushMove(back, {});
    EXPECT_EQ(runToIdle(prepared), runToIdle(direct));
    for (int axis = 0; axis < 3; ++axis)
        EXPECT_EQ(prepared.position(axis), direct.position(axis));
}
