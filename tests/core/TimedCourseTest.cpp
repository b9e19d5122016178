// The course of a timed move (adaptive feed control under G26, MOT-011):
// knots as shares of time and distance, bounded in number, linear between.
#include <gtest/gtest.h>

#include <cmath>

#include "cnc_core/motion/TimedCourse.h"

namespace {

using mtc::core::motion::TimedCourse;

TEST(TimedCourse, WithoutKnotsTheVelocityIsConstant) {
    TimedCourse course;
    ASSERT_TRUE(course.finish(4.0, 10.0));
    EXPECT_DOUBLE_EQ(course.distanceAt(0.25), 0.25);
    EXPECT_DOUBLE_EQ(course.slopeAt(0.7), 1.0);
}

TEST(TimedCourse, AFastStartAndASlowEndAreFollowed) {
    // 8 mm in the first second, 2 mm in the next three.
    TimedCourse course;
    course.add(1.0, 8.0);
    ASSERT_TRUE(course.finish(4.0, 10.0));
    EXPECT_NEAR(course.distanceAt(0.125), 0.4, 1e-12);  // half of the first second
    EXPECT_NEAR(course.slopeAt(0.1), 0.8 / 0.25, 1e-12);
    EXPECT_NEAR(course.slopeAt(0.9), 0.2 / 0.75, 1e-12);
    EXPECT_DOUBLE_EQ(course.distanceAt(1.0), 1.0);
    EXPECT_DOUBLE_EQ(course.distanceAt(2.0), 1.0);  // clamped beyond the end
}

TEST(TimedCourse, AMillionStepsKeepABoundedEvenOutline) {
    // Accelerating: distance = t^2 over 100 s in 1,000,000 steps.
    TimedCourse course;
    const int steps = 1'000'000;
    for (int i = 1; i < steps; ++i) {
        const double t = 100.0 * i / steps;
        course.add(t, t * t);
    }
    ASSERT_TRUE(course.finish(100.0, 10000.0));
    EXPECT_LE(course.knotCount(), TimedCourse::kMaxKnots);
    EXPECT_GE(course.knotCount(), TimedCourse::kMaxKnots / 4);
    for (double share : {0.1, 0.33, 0.5, 0.9})
        EXPECT_NEAR(course.distanceAt(share), share * share, 1e-3) << share;
}

TEST(TimedCourse, NoTimeOrNoDistanceGivesNoCourse) {
    TimedCourse course;
    course.add(1.0, 1.0);
    EXPECT_FALSE(course.finish(0.0, 1.0));
    EXPECT_FALSE(course.finish(1.0, 0.0));
    EXPECT_FALSE(course.finish(std::nan(""), 1.0));
    EXPECT_EQ(course.knotCount(), 1u);
}

}  // namespace
