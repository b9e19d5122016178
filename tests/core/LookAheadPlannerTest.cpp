#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "tests/core/LookAheadTestSupport.h"

using namespace mtc::core::lookahead;
using namespace mtc::core::lookahead::testing;

namespace {

constexpr double kPi = 3.14159265358979323846;

LookAheadParameters defaults() {
    return LookAheadParameters{};
}

void expectWithinLimits(const LookAheadPlan& plan, const std::vector<PathElement>& elements,
                        const AxisLimits& limits, const LookAheadParameters& parameters) {
    ASSERT_TRUE(plan.ok()) << plan.problems.front().code;
    const auto violations = limitViolations(plan, elements, limits, parameters);
    EXPECT_TRUE(violations.empty())
        << violations.size() << " violations, first: " << violations.front();
}

std::vector<const PlannedBlock*> blocksOf(const LookAheadPlan& plan, int element) {
    std::vector<const PlannedBlock*> out;
    for (const PlannedBlock& b : plan.blocks)
        if (b.element == element) out.push_back(&b);
    return out;
}

}  // namespace

TEST(LookAheadPlanner, SingleLineStartsAndEndsAtRest) {
    const auto limits = millLimits();
    const auto elements = polyline({point({0, 0, 0}), point({200, 0, 0})}, 12000);
    const auto plan = planVelocityProfile(elements, limits, defaults());
    expectWithinLimits(plan, elements, limits, defaults());
    EXPECT_DOUBLE_EQ(plan.profiles[0].vStart, 0.0);
    EXPECT_DOUBLE_EQ(plan.profiles[0].vEnd, 0.0);
    EXPECT_NEAR(plan.profiles[0].vMax * 60.0, 12000.0, 1e-9);
    EXPECT_NEAR(plan.totalLength, 200.0, 1e-12);
    // 200 mm at 200 mm/s with ramps of 0.08 s each way at 2450 mm/s^2.
    const double a = 2500.0 * kAccelerationMargin;
    EXPECT_NEAR(plan.totalTime, 200.0 / 200.0 + 200.0 / a, 1e-9);
}

TEST(LookAheadPlanner, RampsAreSplitIntoSubBlocksWithStepwiseF) {
    const auto limits = millLimits();
    const auto elements = polyline({point({0, 0, 0}), point({300, 0, 0})}, 24000);
    const auto plan = planVelocityProfile(elements, limits, defaults());
    expectWithinLimits(plan, elements, limits, defaults());
    const auto parts = blocksOf(plan, 0);
    ASSERT_GT(parts.size(), 4u);
    // Rising F up to the programmed feed, then falling F to the end.
    size_t top = 0;
    for (size_t i = 1; i < parts.size(); ++i)
        if (parts[i]->feed > parts[top]->feed) top = i;
    EXPECT_NEAR(parts[top]->feed, 24000.0, 0.1);
    for (size_t i = 1; i <= top; ++i)
        EXPECT_GT(parts[i]->feed, parts[i - 1]->feed);
    for (size_t i = top + 1; i < parts.size(); ++i)
        EXPECT_LT(parts[i]->feed, parts[i - 1]->feed);
    EXPECT_EQ(parts.front()->subIndex, 0);
    EXPECT_EQ(parts.back()->subIndex, static_cast<int>(parts.size()) - 1);
    EXPECT_EQ((parts.back()->end - elements[0].end).norm(), 0.0);
    for (size_t i = 1; i < parts.size(); ++i)
        EXPECT_NEAR((parts[i]->start - parts[i - 1]->end).norm(), 0.0, 1e-12);
}

TEST(LookAheadPlanner, ShortBlocksBeforeASharpCornerDecelerateOverSeveralBlocks) {
    const auto limits = millLimits();
    std::vector<AxisVector> points;
    for (int i = 0; i <= 60; ++i)
        points.push_back(point({i * 0.5, 0, 0}));
    points.push_back(point({30, 30, 0}));  // 90 degree corner at X30
    const auto elements = polyline(points, 15000);
    const auto plan = planVelocityProfile(elements, limits, defaults());
    expectWithinLimits(plan, elements, limits, defaults());
    // The corner (tangent jump 1 in X and in Y) allows 2 * 2500 * 0.002 = 10 mm/s.
    EXPECT_NEAR(plan.profiles[59].vEnd, 10.0, 1e-9);
    // METB caps the 0.5 mm blocks at 100 mm/s; braking from 100 to 10 mm/s at
    // 2450 mm/s^2 takes 2.02 mm: the four blocks before the corner slow down.
    int slowed = 0;
    for (int k = 40; k < 60; ++k)
        if (plan.profiles[k].vStart < plan.profiles[k].vMax - 1e-9) ++slowed;
    EXPECT_EQ(slowed, 4);
    EXPECT_NEAR(plan.profiles[55].vStart, 100.0, 1e-9);
}

TEST(LookAheadPlanner, MinimumBlockTimeCapsVeryShortBlocks) {
    const auto limits = millLimits();
    std::vector<AxisVector> points;
    for (int i = 0; i <= 400; ++i)
        points.push_back(point({i * 0.1, 0.02 * std::sin(i * 0.1), 0}));
    const auto elements = polyline(points, 20000);
    LookAheadParameters parameters;
    parameters.metbMs = 8.0;
    const auto plan = planVelocityProfile(elements, limits, parameters);
    expectWithinLimits(plan, elements, limits, parameters);
    for (const PlannedBlock& b : plan.blocks) {
        EXPECT_GE(b.time, 0.008 * (1 - 1e-9));
        EXPECT_LE(b.feed / 60.0, (b.sEnd - b.sStart) / 0.008 * (1 + 1e-9));
    }
}

TEST(LookAheadPlanner, VfbtRaisesTheTransitionVelocity) {
    const auto limits = millLimits();
    const auto elements =
        polyline({point({0, 0, 0}), point({100, 0, 0}), point({200, 10, 0})}, 20000);
    LookAheadParameters slow, fast;
    fast.vfbt = 3.0;
    const auto a = planVelocityProfile(elements, limits, slow);
    const auto b = planVelocityProfile(elements, limits, fast);
    expectWithinLimits(a, elements, limits, slow);
    expectWithinLimits(b, elements, limits, fast);
    EXPECT_NEAR(b.profiles[0].vEnd, 3.0 * a.profiles[0].vEnd, 1e-9);
    EXPECT_LT(b.totalTime, a.totalTime);
}

TEST(LookAheadPlanner, AxisVelocityLimitsTheDiagonal) {
    const auto limits = millLimits();
    // Mostly Z: Z may run only 20000 mm/min.
    const auto elements = polyline({point({0, 0, 0}), point({10, 0, -400})}, 30000);
    const auto plan = planVelocityProfile(elements, limits, defaults());
    expectWithinLimits(plan, elements, limits, defaults());
    const double share = 400.0 / std::hypot(10.0, 400.0);
    EXPECT_NEAR(plan.profiles[0].vMax * 60.0, 20000.0 / share, 1e-6);
}

TEST(LookAheadPlanner, ProgrammedAxisVelocityLimitsThatAxis) {
    const auto limits = millLimits();
    auto elements = polyline({point({0, 0, 0}), point({100, 100, 0})}, 20000);
    elements[0].axisFeed[1] = 4500;  // FY=4500
    const auto plan = planVelocityProfile(elements, limits, defaults());
    expectWithinLimits(plan, elements, limits, defaults());
    EXPECT_NEAR(plan.profiles[0].vMax * 60.0, 4500.0 * std::sqrt(2.0), 1e-6);
}

TEST(LookAheadPlanner, AccEffScalesTheAcceleration) {
    const auto limits = millLimits();
    auto elements = polyline({point({0, 0, 0}), point({200, 0, 0})}, 12000);
    const auto full = planVelocityProfile(elements, limits, defaults());
    elements[0].accelerationFactor = 0.5;
    const auto half = planVelocityProfile(elements, limits, defaults());
    expectWithinLimits(half, elements, limits, defaults());
    EXPECT_NEAR(half.profiles[0].acceleration, 0.5 * full.profiles[0].acceleration, 1e-9);
    EXPECT_GT(half.totalTime, full.totalTime);
}

TEST(LookAheadPlanner, ArcsRespectCentripetalAcceleration) {
    const auto limits = millLimits();
    // Full circle of radius 5 mm at F 30000: v^2/r would be 50000 mm/s^2.
    std::vector<PathElement> elements{
        line(point({-10, 0, 0}), point({0, 0, 0}), 30000),
        arc(point({0, 0, 0}), point({0, 0, 0}), point({0, 5, 0}), false, 30000),
        line(point({0, 0, 0}), point({10, 0, 0}), 30000)};
    const auto plan = planVelocityProfile(elements, limits, defaults());
    expectWithinLimits(plan, elements, limits, defaults());
    EXPECT_NEAR(plan.geometry[1].length, 2 * kPi * 5, 1e-9);
    EXPECT_NEAR(plan.profiles[1].vMax, std::sqrt(0.5 * 2500 * 5), 1e-9);
}

TEST(LookAheadPlanner, HelixAndClockwiseArcsInOtherPlanes) {
    const auto limits = millLimits();
    // G18 (Z, X) clockwise quarter with a Y lead, then a G19 arc.
    PathElement g18 = arc(point({0, 0, 0}), point({10, 3, 10}), point({0, 0, 10}), true, 10000);
    g18.planeFirst = 2;
    g18.planeSecond = 0;
    PathElement g19 =
        arc(point({10, 3, 10}), point({10, 13, 20}), point({10, 13, 10}), false, 10000);
    g19.planeFirst = 1;
    g19.planeSecond = 2;
    const std::vector<PathElement> elements{g18, g19};
    const auto plan = planVelocityProfile(elements, limits, defaults());
    expectWithinLimits(plan, elements, limits, defaults());
    EXPECT_NEAR(plan.geometry[0].sweep, -kPi / 2, 1e-12);
    EXPECT_NEAR(plan.geometry[0].length, std::hypot(10 * kPi / 2, 3.0), 1e-9);
    const AxisVector mid = pointAt(g18, plan.geometry[0], plan.geometry[0].length / 2);
    EXPECT_NEAR(std::hypot(mid[0], mid[2] - 10), 10.0, 1e-9);
    EXPECT_NEAR(mid[1], 1.5, 1e-9);
}

TEST(LookAheadPlanner, ReportsBadPolygons) {
    const auto limits = millLimits();
    auto gap = polyline({point({0, 0, 0}), point({10, 0, 0})}, 1000);
    gap.push_back(line(point({11, 0, 0}), point({20, 0, 0}), 1000));
    EXPECT_EQ(planVelocityProfile(gap, limits, defaults()).problems.at(0).code,
              "LA_NOT_CONTIGUOUS");
    auto noFeed = polyline({point({0, 0, 0}), point({10, 0, 0})}, 0);
    EXPECT_EQ(planVelocityProfile(noFeed, limits, defaults()).problems.at(0).code, "LA_NO_FEED");
    auto empty = polyline({point({0, 0, 0}), point({0, 0, 0})}, 1000);
    EXPECT_EQ(planVelocityProfile(empty, limits, defaults()).problems.at(0).code, "LA_ZERO_LENGTH");
    auto axes = polyline({point({0, 0}), point({1, 0})}, 1000);
    EXPECT_EQ(planVelocityProfile(axes, limits, defaults()).problems.at(0).code, "LA_AXES");
    EXPECT_TRUE(planVelocityProfile({}, limits, defaults()).blocks.empty());
    AxisLimits stuck = limits;
    stuck.maxAcceleration[2] = 0.0;
    const auto line = polyline({point({0, 0, 0}), point({1, 0, 0})}, 1000);
    EXPECT_EQ(planVelocityProfile(line, stuck, defaults()).problems.at(0).code, "LA_AXIS_LIMITS");
}

TEST(LookAheadPlanner, SlowFeedsGiveNoSubBlocksShorterThanAMicron) {
    const auto limits = millLimits();
    const auto elements = polyline({point({0, 0, 0}), point({0.05, 0, 0})}, 1.0);
    const auto plan = planVelocityProfile(elements, limits, defaults());
    expectWithinLimits(plan, elements, limits, defaults());
    for (const PlannedBlock& b : plan.blocks)
        EXPECT_GE(b.sEnd - b.sStart, 0.001 - 1e-12);
}

TEST(LookAheadPlanner, RandomPolygonsStayWithinEveryLimit) {
    const auto limits = millLimits();
    std::mt19937 random(6);
    std::uniform_real_distribution<double> step(-5.0, 5.0), feed(100.0, 40000.0), factor(0.2, 2.0);
    std::uniform_real_distribution<double> metb(3.0, 30.0), vfbt(1.0, 10.0);
    for (int round = 0; round < 40; ++round) {
        std::vector<PathElement> elements;
        AxisVector at = point({0, 0, 0});
        for (int k = 0; k < 60; ++k) {
            const double scale = round % 3 == 0 ? 0.02 : 1.0;  // some programs of tiny blocks
            AxisVector next = at + point({step(random), step(random), 0.2 * step(random)}) * scale;
            if (k % 7 == 3) {  // a half circle in G17
                AxisVector centre = at + point({scale, 0, 0});
                next = at + point({2 * scale, 0, 0});
                elements.push_back(arc(at, next, centre, k % 2 == 0, feed(random)));
            } else {
                elements.push_back(line(at, next, feed(random)));
            }
            elements.back().accelerationFactor = factor(random);
            at = next;
        }
        LookAheadParameters parameters;
        parameters.metbMs = metb(random);
        parameters.vfbt = vfbt(random);
        const auto plan = planVelocityProfile(elements, limits, parameters);
        expectWithinLimits(plan, elements, limits, parameters);
    }
}
