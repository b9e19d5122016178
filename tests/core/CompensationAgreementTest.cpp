// The compiler's look-ahead TRC (LA_ON ... LA_OFF, decision LA-011) and the
// interpreter's radius compensation G41/G42 (decision TC-005) offset the same
// contour the same way where they overlap (issue 18 §1): between the start-up
// and the cancel, every element, every inserted corner arc and every inside
// corner intersection agrees to 1e-9 mm. Where they differ by design (the
// lead-in and lead-out lines of the compiler, the start-up and cancel moves
// of the interpreter, reversals) is left out.
#include <gtest/gtest.h>

#include <vector>

#include "cnc_core/compensation/RadiusCompensation.h"
#include "cnc_core/compiler/lookahead/RadiusCorrection.h"
#include "tests/core/LookAheadTestSupport.h"

namespace {

namespace la = mtc::core::lookahead;
namespace comp = mtc::core::comp;
using la::testing::point;

constexpr double kTol = 1e-9;
constexpr double kRadius = 2.0;

/// One contour element in the plane: a line, or an arc with its centre.
struct Element {
    comp::PathKind kind;
    double x0, y0, x1, y1, cx = 0.0, cy = 0.0;
};

/// Inside and outside corners for both sides, lines and arcs, tangent joins.
const std::vector<Element> kContour = {
    {comp::PathKind::Line, 0, 0, 20, 0},
    {comp::PathKind::Line, 20, 0, 20, 15},             // left turn
    {comp::PathKind::Line, 20, 15, 35, 15},            // right turn
    {comp::PathKind::ArcCcw, 35, 15, 45, 25, 35, 25},  // tangent
    {comp::PathKind::Line, 45, 25, 45, 40},            // tangent
    {comp::PathKind::Line, 45, 40, 30, 40},            // left turn
    {comp::PathKind::ArcCw, 30, 40, 20, 50, 30, 50},   // tangent into a circle
    {comp::PathKind::ArcCcw, 20, 50, 10, 60, 10, 50},  // circle to circle, tangent
    {comp::PathKind::Line, 10, 60, 0, 45},             // left turn after a circle
    {comp::PathKind::Line, 0, 45, -10, 45},            // right turn
};

la::PathElement compilerElement(const Element& e) {
    if (e.kind == comp::PathKind::Line)
        return la::testing::line(point({e.x0, e.y0, 0}), point({e.x1, e.y1, 0}), 1000);
    return la::testing::arc(point({e.x0, e.y0, 0}), point({e.x1, e.y1, 0}), point({e.cx, e.cy, 0}),
                            e.kind == comp::PathKind::ArcCw, 1000);
}

comp::PlanePath planePath(const Element& e) {
    comp::PlanePath p;
    p.kind = e.kind;
    p.start = {e.x0, e.y0};
    p.end = {e.x1, e.y1};
    p.centre = {e.cx, e.cy};
    return p;
}

/// The interpreter's engine: a start-up line to the contour's start, the
/// contour, a cancel line away from its end. Returns the tool path pieces
/// between start-up and cancel.
std::vector<comp::ToolPiece> interpreterPath(comp::Side side) {
    comp::RadiusCompensation engine;
    std::vector<comp::ToolPiece> pieces;
    int id = 0;
    auto feed = [&](const comp::PlanePath& path, comp::Side s) {
        comp::ContourMove m;
        m.path = path;
        m.side = s;
        m.radius = kRadius;
        m.id = ++id;
        comp::Release release;
        comp::Problem problem;
        EXPECT_TRUE(engine.apply(m, release, problem)) << (problem.code ? problem.code : "");
        for (int i = 0; i < release.count; ++i)
            pieces.push_back(release.pieces[static_cast<std::size_t>(i)]);
    };
    feed(planePath({comp::PathKind::Line, -10, 0, 0, 0}), side);  // start-up
    for (const Element& e : kContour)
        feed(planePath(e), side);
    feed(planePath({comp::PathKind::Line, -10, 45, -10, 60}), comp::Side::None);  // cancel
    EXPECT_GE(pieces.size(), 2u);
    if (pieces.size() < 2) return {};
    return {pieces.begin() + 1, pieces.end() - 1};
}

/// The compiler's TRC of the same contour (ADTRC 0), without its lead lines.
std::vector<la::PathElement> compilerPath(int trc) {
    std::vector<la::PathElement> contour;
    for (const Element& e : kContour)
        contour.push_back(compilerElement(e));
    la::RadiusCorrectionSettings settings;
    settings.radius = kRadius;
    settings.side = trc;
    const la::CorrectedPolygon result = la::correctToolRadius(contour, settings);
    EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.problems.front().code);
    std::vector<la::PathElement> path;
    for (const la::PathElement& e : result.elements)
        if (e.generated == 0 || e.generated == la::kCornerArc) path.push_back(e);
    return path;
}

comp::PathKind kindOf(const la::PathElement& e) {
    switch (e.kind) {
        case la::ElementKind::ArcCw:
            return comp::PathKind::ArcCw;
        case la::ElementKind::ArcCcw:
            return comp::PathKind::ArcCcw;
        default:
            return comp::PathKind::Line;
    }
}

void expectSame(const la::AxisVector& compiler, const comp::Vec2& interpreter, const char* what,
                std::size_t k) {
    EXPECT_NEAR(compiler[0], interpreter.x(), kTol) << what << " of element " << k;
    EXPECT_NEAR(compiler[1], interpreter.y(), kTol) << what << " of element " << k;
}

void expectAgreement(comp::Side side, int trc) {
    const std::vector<comp::ToolPiece> interpreter = interpreterPath(side);
    const std::vector<la::PathElement> compiler = compilerPath(trc);
    ASSERT_EQ(interpreter.size(), compiler.size());
    int corners = 0;
    for (std::size_t k = 0; k < compiler.size(); ++k) {
        const la::PathElement& c = compiler[k];
        const comp::ToolPiece& i = interpreter[k];
        EXPECT_EQ(kindOf(c), i.path.kind) << "element " << k;
        EXPECT_EQ(c.generated == la::kCornerArc, i.inserted) << "element " << k;
        corners += i.inserted ? 1 : 0;
        expectSame(c.start, i.path.start, "start", k);
        expectSame(c.end, i.path.end, "end", k);
        if (i.path.isArc()) expectSame(c.center, i.path.centre, "centre", k);
    }
    EXPECT_GE(corners, 2) << "the contour has outside corners on either side";
}

TEST(CompensationAgreement, CompilerTrcLeftAndG41GiveTheSameToolPath) {
    expectAgreement(comp::Side::Left, 1);
}

TEST(CompensationAgreement, CompilerTrcRightAndG42GiveTheSameToolPath) {
    expectAgreement(comp::Side::Right, 2);
}

}  // namespace
