// The radius compensation engine alone (plane geometry, no interpreter):
// start-up, inside and outside corners, arcs, cancel, interruptions and the
// contours a tool cannot follow, against hand-computed points (1e-6 mm).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "cnc_core/compensation/RadiusCompensation.h"

namespace {

using namespace mtc::core::comp;

constexpr double kTol = 1e-6;

PlanePath line(double x0, double y0, double x1, double y1) {
    PlanePath p;
    p.start = {x0, y0};
    p.end = {x1, y1};
    return p;
}

PlanePath arc(PathKind kind, double x0, double y0, double x1, double y1, double cx, double cy) {
    PlanePath p;
    p.kind = kind;
    p.start = {x0, y0};
    p.end = {x1, y1};
    p.centre = {cx, cy};
    return p;
}

/// Feeds moves one by one and collects every released piece.
struct Feed {
    RadiusCompensation engine;
    std::vector<ToolPiece> pieces;
    Problem problem;
    int next = 1;

    bool move(const PlanePath& path, Side side, double radius = 2.0, bool rapid = false) {
        ContourMove m;
        m.path = path;
        m.side = side;
        m.radius = radius;
        m.rapid = rapid;
        m.id = next++;
        RadiusCompensation copy = engine;
        Release r;
        if (!copy.apply(m, r, problem)) return false;
        engine = copy;
        for (int i = 0; i < r.count; ++i)
            pieces.push_back(r.pieces[static_cast<std::size_t>(i)]);
        return true;
    }
};

void expectPoint(const Vec2& actual, double x, double y) {
    EXPECT_NEAR(actual.x(), x, kTol);
    EXPECT_NEAR(actual.y(), y, kTol);
}

void expectLine(const ToolPiece& p, double x0, double y0, double x1, double y1) {
    EXPECT_EQ(p.path.kind, PathKind::Line);
    expectPoint(p.path.start, x0, y0);
    expectPoint(p.path.end, x1, y1);
}

TEST(CompensationEngine, InsideCornersOfAPocketAreIntersections) {
    Feed run;
    ASSERT_TRUE(run.move(line(-10, -10, 0, 0), Side::Left));  // start-up
    ASSERT_TRUE(run.move(line(0, 0, 10, 0), Side::Left));     // first element: held
    EXPECT_EQ(run.pieces.size(), 1u);                         // the start-up line
    expectLine(run.pieces[0], -10, -10, 0, 2);                // to the perpendicular
    ASSERT_TRUE(run.move(line(10, 0, 10, 10), Side::Left));   // left turn: inside
    ASSERT_TRUE(run.move(line(10, 10, 0, 10), Side::Left));   // inside again
    ASSERT_TRUE(run.move(line(0, 10, -10, 20), Side::None));  // cancel
    ASSERT_EQ(run.pieces.size(), 5u);
    expectLine(run.pieces[1], 0, 2, 8, 2);
    expectLine(run.pieces[2], 8, 2, 8, 8);
    expectLine(run.pieces[3], 8, 8, 0, 8);     // ends at its perpendicular before the cancel
    expectLine(run.pieces[4], 0, 8, -10, 20);  // cancel: to the programmed point
    for (const auto& p : run.pieces)
        EXPECT_FALSE(p.inserted);
    EXPECT_EQ(run.engine.phase(), Phase::Off);
    EXPECT_TRUE(run.engine.idle());
}

TEST(CompensationEngine, OutsideCornersGetAnArcAroundTheCorner) {
    Feed run;
    ASSERT_TRUE(run.move(line(-10, -10, 0, 0), Side::Right));
    ASSERT_TRUE(run.move(line(0, 0, 10, 0), Side::Right));
    ASSERT_TRUE(run.move(line(10, 0, 10, 10), Side::Right));  // left turn, tool right: outside
    ASSERT_TRUE(run.move(line(10, 10, 20, 10), Side::None));
    ASSERT_EQ(run.pieces.size(), 5u);
    expectLine(run.pieces[0], -10, -10, 0, -2);
    expectLine(run.pieces[1], 0, -2, 10, -2);
    const ToolPiece& corner = run.pieces[2];
    EXPECT_TRUE(corner.inserted);
    EXPECT_EQ(corner.id, 2);                        // belongs to the block before the corner
    EXPECT_EQ(corner.path.kind, PathKind::ArcCcw);  // G42: around the corner counter-clockwise
    expectPoint(corner.path.start, 10, -2);
    expectPoint(corner.path.end, 12, 0);
    expectPoint(corner.path.centre, 10, 0);
    expectLine(run.pieces[3], 12, 0, 12, 10);
    expectLine(run.pieces[4], 12, 10, 20, 10);
}

TEST(CompensationEngine, ArcsChangeTheirRadiusAndMeetLinesAtTheIntersection) {
    // Line along x, then a quarter circle G3 around (10, 5) radius 5, tool left (inside).
    Feed run;
    ASSERT_TRUE(run.move(line(0, -5, 0, 0), Side::Left));
    ASSERT_TRUE(run.move(line(0, 0, 10, 0), Side::Left));
    ASSERT_TRUE(run.move(arc(PathKind::ArcCcw, 10, 0, 15, 5, 10, 5), Side::Left));  // tangent
    ASSERT_TRUE(run.move(line(15, 5, 15, 20), Side::Left));                         // tangent
    ASSERT_TRUE(run.move(line(15, 20, 30, 20), Side::None));
    ASSERT_EQ(run.pieces.size(), 5u);
    expectLine(run.pieces[1], 0, 2, 10, 2);
    const ToolPiece& a = run.pieces[2];
    EXPECT_EQ(a.path.kind, PathKind::ArcCcw);
    expectPoint(a.path.start, 10, 2);
    expectPoint(a.path.end, 13, 5);  // radius 5 - 2
    expectPoint(a.path.centre, 10, 5);
    expectLine(run.pieces[3], 13, 5, 13, 20);
}

TEST(CompensationEngine, TwoCirclesMeetAtAnInsideCornerInTheirIntersection) {
    // G2 R10 around (20,-10) ends at (20,-20) heading -x; G3 R10 around
    // (10,-20) leaves heading +y: a right turn, inside for G42. Tool circles
    // R6.5 and R13.5; their centres 14.142 apart: along = 60 / (2 * 14.142),
    // h = sqrt(6.5^2 - along^2) = sqrt(37.75): (18.5 + h / sqrt2, -11.5 - h / sqrt2).
    Feed run;
    // Start-up (40,-10)-(30,-10), the two circles, the cancel line: four pieces.
    ASSERT_TRUE(run.move(line(40, -10, 30, -10), Side::Right, 3.5));
    ASSERT_TRUE(run.move(arc(PathKind::ArcCw, 30, -10, 20, -20, 20, -10), Side::Right, 3.5));
    ASSERT_TRUE(run.move(arc(PathKind::ArcCcw, 20, -20, 10, -10, 10, -20), Side::Right, 3.5));
    ASSERT_TRUE(run.move(line(10, -10, 10, 10), Side::None, 3.5));
    const double h = std::sqrt(37.75) / std::sqrt(2.0);
    ASSERT_EQ(run.pieces.size(), 4u);
    expectLine(run.pieces[0], 40, -10, 26.5, -10);  // start-up: perpendicular to the circle's start
    EXPECT_EQ(run.pieces[1].path.kind, PathKind::ArcCw);
    expectPoint(run.pieces[1].path.start, 26.5, -10);
    expectPoint(run.pieces[1].path.end, 18.5 + h, -11.5 - h);
    expectPoint(run.pieces[2].path.start, 18.5 + h, -11.5 - h);
    expectPoint(run.pieces[2].path.end, 10, -6.5);  // perpendicular end: (10,-20) + 13.5 up
    EXPECT_NEAR(run.pieces[2].path.radius(), 13.5, kTol);
    EXPECT_NEAR((run.pieces[1].path.end - Vec2(20, -10)).norm(), 6.5, kTol);
}

TEST(CompensationEngine, ArcSmallerThanTheToolOnTheInsideIsRefused) {
    Feed run;
    ASSERT_TRUE(run.move(line(0, -5, 0, 0), Side::Left));
    ASSERT_TRUE(run.move(line(0, 0, 10, 0), Side::Left));
    // G3 radius 1.5 with the tool (radius 2) on the centre's side.
    EXPECT_FALSE(run.move(arc(PathKind::ArcCcw, 10, 0, 11.5, 1.5, 10, 1.5), Side::Left));
    EXPECT_STREQ(run.problem.code, "COMP_ARC_TOO_SMALL");
    EXPECT_EQ(run.problem.id, 3);
    // The same arc with the tool outside is fine (radius 3.5).
    Feed outside;
    ASSERT_TRUE(outside.move(line(0, -5, 0, 0), Side::Right));
    ASSERT_TRUE(outside.move(line(0, 0, 10, 0), Side::Right));
    EXPECT_TRUE(outside.move(arc(PathKind::ArcCcw, 10, 0, 11.5, 1.5, 10, 1.5), Side::Right));
}

TEST(CompensationEngine, ShortStepAtAnInsideCornerWouldGouge) {
    // A step of 1 mm up at an inside corner: with radius 2 the tool path of
    // the step ends before it begins (the offsets meet at y 2, above the step).
    Feed run;
    ASSERT_TRUE(run.move(line(-5, -5, 0, 0), Side::Left));
    ASSERT_TRUE(run.move(line(0, 0, 10, 0), Side::Left));
    EXPECT_FALSE(run.move(line(10, 0, 10, 1), Side::Left));
    EXPECT_STREQ(run.problem.code, "COMP_ELEMENT_TOO_SHORT");
    EXPECT_EQ(run.problem.id, 3);  // the step is at fault
    EXPECT_EQ(run.problem.otherId, 2);
}

TEST(CompensationEngine, SlotNarrowerThanTheToolIsRefused) {
    // A slot 3 mm wide needs a tool of at most 1.5 mm radius: with 2 mm the
    // tool path across the end of the slot runs backwards.
    Feed run;
    ASSERT_TRUE(run.move(line(-10, 0, 0, 0), Side::Left));
    ASSERT_TRUE(run.move(line(0, 0, 0, 20), Side::Left));
    ASSERT_TRUE(run.move(line(0, 20, -3, 20), Side::Left));
    EXPECT_FALSE(run.move(line(-3, 20, -3, 0), Side::Left));
    EXPECT_STREQ(run.problem.code, "COMP_ELEMENT_TOO_SHORT");
    EXPECT_EQ(run.problem.id, 3);  // the end of the slot
}

TEST(CompensationEngine, ClosingAPocketAtACornerCutsIntoItsFirstWall) {
    // Square pocket started and left at the corner (0, 0): the last wall's
    // tool path ends at (2, 0) and crosses the first wall's at (2, 2).
    Feed run;
    ASSERT_TRUE(run.move(line(5, 5, 0, 0), Side::Left));
    ASSERT_TRUE(run.move(line(0, 0, 10, 0), Side::Left));
    ASSERT_TRUE(run.move(line(10, 0, 10, 10), Side::Left));
    ASSERT_TRUE(run.move(line(10, 10, 0, 10), Side::Left));
    ASSERT_TRUE(run.move(line(0, 10, 0, 0), Side::Left));
    EXPECT_FALSE(run.move(line(0, 0, 5, 5), Side::None));
    EXPECT_STREQ(run.problem.code, "COMP_BOTTLENECK");
    EXPECT_EQ(run.problem.id, 5);       // the last wall
    EXPECT_EQ(run.problem.otherId, 2);  // the first wall
    // Left in the middle of the first wall instead, nothing crosses.
    Feed good;
    ASSERT_TRUE(good.move(line(5, 5, 5, 0), Side::Left));
    ASSERT_TRUE(good.move(line(5, 0, 10, 0), Side::Left));
    ASSERT_TRUE(good.move(line(10, 0, 10, 10), Side::Left));
    ASSERT_TRUE(good.move(line(10, 10, 0, 10), Side::Left));
    ASSERT_TRUE(good.move(line(0, 10, 0, 0), Side::Left));
    ASSERT_TRUE(good.move(line(0, 0, 6, 0), Side::Left));
    EXPECT_TRUE(good.move(line(6, 0, 5, 5), Side::None)) << good.problem.message;
}

TEST(CompensationEngine, ReversalGoesAroundTheEnd) {
    Feed run;
    ASSERT_TRUE(run.move(line(0, -5, 0, 0), Side::Left));
    ASSERT_TRUE(run.move(line(0, 0, 10, 0), Side::Left));
    ASSERT_TRUE(run.move(line(10, 0, 0, 0), Side::Left));  // back on itself
    ASSERT_TRUE(run.move(line(0, 0, 0, -5), Side::None));
    ASSERT_EQ(run.pieces.size(), 5u);
    const ToolPiece& turn = run.pieces[2];
    EXPECT_TRUE(turn.inserted);
    EXPECT_EQ(turn.path.kind, PathKind::ArcCw);
    expectPoint(turn.path.start, 10, 2);
    expectPoint(turn.path.end, 10, -2);
    EXPECT_NEAR(turn.path.sweep(), 3.14159265358979323846, 1e-9);
    expectLine(run.pieces[3], 10, -2, 0, -2);
}

TEST(CompensationEngine, StartUpAndCancelMustBeStraight) {
    Feed run;
    EXPECT_FALSE(run.move(arc(PathKind::ArcCw, 0, 0, 10, 0, 5, 0), Side::Left));
    EXPECT_STREQ(run.problem.code, "COMP_STARTUP_ARC");
    Feed cancel;
    ASSERT_TRUE(cancel.move(line(0, -5, 0, 0), Side::Left));
    ASSERT_TRUE(cancel.move(line(0, 0, 10, 0), Side::Left));
    EXPECT_FALSE(cancel.move(arc(PathKind::ArcCw, 10, 0, 20, 0, 15, 0), Side::None));
    EXPECT_STREQ(cancel.problem.code, "COMP_CANCEL_ARC");
}

TEST(CompensationEngine, InterruptionStopsAtThePerpendicularAndResumesAroundAnOutsideCorner) {
    Feed run;
    ASSERT_TRUE(run.move(line(0, -5, 0, 0), Side::Right));
    ASSERT_TRUE(run.move(line(0, 0, 10, 0), Side::Right));
    const Release stop = run.engine.interrupt();
    ASSERT_EQ(stop.count, 1);
    expectLine(stop.pieces[0], 0, -2, 10, -2);
    EXPECT_EQ(run.engine.phase(), Phase::Resume);
    ASSERT_TRUE(run.move(line(10, 0, 10, 10), Side::Right));  // outside corner
    ASSERT_EQ(run.pieces.size(), 2u);
    EXPECT_TRUE(run.pieces[1].inserted);
    expectPoint(run.pieces[1].path.end, 12, 0);
    Feed inside;
    ASSERT_TRUE(inside.move(line(0, -5, 0, 0), Side::Left));
    ASSERT_TRUE(inside.move(line(0, 0, 10, 0), Side::Left));
    inside.engine.interrupt();
    EXPECT_FALSE(inside.move(line(10, 0, 10, 10), Side::Left));  // inside corner after a stop
    EXPECT_STREQ(inside.problem.code, "COMP_CORNER_INTERRUPTED");
}

TEST(CompensationEngine, ZeroRadiusFollowsTheProgrammedPath) {
    Feed run;
    ASSERT_TRUE(run.move(line(0, -5, 0, 0), Side::Left, 0.0));
    ASSERT_TRUE(run.move(line(0, 0, 10, 0), Side::Left, 0.0));
    ASSERT_TRUE(run.move(line(10, 0, 10, 10), Side::Left, 0.0));
    ASSERT_TRUE(run.move(line(10, 10, 20, 10), Side::Left, 0.0));
    ASSERT_TRUE(run.move(line(20, 10, 20, 20), Side::None, 0.0));
    ASSERT_EQ(run.pieces.size(), 5u);
    expectLine(run.pieces[1], 0, 0, 10, 0);
    expectLine(run.pieces[2], 10, 0, 10, 10);
    expectLine(run.pieces[3], 10, 10, 20, 10);
}

TEST(CompensationEngine, OuterCornerBetweenRapidMovesIsAStraightLink) {
    Feed run;
    ASSERT_TRUE(run.move(line(0, -5, 0, 0), Side::Right, 2.0, true));
    ASSERT_TRUE(run.move(line(0, 0, 10, 0), Side::Right, 2.0, true));
    ASSERT_TRUE(run.move(line(10, 0, 10, 10), Side::Right, 2.0, true));
    ASSERT_GE(run.pieces.size(), 3u);
    EXPECT_TRUE(run.pieces[2].inserted);
    EXPECT_EQ(run.pieces[2].path.kind, PathKind::Line);
}

}  // namespace
