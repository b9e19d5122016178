#include <gtest/gtest.h>

#include <cmath>

#include "cnc_core/compiler/lookahead/RadiusCorrection.h"
#include "tests/core/LookAheadTestSupport.h"

using namespace mtc::core::lookahead;
using namespace mtc::core::lookahead::testing;

namespace {

std::vector<PathElement> square(double feed = 3000) {
    return polyline({point({0, 0, 0}), point({10, 0, 0}), point({10, 10, 0}), point({0, 10, 0}),
                     point({0, 0, 0})},
                    feed);
}

RadiusCorrectionSettings settings(double radius, int side, double approach = 0.0) {
    RadiusCorrectionSettings s;
    s.radius = radius;
    s.side = side;
    s.approach = approach;
    return s;
}

void expectPoint(const AxisVector& actual, std::initializer_list<double> expected) {
    const AxisVector e = point(expected);
    EXPECT_NEAR((actual - e).norm(), 0.0, 1e-9) << actual.transpose() << " vs " << e.transpose();
}

void expectContiguous(const std::vector<PathElement>& elements) {
    for (size_t k = 1; k < elements.size(); ++k)
        EXPECT_NEAR((elements[k].start - elements[k - 1].end).norm(), 0.0, 1e-9) << k;
}

}  // namespace

TEST(LookAheadRadiusCorrection, LeftOfACounterClockwiseUTrimsInsideCorners) {
    const auto open = polyline(
        {point({0, 0, 0}), point({10, 0, 0}), point({10, 10, 0}), point({0, 10, 0})}, 3000);
    const auto result = correctToolRadius(open, settings(1.0, 1, 2.0));
    ASSERT_TRUE(result.ok()) << result.problems.front().code;
    const auto& e = result.elements;
    ASSERT_EQ(e.size(), 7u);  // lead-in, approach, 3 sides, retract, lead-out
    EXPECT_EQ(e[0].generated, kLeadIn);
    expectPoint(e[0].start, {0, 0, 0});
    expectPoint(e[1].start, {-2, 1, 0});  // approach: 2 mm tangential before (0, 1)
    EXPECT_EQ(e[1].generated, kApproachLine);
    expectPoint(e[2].start, {0, 1, 0});
    expectPoint(e[2].end, {9, 1, 0});
    expectPoint(e[3].end, {9, 9, 0});
    expectPoint(e[4].end, {0, 9, 0});
    EXPECT_EQ(e[5].generated, kRetractLine);
    expectPoint(e[5].end, {-2, 9, 0});
    EXPECT_EQ(e[6].generated, kLeadOut);
    expectPoint(e[6].end, {0, 10, 0});
    expectContiguous(e);
}

TEST(LookAheadRadiusCorrection, ClosedContourCrossesItselfAtTheStartWithinTheBuffer) {
    // Left of the closed square: the last side's offset crosses the first's
    // (the tool would cut into the first side): reported as a bottleneck.
    const auto result = correctToolRadius(square(), settings(1.0, 1));
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.problems[0].code, "LA_TRC_BOTTLENECK");
}

TEST(LookAheadRadiusCorrection, RightOfTheSquareAddsCornerArcsAroundTheCorners) {
    const auto result = correctToolRadius(square(), settings(1.0, 2));
    ASSERT_TRUE(result.ok());
    const auto& e = result.elements;
    ASSERT_EQ(e.size(), 9u);  // lead-in, 4 sides, 3 corner arcs, lead-out
    expectPoint(e[1].start, {0, -1, 0});
    expectPoint(e[1].end, {10, -1, 0});
    EXPECT_EQ(e[2].generated, kCornerArc);
    EXPECT_EQ(e[2].kind, ElementKind::ArcCcw);
    expectPoint(e[2].center, {10, 0, 0});
    expectPoint(e[2].end, {11, 0, 0});
    expectPoint(e[3].end, {11, 10, 0});
    expectContiguous(e);
    // Every point of the corrected sides lies 1 mm from the square.
    for (const PathElement& side : {e[1], e[3], e[5], e[7]}) {
        const AxisVector mid = 0.5 * (side.start + side.end);
        const double inside = std::min({mid[0], 10 - mid[0], mid[1], 10 - mid[1]});
        EXPECT_NEAR(inside, -1.0, 1e-9);
    }
}

TEST(LookAheadRadiusCorrection, ArcsChangeTheirRadiusByTheToolRadius) {
    const PathElement ccw = arc(point({5, 0, 0}), point({-5, 0, 0}), point({0, 0, 0}), false, 2000);
    const PathElement cw = arc(point({5, 0, 0}), point({-5, 0, 0}), point({0, 0, 0}), true, 2000);
    auto radiusOf = [](const CorrectedPolygon& c) {
        return c.elements.at(1).start.head<2>().norm();
    };
    EXPECT_NEAR(radiusOf(correctToolRadius({ccw}, settings(1.5, 1))), 3.5, 1e-12);
    EXPECT_NEAR(radiusOf(correctToolRadius({ccw}, settings(1.5, 2))), 6.5, 1e-12);
    EXPECT_NEAR(radiusOf(correctToolRadius({cw}, settings(1.5, 1))), 6.5, 1e-12);
    EXPECT_NEAR(radiusOf(correctToolRadius({cw}, settings(1.5, 2))), 3.5, 1e-12);
}

TEST(LookAheadRadiusCorrection, LineIntoArcInsideCornerMeetsOnTheOffsetCircle) {
    // Line along +X into a CCW arc that turns left (inside corner for left TRC).
    const std::vector<PathElement> contour{
        line(point({0, 0, 0}), point({10, 0, 0}), 2000),
        arc(point({10, 0, 0}), point({10, 10, 0}), point({5, 5, 0}), false, 2000)};
    const auto result = correctToolRadius(contour, settings(1.0, 1));
    ASSERT_TRUE(result.ok()) << result.problems.front().code;
    const AxisVector x = result.elements[1].end;
    EXPECT_NEAR(x[1], 1.0, 1e-9);                                              // on the offset line
    EXPECT_NEAR(std::hypot(x[0] - 5, x[1] - 5), std::sqrt(50.0) - 1.0, 1e-9);  // on the offset arc
    expectContiguous(result.elements);
}

TEST(LookAheadRadiusCorrection, ErrorConditions) {
    const PathElement small =
        arc(point({2, 0, 0}), point({-2, 0, 0}), point({0, 0, 0}), false, 2000);
    EXPECT_EQ(correctToolRadius({small}, settings(3.0, 1)).problems.at(0).code,
              "LA_TRC_RADIUS_TOO_LARGE");
    const auto shortStep = polyline(
        {point({0, 0, 0}), point({10, 0, 0}), point({10, 0.5, 0}), point({0, 0.5, 0})}, 2000);
    const auto tooShort = correctToolRadius(shortStep, settings(1.0, 1));
    EXPECT_EQ(tooShort.problems.at(0).code, "LA_TRC_ELEMENT_TOO_SHORT");
    const auto plunge = polyline({point({0, 0, 0}), point({0, 0, -5})}, 2000);
    EXPECT_EQ(correctToolRadius(plunge, settings(1.0, 1)).problems.at(0).code,
              "LA_TRC_NO_PLANE_MOTION");
    const auto back = polyline({point({0, 0, 0}), point({10, 0, 0}), point({5, 0, 0})}, 2000);
    EXPECT_EQ(correctToolRadius(back, settings(1.0, 1)).problems.at(0).code, "LA_TRC_REVERSAL");
    EXPECT_EQ(correctToolRadius(square(), settings(0.0, 1)).problems.at(0).code,
              "LA_TRC_NO_RADIUS");
}

TEST(LookAheadRadiusCorrection, BottleneckIsFoundWithinTheBlockBuffer) {
    const auto slot = polyline({point({0, 0, 0}), point({20, 0, 0}), point({20, 10, 0}),
                                point({10, 10, 0}), point({10, 1.5, 0}), point({4, 3, 0})},
                               2000);
    RadiusCorrectionSettings s = settings(1.0, 1);
    s.blockBuffer = 3;  // elements 0 and 4 are four apart: not checked
    EXPECT_TRUE(correctToolRadius(slot, s).ok());
    s.blockBuffer = 4;
    const auto found = correctToolRadius(slot, s);
    ASSERT_FALSE(found.ok());
    EXPECT_EQ(found.problems[0].code, "LA_TRC_BOTTLENECK");
    EXPECT_EQ(found.problems[0].element, 4);
}

TEST(LookAheadRadiusCorrection, CorrectedPolygonPlansWithinTheLimits) {
    const auto limits = millLimits();
    for (int side : {1, 2}) {
        auto contour = square(8000);
        contour.pop_back();  // open: the closing side would cross the first one
        const auto corrected = correctToolRadius(contour, settings(2.0, side, 3.0));
        ASSERT_TRUE(corrected.ok()) << corrected.problems.front().code;
        const LookAheadParameters parameters;
        const auto plan = planVelocityProfile(corrected.elements, limits, parameters);
        ASSERT_TRUE(plan.ok());
        EXPECT_TRUE(limitViolations(plan, corrected.elements, limits, parameters).empty());
    }
}

TEST(LookAheadRadiusCorrection, WorksInTheG18Plane) {
    // G18: plane Z (first) / X (second); a line along +Z, left correction.
    const auto contour = polyline({point({0, 0, 0}), point({0, 0, 10})}, 2000);
    RadiusCorrectionSettings s = settings(1.0, 1);
    s.planeFirst = 2;
    s.planeSecond = 0;
    const auto result = correctToolRadius(contour, s);
    ASSERT_TRUE(result.ok());
    // Left of +Z in the Z/X plane is +X.
    expectPoint(result.elements[1].start, {1, 0, 0});
    expectPoint(result.elements[1].end, {1, 0, 10});
}
