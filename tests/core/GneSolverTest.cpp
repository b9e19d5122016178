// Solver of the GNE contours (seed 001, ch. 3): tangent chains, ambiguous
// intersections, under- and over-determined elements, transitions.

#include <gtest/gtest.h>

#include <cmath>

#include "cnc_core/contour/ContourSolver.h"
#include "cnc_core/contour/GneText.h"

namespace mtc::core::gne {
namespace {

Contour contourOf(const std::string& body, const char* window = "WINDOW_01 (-80, 2, 40)") {
    GneDocument doc = readGne(std::string(window) + "\nCONT (1)\n" + body + "END_CONT\n");
    EXPECT_TRUE(doc.ok()) << (doc.diagnostics.empty() ? "" : doc.diagnostics[0].message);
    for (const GneItem& item : doc.items)
        if (item.isContour) return item.contour;
    return {};
}

void expectPoint(const Point& p, double x, double y) {
    EXPECT_NEAR(p.x(), x, 1e-6);
    EXPECT_NEAR(p.y(), y, 1e-6);
}

TEST(GneSolver, FullySpecifiedLinesAndArc) {
    ContourSolution s = solveContour(contourOf(
        "START Z0 X0\nLINE Z0 X20\nLINE Z-30 X20\nCW Z-40 X30 K-30 I30\nLINE Z-60 X30\n"));
    ASSERT_TRUE(s.complete()) << s.diagnostics[0].message;
    ASSERT_EQ(s.path.size(), 4u);
    expectPoint(s.path[0].end, 0, 20);
    expectPoint(s.path[1].end, -30, 20);
    EXPECT_EQ(s.path[2].kind, Segment::ArcCW);
    expectPoint(s.path[2].centre, -30, 30);
    expectPoint(s.path[3].end, -60, 30);
}

TEST(GneSolver, LineWithAngleIntersectsNextLine) {
    // The cone's end is unknown: it lies on the line A135 from (0,10) and
    // on the horizontal X20 that the next element continues.
    ContourSolution s = solveContour(contourOf("START Z0 X10\nLINE A135\nLINE Z-30 X20 A180\n"));
    ASSERT_TRUE(s.complete()) << s.diagnostics[0].message;
    expectPoint(s.path[0].end, -10, 20);
    expectPoint(s.path[1].end, -30, 20);
}

TEST(GneSolver, AngleAndLength) {
    ContourSolution s = solveContour(contourOf("START Z0 X0\nLINE A90 L12.5\nLINE A180 L20\n"));
    ASSERT_TRUE(s.complete());
    expectPoint(s.path[1].end, -20, 12.5);
}

TEST(GneSolver, TangentArcAfterLineWithRadius) {
    // CW arc tangential to the line towards -Z, radius 5, ends at X25: of
    // its two points on X25 the first (ALT0) is the short arc.
    ContourSolution s = solveContour(contourOf("START Z0 X20\nLINE Z-10 X20\nCW X25 R5 TAN\n"));
    ASSERT_TRUE(s.complete()) << s.diagnostics[0].message;
    EXPECT_EQ(s.path[1].kind, Segment::ArcCW);
    expectPoint(s.path[1].centre, -10, 25);
    expectPoint(s.path[1].end, -15, 25);
    EXPECT_NEAR((s.path[1].startTangent() - s.path[0].endTangent()).norm(), 0, 1e-9);
}

TEST(GneSolver, LineTangentToArcFromAPoint) {
    // A line from the circle around (-20,20) R5 to the point (-40,40),
    // tangential to the arc: of the two tangent points, the arc's direction
    // (CCW or CW) decides which one the line can leave from.
    ContourSolution ccw =
        solveContour(contourOf("START Z-15 X20\nCCW K-20 I20\nLINE Z-40 X40 TAN\n"));
    ContourSolution cw =
        solveContour(contourOf("START Z-15 X20\nCW K-20 I20\nLINE Z-40 X40 TAN\n"));
    for (const ContourSolution* s : {&ccw, &cw}) {
        ASSERT_TRUE(s->complete()) << s->diagnostics[0].message;
        const Segment& arc = s->path[0];
        EXPECT_NEAR(arc.radius(), 5.0, 1e-6);
        EXPECT_NEAR((arc.end - arc.centre).dot(Point(-40, 40) - arc.end), 0.0, 1e-6);
        EXPECT_NEAR((s->path[1].startTangent() - arc.endTangent()).norm(), 0.0, 1e-6);
    }
    EXPECT_GT((ccw.path[0].end - cw.path[0].end).norm(), 1.0);
}

TEST(GneSolver, LineCircleIntersectionIsAmbiguous) {
    // Line from (0,0) at 45 degrees meets the circle around (10,5) R5 twice.
    Contour c =
        contourOf("START X0 Y0\nLINE A45\nCCW X15 Y5 I10 J5\n", "WINDOW_02 (-50, -50, 50, 50)");
    ContourSolution s = solveContour(c);
    ASSERT_EQ(s.elements[1].candidates.size(), 2u);
    c.elements[1].alternative = 1;
    ContourSolution other = solveContour(c);
    ASSERT_TRUE(s.complete());
    ASSERT_TRUE(other.complete());
    EXPECT_GT((s.path[0].end - other.path[0].end).norm(), 1.0);
    for (const ContourSolution* sol : {&s, &other})
        EXPECT_NEAR((sol->path[0].end - Point(10, 5)).norm(), 5.0, 1e-6);
    c.elements[1].alternative = 2;
    ContourSolution bad = solveContour(c);
    EXPECT_EQ(bad.elements[1].state, ElementState::Overdetermined);
}

TEST(GneSolver, ArcWithRadiusOnlyOffersBothCentres) {
    ContourSolution s = solveContour(contourOf("START Z0 X20\nCCW Z-10 X20 R8\n"));
    ASSERT_EQ(s.elements[1].candidates.size(), 2u);
    EXPECT_TRUE(s.complete());
}

TEST(GneSolver, UnderdeterminedElementAndFollowers) {
    ContourSolution s =
        solveContour(contourOf("START Z0 X0\nLINE A90\nLINE A180\nLINE Z-50 X30\n"));
    EXPECT_FALSE(s.complete());
    EXPECT_EQ(s.elements[1].state, ElementState::Undetermined);
    EXPECT_EQ(s.elements[2].state, ElementState::NotReached);
    EXPECT_EQ(s.elements[3].state, ElementState::NotReached);
    ASSERT_FALSE(s.diagnostics.empty());
    EXPECT_EQ(s.diagnostics[0].code, "GNE_UNDERDETERMINED");
    EXPECT_EQ(s.diagnostics[0].line, 4u);
}

TEST(GneSolver, OverdeterminedLineIsReported) {
    ContourSolution s = solveContour(contourOf("START Z0 X0\nLINE Z-10 X10 A90\n"));
    EXPECT_EQ(s.elements[1].state, ElementState::Overdetermined);
    EXPECT_EQ(s.diagnostics[0].code, "GNE_OVERDETERMINED");
    // Redundant but consistent data are accepted.
    EXPECT_TRUE(
        solveContour(contourOf("START Z0 X0\nLINE Z-10 X10 A135 L14.142135623731\n")).complete());
}

TEST(GneSolver, ArcDataThatDoNotFitOneCircle) {
    ContourSolution s = solveContour(contourOf("START Z0 X20\nCW Z-10 X20 K-5 I20 R3\n"));
    EXPECT_EQ(s.elements[1].state, ElementState::Overdetermined);
}

TEST(GneSolver, NoIntersectionIsImpossible) {
    ContourSolution s = solveContour(
        contourOf("START X0 Y0\nLINE A0\nCCW X50 Y20 I50 J30\n", "WINDOW_02 (0, 0, 60, 60)"));
    EXPECT_EQ(s.elements[1].state, ElementState::Impossible);
}

TEST(GneSolver, RoundingIsTangentToBothNeighbours) {
    ContourSolution s = solveContour(contourOf("START Z0 X0\nLINE Z0 X20\nRD 2\nLINE Z-30 X20\n"));
    ASSERT_TRUE(s.complete());
    ASSERT_EQ(s.path.size(), 3u);
    const Segment& arc = s.path[1];
    EXPECT_EQ(arc.kind, Segment::ArcCCW);
    expectPoint(arc.start, 0, 18);
    expectPoint(arc.end, -2, 20);
    expectPoint(arc.centre, -2, 18);
    EXPECT_EQ(s.elements[2].segments.size(), 1u);
}

TEST(GneSolver, ChamferCutsBothNeighbours) {
    ContourSolution s =
        solveContour(contourOf("START Z0 X0\nLINE Z0 X20\nCF 1.5\nLINE Z-30 X20\n"));
    ASSERT_TRUE(s.complete());
    expectPoint(s.path[0].end, 0, 18.5);
    expectPoint(s.path[1].end, -1.5, 20);
}

TEST(GneSolver, RoundingBetweenLineAndArc) {
    ContourSolution s =
        solveContour(contourOf("START Z0 X20\nLINE Z-20\nRD 1\nCW Z-30 X30 K-30 I20\n"));
    ASSERT_TRUE(s.complete()) << s.diagnostics[0].message;
    const Segment& round = s.path[1];
    EXPECT_NEAR((round.centre - Point(-30, 20)).norm(), 10 + 1, 1e-6);  // tangent outside
    EXPECT_NEAR(round.radius(), 1.0, 1e-6);
}

TEST(GneSolver, RoundingTooLargeIsImpossible) {
    ContourSolution s = solveContour(contourOf("START Z0 X0\nLINE Z0 X5\nRD 8\nLINE Z-30 X5\n"));
    EXPECT_EQ(s.elements[2].state, ElementState::Impossible);
    EXPECT_FALSE(s.complete());
}

TEST(GneSolver, ReliefDin509FormE) {
    ContourSolution s = solveContour(contourOf(
        "START Z0 X10\nLINE Z-30 X10\nRELIEF E R0.6 T0.2\nLINE Z-30 X20\nLINE Z-50 X20\n"));
    ASSERT_TRUE(s.complete()) << s.diagnostics[0].message;
    const auto& relief = s.elements[2].segments;
    ASSERT_EQ(relief.size(), 3u);               // ramp, bottom, radius
    expectPoint(relief[0].start, -28, 10);      // width f = 2
    EXPECT_NEAR(relief[1].end.y(), 9.8, 1e-9);  // depth t1 = 0.2
    EXPECT_NEAR(relief[2].radius(), 0.6, 1e-9);
    expectPoint(relief[2].end, -30, 10.4);  // runs into the face above the cylinder
    expectPoint(s.path.back().start, -30, 20);
}

TEST(GneSolver, ReliefNeedsKnownSizeOrWidth) {
    ContourSolution s =
        solveContour(contourOf("START Z0 X10\nLINE Z-30 X10\nRELIEF E R0.7 T0.2\nLINE Z-30 X20\n"));
    EXPECT_EQ(s.elements[2].state, ElementState::Impossible);
    EXPECT_TRUE(
        solveContour(
            contourOf("START Z0 X10\nLINE Z-30 X10\nRELIEF F R0.7 T0.2 W3 U0.1\nLINE Z-30 X20\n"))
            .complete());
}

}  // namespace
}  // namespace mtc::core::gne
