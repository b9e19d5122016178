// The one arc rule (docs/DECISIONS.md D-016, issue 16 §1): when a G2/G3 is a
// full circle and how far an arc turns, the same in the interpreter, the
// machine's motion, the tool path view and tool compensation.
#include <gtest/gtest.h>

#include <cmath>

#include "InterpTestSupport.h"
#include "MotionTestSupport.h"
#include "cnc_core/compensation/PlanePath.h"
#include "cnc_core/geometry/ArcSweep.h"
#include "cnc_core/interp/MotionPath.h"
#include "cnc_core/motion/SegmentGeometry.h"

using namespace mtc::core;
using namespace mtc::test;

namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(ArcSweep, AnEndWithinTheRadiusToleranceOfTheStartClosesTheCircle) {
    EXPECT_DOUBLE_EQ(kFullCircleChord, 0.002) << "the interpreter's radius tolerance (I-009)";
    EXPECT_TRUE(closesCircle(10, 0, 10, 0));
    EXPECT_TRUE(closesCircle(10, 0, 10.0012, 0.0015)) << "0.0019 mm apart: closed";
    EXPECT_FALSE(closesCircle(10, 0, 10, 0.00201)) << "just over 0.002 mm: an arc";
    EXPECT_TRUE(closesCircle(10, 0, 10, 0.003, 0.005)) << "the tolerance can be given";
}

TEST(ArcSweep, SignFollowsTheSenseAndTheMagnitudeLiesInZeroToTwoPi) {
    EXPECT_NEAR(arcSweep(1, 0, 0, 1, 0, 0, false, false), kPi / 2, 1e-12);  // G3 quarter
    EXPECT_NEAR(arcSweep(1, 0, 0, 1, 0, 0, true, false), -1.5 * kPi, 1e-12);
    EXPECT_NEAR(arcSweep(1, 0, -1, 0, 0, 0, true, false), -kPi, 1e-12);
    EXPECT_NEAR(arcSweep(5, 5, 5, 5, 0, 0, false, false), 2 * kPi, 1e-12) << "same point";
    EXPECT_NEAR(arcSweep(1, 0, 1, 0, 0, 0, true, false), -2 * kPi, 1e-12);
}

TEST(ArcSweep, NearFullCircles) {
    const double r = 10, a = 1e-4;  // end 0.001 mm from the start along the circle
    const double e1 = r * std::cos(a), ahead = r * std::sin(a);
    // Programmed (the flag from closesCircle): one whole turn, either side.
    ASSERT_TRUE(closesCircle(r, 0, e1, ahead));
    EXPECT_NEAR(arcSweep(r, 0, e1, ahead, 0, 0, false, true), 2 * kPi, 1e-15);
    EXPECT_NEAR(arcSweep(r, 0, e1, -ahead, 0, 0, false, true), 2 * kPi, 1e-15);
    EXPECT_NEAR(arcSweep(r, 0, e1, ahead, 0, 0, true, true), -2 * kPi, 1e-15);
    // Not flagged (a corner element tool compensation inserts): what it is.
    EXPECT_NEAR(arcSweep(r, 0, e1, ahead, 0, 0, false, false), a, 1e-12);
    EXPECT_NEAR(arcSweep(r, 0, e1, -ahead, 0, 0, false, false), 2 * kPi - a, 1e-12);
    // Directions within kSameDirection are the same: a whole turn.
    EXPECT_NEAR(arcSweep(r, 0, r, 1e-12, 0, 0, false, false), 2 * kPi, 1e-12);
    EXPECT_NEAR(arcSweep(r, 0, r, 1e-9, 0, 0, false, false), 1e-10, 1e-14);
}

TEST(ArcSweep, TheInterpreterFlagsTheProgrammedFullCircleAndEveryLayerTurnsOnce) {
    const ProcessConfig& config = *demoCell().process(0);  // the mill, G17
    ProgramStore store;
    RecordingSink sink;
    Interpreter interpreter(config, store, sink);
    store.put(config.index, 1,
              parse("N0001 G0 X10 Y0\n"
                    "N0002 G3 X10.001 Y0.0015 I0 J0 F1000\n"  // 0.0018 mm off the start
                    "N0003 G3 X10 Y0.004 I0 J0\n"             // 0.0027 mm on: a short arc
                    "N0004 M30\n",
                    1));
    ASSERT_TRUE(interpreter.select(1));
    const RunResult run = interpreter.run();
    ASSERT_EQ(run.status, RunStatus::Ended) << diagnosticsText(run.diagnostics);
    ASSERT_EQ(sink.motions.size(), 3u);
    const Motion& full = sink.motions[1];
    const Motion& shortArc = sink.motions[2];
    EXPECT_TRUE(full.fullCircle);
    EXPECT_FALSE(shortArc.fullCircle);
    const auto limits = motion::MotionLimits::fromConfig(config);
    const double turn = 2 * kPi * 10;
    EXPECT_NEAR(motionPathLength(full), turn, 1e-6);
    EXPECT_NEAR(motion::SegmentGeometry::of(full, limits).length(), turn, 0.01);
    EXPECT_LT(motionPathLength(shortArc), 0.003);
    EXPECT_LT(motion::SegmentGeometry::of(shortArc, limits).length(), 0.003);
}

TEST(ArcSweep, AnInsertedCornerArcShorterThanTheToleranceIsNoFullCircle) {
    // Tool compensation's corner arc at a nearly tangent outside corner:
    // 0.0005 mm long. The machine and the view once made it a whole turn.
    Motion corner = arc({5, 0, 0}, {5 * std::cos(1e-4), 5 * std::sin(1e-4), 0}, 0, 0, false, 1000);
    corner.inserted = true;
    const auto limits = threeAxes();
    EXPECT_NEAR(motionPathLength(corner), 5e-4, 1e-9);
    EXPECT_NEAR(motion::SegmentGeometry::of(corner, limits).length(), 5e-4, 1e-9);
    comp::PlanePath path;
    path.kind = comp::PathKind::ArcCcw;
    path.start = comp::Vec2(5, 0);
    path.end = comp::Vec2(5 * std::cos(1e-4), 5 * std::sin(1e-4));
    EXPECT_NEAR(path.sweep(), 1e-4, 1e-12);
    path.fullCircle = true;  // the programmed full circle keeps its turn
    EXPECT_NEAR(path.sweep(), 2 * kPi, 1e-12);
}

}  // namespace
