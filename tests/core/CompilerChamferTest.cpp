// Chamfers and roundings (seed 001 ch. 2): exact geometry (tangency points,
// radii, directions) for line/line, line/arc and arc/arc in every plane, the
// boundary conditions and the reduction of sizes that do not fit.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "CompilerTestSupport.h"
#include "cnc_core/compiler/CornerGeometry.h"

using namespace mtc::core;
using namespace mtc::test;

namespace {

constexpr double kTol = 1e-9;

double crossOf(const Point2& a, const Point2& b) {
    return a.x() * b.y() - a.y() * b.x();
}

/// Checks a rounding: the arc of radius `fit.applied` touches both elements
/// at pointA/pointB (on the element, same tangent direction).
void expectTangentRounding(const PathElement& a, const PathElement& b, const CornerFit& fit) {
    const double r = fit.applied;
    EXPECT_NEAR((fit.pointA - fit.center).norm(), r, 1e-7);
    EXPECT_NEAR((fit.pointB - fit.center).norm(), r, 1e-7);
    const double sa = a.parameterOf(fit.pointA), sb = b.parameterOf(fit.pointB);
    EXPECT_NEAR((a.pointAt(sa) - fit.pointA).norm(), 0.0, 1e-7);
    EXPECT_NEAR((b.pointAt(sb) - fit.pointB).norm(), 0.0, 1e-7);
    const PathElement arc = PathElement::circle(fit.pointA, fit.pointB, fit.center, fit.ccw);
    EXPECT_NEAR((arc.tangentAt(0.0) - a.tangentAt(sa)).norm(), 0.0, 1e-6);
    EXPECT_NEAR((arc.tangentAt(arc.length()) - b.tangentAt(sb)).norm(), 0.0, 1e-6);
    EXPECT_LT(arc.sweep(), 3.14159265358979);  // the short way round the corner
}

TEST(CornerGeometry, LineLineRoundingLeftTurn) {
    const PathElement a = PathElement::line({0, 0}, {20, 0});
    const PathElement b = PathElement::line({20, 0}, {20, 20});
    const CornerFit fit = fitCorner(CornerKind::Rounding, a, 0.0, b, 5.0);
    EXPECT_FALSE(fit.reduced);
    EXPECT_NEAR((fit.pointA - Point2(15, 0)).norm(), 0.0, kTol);
    EXPECT_NEAR((fit.pointB - Point2(20, 5)).norm(), 0.0, kTol);
    EXPECT_NEAR((fit.center - Point2(15, 5)).norm(), 0.0, kTol);
    EXPECT_TRUE(fit.ccw);
    expectTangentRounding(a, b, fit);
}

TEST(CornerGeometry, LineLineRoundingRightTurnIsClockwise) {
    const PathElement a = PathElement::line({0, 0}, {10, 10});
    const PathElement b = PathElement::line({10, 10}, {20, 0});
    const CornerFit fit = fitCorner(CornerKind::Rounding, a, 0.0, b, 2.0);
    EXPECT_FALSE(fit.ccw);
    // 90 degree corner: tangent length = r
    EXPECT_NEAR((fit.pointA - Point2(10, 10)).norm(), 2.0, kTol);
    EXPECT_NEAR((fit.center - Point2(10, 10 - 2 * std::sqrt(2.0))).norm(), 0.0, kTol);
    expectTangentRounding(a, b, fit);
}

TEST(CornerGeometry, ChamferRemovesTheWidthFromBothElements) {
    const PathElement a = PathElement::line({0, 0}, {0, 30});
    const PathElement b = PathElement::line({0, 30}, {40, 30});
    const CornerFit fit = fitCorner(CornerKind::Chamfer, a, 0.0, b, 3.0);
    EXPECT_NEAR((fit.pointA - Point2(0, 27)).norm(), 0.0, kTol);
    EXPECT_NEAR((fit.pointB - Point2(3, 30)).norm(), 0.0, kTol);
}

TEST(CornerGeometry, ChamferOnAnArcMeasuresAlongTheArc) {
    const PathElement a = PathElement::line({0, 0}, {10, 0});
    const PathElement b = PathElement::circle({10, 0}, {20, 10}, {20, 0}, true);  // 1/4 circle
    const CornerFit fit = fitCorner(CornerKind::Chamfer, a, 0.0, b, 2.0);
    EXPECT_NEAR(b.parameterOf(fit.pointB), 2.0, 1e-9);
    EXPECT_NEAR((fit.pointB - b.pointAt(2.0)).norm(), 0.0, kTol);
    EXPECT_NEAR((fit.pointB - Point2(20, 0)).norm(), 10.0, 1e-9);
}

TEST(CornerGeometry, LineArcAndArcArcRoundingsAreTangent) {
    // line into a clockwise arc with a bend
    const PathElement line = PathElement::line({0, 0}, {10, 0});
    const PathElement cw = PathElement::circle({10, 0}, {20, 0}, {15, -5}, false);
    CornerFit fit = fitCorner(CornerKind::Rounding, line, 0.0, cw, 1.5);
    EXPECT_FALSE(fit.reduced);
    // a left turn into a clockwise arc: the rounding lies outside the arc
    EXPECT_NEAR((fit.center - cw.center).norm(), cw.radius + 1.5, 1e-7);
    expectTangentRounding(line, cw, fit);
    // arc into arc
    const PathElement ccw = PathElement::circle({0, 0}, {10, 10}, {10, 0}, false);
    const PathElement next = PathElement::circle({10, 10}, {20, 0}, {10, 0}, false);
    ASSERT_GT(std::fabs(crossOf(ccw.tangentAt(ccw.length()), next.tangentAt(0))), -1.0);
    const PathElement bent = PathElement::circle({10, 10}, {10, 20}, {15, 15}, true);
    fit = fitCorner(CornerKind::Rounding, ccw, 0.0, bent, 1.0);
    EXPECT_FALSE(fit.reduced);
    expectTangentRounding(ccw, bent, fit);
}

TEST(CornerGeometry, RandomCornersAreTangentOrReduced) {
    std::mt19937 random(17);
    std::uniform_real_distribution<double> coordinate(-50, 50), size(0.1, 8);
    std::bernoulli_distribution coin(0.5);
    int checked = 0;
    for (int i = 0; i < 3000; ++i) {
        const Point2 s(coordinate(random), coordinate(random));
        const Point2 p(coordinate(random), coordinate(random));
        const Point2 e(coordinate(random), coordinate(random));
        auto makeElement = [&](const Point2& from, const Point2& to) {
            if (coin(random)) return PathElement::line(from, to);
            const Point2 mid = (from + to) / 2, d = to - from;
            const Point2 centre = mid + Point2(-d.y(), d.x()) * (coordinate(random) / 50.0);
            return PathElement::circle(from, to, centre, coin(random));
        };
        const PathElement a = makeElement(s, p), b = makeElement(p, e);
        if (a.length() < 1e-3 || b.length() < 1e-3) continue;
        const double requested = size(random);
        const CornerFit fit = fitCorner(CornerKind::Rounding, a, 0.0, b, requested);
        EXPECT_LE(fit.applied, requested + 1e-12);
        if (fit.applied > 0.0) {
            expectTangentRounding(a, b, fit);
            ++checked;
        }
        const CornerFit chamfer = fitCorner(CornerKind::Chamfer, a, 0.0, b, requested);
        if (chamfer.applied > 0.0) {
            EXPECT_NEAR(a.length() - a.parameterOf(chamfer.pointA), chamfer.applied, 1e-6);
            EXPECT_NEAR(b.parameterOf(chamfer.pointB), chamfer.applied, 1e-6);
        }
    }
    EXPECT_GT(checked, 1000);
}

TEST(CornerGeometry, TooLargeIsReducedToWhatFitsAndStraightCornersToZero) {
    const PathElement a = PathElement::line({0, 0}, {4, 0});
    const PathElement b = PathElement::line({4, 0}, {4, 10});
    const CornerFit fit = fitCorner(CornerKind::Rounding, a, 0.0, b, 6.0);
    EXPECT_TRUE(fit.reduced);
    EXPECT_NEAR(fit.applied, 4.0, 1e-4);
    const CornerFit chamfer = fitCorner(CornerKind::Chamfer, a, 1.0, b, 6.0);
    EXPECT_NEAR(chamfer.applied, 3.0, 1e-4);
    const PathElement straight = PathElement::line({4, 0}, {9, 0});
    const CornerFit none = fitCorner(CornerKind::Rounding, a, 0.0, straight, 1.0);
    EXPECT_TRUE(none.reduced);
    EXPECT_EQ(none.applied, 0.0);
}

// ------------------------------------------------------------ whole programs

TEST(CompilerChamfer, EveryPlaneGetsTheRightAxesCentresAndDirection) {
    const CompileResult r = compileText(
        "N0001 G18 G90 G1 Z0 X0 F500\nN0002 Z-20 RD3\nN0003 X10\n"
        "N0004 G19 Y0 Z0\nN0005 Y10 RD2\nN0006 Z10\n"
        "N0007 G17 X0 Y0 Z0\nN0008 G20 X0 Z0 Y0\nN0009 X10 RD1\nN0010 Z10\n");
    ASSERT_EQ(r.status, CompileStatus::Compiled);
    const std::vector<std::string> b = objectBlocks(r);
    ASSERT_EQ(b.size(), 13u);
    EXPECT_EQ(b[1], "N0002:0000 Z-17 X0");
    EXPECT_EQ(b[2], "N0002:0001 G2 Z-20 X3 K-17 I3");  // right turn in (Z, X)
    EXPECT_EQ(b[3], "N0003:0000 G1 X10");
    EXPECT_EQ(b[5], "N0005:0000 Y8 Z0");
    EXPECT_EQ(b[6], "N0005:0001 G3 Y10 Z2 J8 K2");  // left turn in (Y, Z)
    EXPECT_EQ(b[10], "N0009:0000 X9 Z0");
    EXPECT_EQ(b[11], "N0009:0001 G3 X10 Z1 I9 J1");  // G20: I, J on the 1st and 2nd axis
}

TEST(CompilerChamfer, IncrementalAndDiameterProgramming) {
    const CompileResult r = compileText(
        "N0001 G18 G1 Z0 X0 F100\nN0002 G91 Z-10 CF1\nN0003 X5\n"
        "N0004 G90 G16 X0 Z0\nN0005 X20 CF1\nN0006 Z-10\n");
    ASSERT_EQ(r.status, CompileStatus::Compiled);
    const std::vector<std::string> b = objectBlocks(r);
    EXPECT_EQ(b[1], "N0002:0000 G91 Z-9 X0");
    EXPECT_EQ(b[2], "N0002:0001 G1 Z-1 X1");
    EXPECT_EQ(b[3], "N0003:0000 Z0 X4");
    EXPECT_EQ(b[5], "N0005:0000 Z0 X18");  // diameter 18 = radius 9
    EXPECT_EQ(b[6], "N0005:0001 G1 Z-1 X20");
}

TEST(CompilerChamfer, SeparateBlockAndNonMotionBlocksInBetween) {
    const CompileResult r =
        compileText("N0001 G1 X0 Y0 F100\nN0002 X10\nN0003 CF2\nN0004 M8\nN0005 M9\nN0006 Y10\n");
    ASSERT_EQ(r.status, CompileStatus::Compiled);
    EXPECT_EQ(objectBlocks(r),
              (std::vector<std::string>{"N0001:0000 G1 X0 Y0 F100", "N0002:0000 X8 Y0",
                                        "N0003:0000", "N0003:0001 G1 X10 Y2", "N0004:0000 M8",
                                        "N0005:0000 M9", "N0006:0000 Y10"}));
}

TEST(CompilerChamfer, InstructionInTheSecondMotionBlockBelongsToTheNextCorner) {
    const CompileResult r =
        compileText("N0001 G1 X0 Y0 F100\nN0002 X10\nN0003 Y10 RD1\nN0004 X0\n");
    ASSERT_EQ(r.status, CompileStatus::Compiled);
    const std::vector<std::string> b = objectBlocks(r);
    EXPECT_EQ(b[1], "N0002:0000 X10");  // the corner N0002/N0003 stays sharp
    EXPECT_EQ(b[2], "N0003:0000 X10 Y9");
    EXPECT_EQ(b[3], "N0003:0001 G3 X9 Y10 I9 J9");
}

TEST(CompilerChamfer, TwentyBlocksBetweenAreAllowedTwentyOneAreNot) {
    auto program = [](int between) {
        std::string text = "N0000 G1 X0 Y0 F100\nN0001 X10 RD1\n";
        for (int i = 0; i < between; ++i)
            text += "N" + std::to_string(1000 + i) + " M8\n";
        return text + "N0099 Y10\n";
    };
    EXPECT_EQ(compileText(program(20)).status, CompileStatus::Compiled);
    const CompileResult r = compileText(program(21));
    EXPECT_EQ(codes(r), std::vector<std::string>{"COMPILER_CFRD_NO_TARGET"});
    EXPECT_EQ(r.errors[0].block, "N0001");
}

TEST(CompilerChamfer, IllegalFunctionsBetweenTheMotionBlocks) {
    for (const char* between : {"G17", "G54", "G91", "G71", "G16", "G31", "G72", "G74", "G78",
                                "BRA .NEXT", ".LABEL M8", "BSR .SUB", "JSR 3"}) {
        const CompileResult r = compileText(std::string("N0001 G1 X0 Y0 F100\nN0002 X10 RD1\n"
                                                        "N0003 ") +
                                            between + "\nN0004 Y10\nN0005 .NEXT M30\n");
        EXPECT_EQ(codes(r), std::vector<std::string>{"COMPILER_CFRD_ILLEGAL"}) << between;
    }
}

// A G number no int holds is no G function the scan knows: it is left to
// the interpreter, which refuses it (converting it was undefined behaviour;
// on x86 it became INT_MIN, "a computed G function"). G1e308 or G1.5
// never get here: the parser refuses them (PARSE_BAD_NUMBER, LEX_BAD_CHAR).
TEST(CompilerChamfer, GNumbersBeyondIntAreNoFunctionOfTheScan) {
    for (const char* g : {"G8888888888", "G4294967297"}) {
        const CompileResult r = compileText(
            std::string("N0001 G1 X0 Y0 F100\nN0002 X10 RD1\nN0003 ") + g + " M8\nN0004 Y10\n");
        EXPECT_EQ(r.status, CompileStatus::Compiled) << g;
        EXPECT_TRUE(codes(r).empty()) << g << ": " << (codes(r).empty() ? "" : codes(r)[0]);
    }
}

TEST(CompilerChamfer, BoundaryConditionErrors) {
    auto firstCode = [](const std::string& text) {
        const CompileResult r = compileText(text);
        return r.errors.empty() ? std::string("none") : r.errors[0].code;
    };
    EXPECT_EQ(firstCode("N1 G1 X0 Y0\nN2 X=@1 RD1\nN3 Y10\n"), "COMPILER_CFRD_VARIABLE");
    EXPECT_EQ(firstCode("N1 G1 X0 Y0\nN2 X10 RD1\nN3 Y@2\n"), "COMPILER_CFRD_VARIABLE");
    EXPECT_EQ(firstCode("N1 G0 X0 Y0\nN2 X10 RD1\nN3 Y10\n"), "COMPILER_CFRD_NOT_CONTOUR");
    EXPECT_EQ(firstCode("N1 G1 X0 Y0 Z0\nN2 X10 RD1\nN3 Y10 Z4\n"), "COMPILER_CFRD_OUT_OF_PLANE");
    EXPECT_EQ(firstCode("N1 G1 X10 RD1\nN2 Y10\n"), "COMPILER_CFRD_START_UNKNOWN");
    EXPECT_EQ(firstCode("N1 G1 X0 Y0\nN2 M8\nN3 RD1\nN4 Y10\n"),
              "COMPILER_CFRD_NO_PRECEDING_MOTION");
    EXPECT_EQ(firstCode("N1 G1 X0 Y0\nN2 X10 RD1 CF1\nN3 Y10\n"), "COMPILER_CFRD_TWICE");
    EXPECT_EQ(firstCode("N1 G1 X0 Y0\nN2 X10 RD=-1\nN3 Y10\n"), "COMPILER_CFRD_VALUE");
    EXPECT_EQ(firstCode("N1 G1 X0 Y0\nN2 X10 RD1\nN3 M30\n"), "COMPILER_CFRD_NO_TARGET");
    EXPECT_EQ(firstCode("N1 G1 X0 Y0\nN2 G2 X10 Y0 I5 J1 RD1\nN3 Y10\n"),
              "COMPILER_CFRD_BAD_ELEMENT");
}

TEST(CompilerChamfer, ReductionIsAWarningWithTheAppliedValue) {
    const CompileResult r = compileText("N0001 G1 X0 Y0 F100\nN0002 X4 RD6\nN0003 Y10\n");
    ASSERT_EQ(r.status, CompileStatus::Compiled);
    ASSERT_EQ(codes(r), std::vector<std::string>{"COMPILER_CFRD_REDUCED"});
    EXPECT_EQ(r.errors[0].severity, Severity::Warning);
    EXPECT_EQ(r.errors[0].message, "RD reduced to 4.");
    EXPECT_EQ(r.errors[0].details.back(), "Applied value: 4.");
    EXPECT_EQ(objectBlocks(r)[2], "N0002:0001 G3 X4 Y4 I0 J4");
}

TEST(CompilerChamfer, StraightCornerInsertsNothingButWarns) {
    const CompileResult r = compileText("N0001 G1 X0 Y0 F100\nN0002 X4 CF1\nN0003 X9\n");
    ASSERT_EQ(r.status, CompileStatus::Compiled);
    EXPECT_EQ(codes(r), std::vector<std::string>{"COMPILER_CFRD_REDUCED"});
    EXPECT_EQ(objectBlocks(r), (std::vector<std::string>{"N0001:0000 G1 X0 Y0 F100",
                                                         "N0002:0000 X4", "N0003:0000 X9"}));
}

TEST(CompilerChamfer, ConsecutiveCornersShareTheElementBetweenThem) {
    const CompileResult r =
        compileText("N0001 G1 X0 Y0 F100\nN0002 X10 RD3\nN0003 Y4 RD3\nN0004 X0\n");
    ASSERT_EQ(r.status, CompileStatus::Compiled);
    ASSERT_EQ(codes(r), std::vector<std::string>{"COMPILER_CFRD_REDUCED"});
    EXPECT_EQ(r.errors[0].block, "N0003");
    EXPECT_EQ(r.errors[0].message, "RD reduced to 1.");  // 4 - 3 left of N0003
}

TEST(CompilerChamfer, MessagesNameTheIllegalFunctionAndTheElementProblem) {
    auto details = [](const std::string& text) {
        const CompileResult r = compileText(text);
        std::string joined;  // the detail lines are wrapped at 65 characters
        for (const std::string& line :
             r.errors.empty() ? std::vector<std::string>{} : r.errors[0].details)
            joined += line + " ";
        return joined;
    };
    EXPECT_NE(details("N1 G1 X0 Y0\nN2 X10 RD1\nN3 G18\nN4 Y10\n").find("a change of plane (G18)"),
              std::string::npos);
    EXPECT_NE(
        details("N1 G1 X0 Y0\nN2 X10 RD1\nN3 G=@1\nN4 Y10\n").find("a computed G function (G=)"),
        std::string::npos);
    EXPECT_NE(details("N1 G1 X0 Y0\nN2 X10 RD1\nN3 .MARK M8\nN4 Y10\n").find("a jump label"),
              std::string::npos);
    EXPECT_NE(details("N1 G1 X0 Y0\nN2 G2 X10 Y0 I5 J1 RD1\nN3 Y10\n")
                  .find("N0003: the circle's start point is its centre."),
              std::string::npos);
    EXPECT_NE(details("N1 G1 X0 Y0\nN2 G2 X10 Y0 I4 J0 RD1\nN3 G1 Y10\n")
                  .find("N0002: start and end point are not on one circle."),
              std::string::npos);
    EXPECT_NE(
        details("N1 G1 X0 Y0\nN2 X0 RD1\nN3 Y10\n").find("the block does not move in the plane."),
        std::string::npos);
    EXPECT_NE(details("N1 G1 X0 Y0\nN2 X10 RD=@3\nN3 Y10\n").find("must be a number"),
              std::string::npos);
}

TEST(CompilerChamfer, EveryCornerOfAZigZagGetsItsBlockRightAfterItsOwnBlock) {
    std::string text = "N0001 G1 X0 Y0 F100\n";
    for (int i = 2; i <= 9; ++i)
        text += "N000" + std::to_string(i) + (i % 2 ? " Y" : " X") + std::to_string(10 * i) +
                (i < 9 ? (i % 2 ? " CF1" : " RD1") : "") + "\n";
    const CompileResult r = compileText(text);
    ASSERT_EQ(r.status, CompileStatus::Compiled);
    const std::vector<std::string> b = objectBlocks(r);
    ASSERT_EQ(b.size(), 16u);  // 9 blocks and 7 corners
    for (int i = 2; i <= 8; ++i) {
        const std::string number = "N000" + std::to_string(i);
        EXPECT_EQ(b[static_cast<std::size_t>(2 * i - 3)].substr(0, 10), number + ":0000");
        EXPECT_EQ(b[static_cast<std::size_t>(2 * i - 2)].substr(0, 13),
                  number + ":0001 " + (i % 2 ? "G1" : "G3"));
    }
    EXPECT_EQ(b.back().substr(0, 10), "N0009:0000");
}

// Every spelling of the same value gives the same object program (the
// plain decimal is read directly, the others by readNumberPrefix).
TEST(CompilerChamfer, SpellingsOfOneValueGiveOneObject) {
    const auto object = [](const std::string& corner) {
        const CompileResult r =
            compileText("N0001 G1 X0 Y0 F100\nN0002 X10 " + corner + "\nN0003 Y10\n");
        EXPECT_EQ(r.status, CompileStatus::Compiled) << corner;
        return r.objectText;
    };
    for (const char* kind : {"RD", "CF"}) {
        const std::string k(kind);
        const std::string expected = object(k + "1.5");
        for (const char* value : {"=1.5", " 1.5", "1.50", "01.5", "1.5e0", "15e-1",
                                  "1.500000000000000", "0000000000000001.5", "= 1.5 "})
            EXPECT_EQ(object(k + value), expected) << k + value;
        EXPECT_EQ(object(k + ".5"), object(k + "0.5"));
        EXPECT_EQ(object(k + "2."), object(k + "2"));
    }
}

// A block after a corner keeps its text, blanks squeezed (also when its
// motion stays as written).
TEST(CompilerChamfer, BlocksAfterACornerHaveTheirBlanksSqueezed) {
    const CompileResult r =
        compileText("N0001 G1 X0 Y0 F100\nN0002 X10 CF1\nN0003 Y10  F200   M8 ;a  b\nN0004 X0\n");
    ASSERT_EQ(r.status, CompileStatus::Compiled);
    const std::vector<std::string> b = objectBlocks(r);
    ASSERT_EQ(b.size(), 5u);
    EXPECT_EQ(b[3], "N0003:0000 Y10 F200 M8 ;a  b");
}

}  // namespace
