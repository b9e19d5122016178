// Coarse copy of the toolpath for the moving view (TP-010): runs of one
// chain and one kind simplified within the tolerance, the cell budget kept
// (tolerance grows, kinds joined, runs left out as the last resort), and
// picking through the coarse copy finds the same segment as measuring all.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cnc_core/toolpath/ToolpathDecimation.h"
#include "cnc_core/toolpath/ToolpathPick.h"

namespace {

using namespace mtc::core;
using Point = std::array<double, 3>;

/// A geometry of one move per segment along `points` (one chain), the kind
/// of segment i from `kindOf(i)`.
template <typename KindOf>
ToolpathGeometry chain(const std::vector<Point>& points, KindOf kindOf) {
    ToolpathGeometry g;
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        ToolpathMove move;
        move.block = static_cast<std::uint32_t>(i);
        move.kind = kindOf(i);
        move.firstScene = static_cast<std::uint32_t>(g.scene.segmentCount());
        g.moves.push_back(move);
        g.scene.addSegment(points[i], points[i + 1]);
    }
    return g;
}

ToolpathGeometry allFeed(const std::vector<Point>& points) {
    return chain(points, [](std::size_t) { return ToolpathKind::Feed; });
}

/// A wave of `count` segments over 100 mm (amplitude 5 mm, 7 periods).
std::vector<Point> wave(int count) {
    std::vector<Point> points;
    for (int i = 0; i <= count; ++i) {
        const double x = 100.0 * i / count;
        points.push_back({x, 5.0 * std::sin(x / 100.0 * 7 * 2 * M_PI), 0.0});
    }
    return points;
}

/// Every segment of the layer is in exactly one cell, in order, with its kind.
void expectCoversEverySegmentOnce(const ToolpathGeometry& g, const DecimatedLayer& d) {
    std::uint32_t next = 0;
    for (std::size_t c = 0; c < d.cellCount(); ++c) {
        const auto [first, last] = d.segmentsOf(c);
        ASSERT_EQ(first, next) << "cell " << c;
        ASSERT_LT(first, last);
        EXPECT_EQ(d.ends[2 * c], g.scene.segmentStart[first]);
        EXPECT_EQ(d.ends[2 * c + 1], g.scene.segmentStart[last - 1] + 1);
        next = last;
    }
    EXPECT_EQ(next, g.scene.segmentCount());
}

/// Every vertex a cell leaves out lies within the tolerance of the cell.
void expectWithinTolerance(const ToolpathGeometry& g, const DecimatedLayer& d) {
    for (std::size_t c = 0; c < d.cellCount(); ++c) {
        const auto a = g.scene.vertex(d.ends[2 * c]), b = g.scene.vertex(d.ends[2 * c + 1]);
        for (std::uint32_t v = d.ends[2 * c] + 1; v < d.ends[2 * c + 1]; ++v)
            ASSERT_LE(distanceToSegment(g.scene.vertex(v), a, b), d.tolerance + 1e-9)
                << "cell " << c << " vertex " << v;
    }
}

TEST(ToolpathDecimation, CollinearRunsBecomeOneCellPerRunOfOneKind) {
    std::vector<Point> points;
    for (int i = 0; i <= 1000; ++i)
        points.push_back({0.1 * i, 0.0, 0.0});
    const auto g = chain(points, [](std::size_t i) {
        return i % 100 == 0 ? ToolpathKind::Rapid : ToolpathKind::Feed;
    });
    const DecimatedLayer d = decimateLayer(g, false, 0.01, 1000);
    ASSERT_EQ(d.cellCount(), 20u);  // per 100 segments: 1 rapid, then 99 feed in one cell
    EXPECT_EQ(d.kinds[0], ToolpathKind::Rapid);
    EXPECT_EQ(d.kinds[1], ToolpathKind::Feed);
    EXPECT_EQ(d.segmentsOf(1), std::make_pair(1u, 100u));
    EXPECT_DOUBLE_EQ(d.tolerance, 0.01);
    EXPECT_FALSE(d.dropped);
    expectCoversEverySegmentOnce(g, d);
}

TEST(ToolpathDecimation, LongRunsAreCutIntoPiecesWithinTheBudget) {
    std::vector<Point> points;
    for (int i = 0; i <= 10000; ++i)
        points.push_back({0.01 * i, 0.0, 0.0});
    const auto g = allFeed(points);
    const DecimatedLayer pieces = decimateLayer(g, false, 0.01, 1000);
    EXPECT_EQ(pieces.cellCount(), 3u);  // 4096 + 4096 + 1808 segments
    expectCoversEverySegmentOnce(g, pieces);
    const DecimatedLayer tight = decimateLayer(g, false, 0.01, 4);
    EXPECT_LE(tight.cellCount(), 4u);  // pieces never more than half the budget
    EXPECT_FALSE(tight.dropped);
    expectCoversEverySegmentOnce(g, tight);
}

TEST(ToolpathDecimation, LeftOutVerticesStayWithinTheTolerance) {
    const auto g = allFeed(wave(20000));
    for (double tolerance : {0.001, 0.01, 0.1}) {
        const DecimatedLayer d = decimateLayer(g, false, tolerance, 20000);
        EXPECT_DOUBLE_EQ(d.tolerance, tolerance);
        EXPECT_LT(d.cellCount(), 20000u);
        expectCoversEverySegmentOnce(g, d);
        expectWithinTolerance(g, d);
    }
}

TEST(ToolpathDecimation, TheBudgetIsKeptByGrowingTheTolerance) {
    const auto g = allFeed(wave(20000));
    const DecimatedLayer d = decimateLayer(g, false, 0.001, 40);
    EXPECT_LE(d.cellCount(), 40u);
    EXPECT_GT(d.tolerance, 0.001);
    EXPECT_FALSE(d.dropped);
    expectCoversEverySegmentOnce(g, d);
    expectWithinTolerance(g, d);
}

TEST(ToolpathDecimation, KindsAreJoinedWhenTheirRunsAloneBreakTheBudget) {
    const auto g = chain(
        wave(1000), [](std::size_t i) { return i % 2 ? ToolpathKind::Arc : ToolpathKind::Feed; });
    const DecimatedLayer d = decimateLayer(g, false, 0.01, 100);
    EXPECT_LE(d.cellCount(), 100u);
    EXPECT_FALSE(d.dropped);
    expectCoversEverySegmentOnce(g, d);
    expectWithinTolerance(g, d);
}

TEST(ToolpathDecimation, APathThatRetracesItselfIsThinnedOutNotBlurred) {
    // 3000 passes over one circle of radius 10 mm, 64 chords each, each pass
    // its own chain (a contour programmed over and over). One cell per pass
    // would draw every pass as a single chord across the circle; the copy
    // keeps every n-th pass instead, at most 1/20 of the picture off (TP-010).
    ToolpathGeometry g;
    auto onCircle = [](int i, double z) {
        const double a = 2.0 * M_PI * i / 64.0;
        return Point{10.0 * std::cos(a), 10.0 * std::sin(a), z};
    };
    for (int pass = 0; pass < 3000; ++pass) {
        g.moves.push_back({0, static_cast<std::uint32_t>(pass), 0, ToolpathKind::Feed, 30, 0,
                           static_cast<std::uint32_t>(g.scene.segmentCount()), 0});
        for (int i = 0; i < 64; ++i)
            g.scene.addSegment(onCircle(i, 0.001 * pass), onCircle(i + 1, 0.001 * pass));
    }
    const DecimatedLayer d = decimateLayer(g, false, 0.01, 5000);
    EXPECT_TRUE(d.dropped);
    EXPECT_LE(d.tolerance, g.scene.bounds.size() / 20.0 + 1e-12);
    EXPECT_LE(d.cellCount(), 5000u);
    EXPECT_GE(d.cellCount(), 5000u / 8) << "thinned out more than the budget needs";
    expectWithinTolerance(g, d);
}

TEST(ToolpathDecimation, TooManyChainsKeepEveryNthRun) {
    ToolpathGeometry g;
    for (int i = 0; i < 1000; ++i) {  // 1000 separate dashes: 1000 chains
        g.moves.push_back({0, static_cast<std::uint32_t>(i), 0, ToolpathKind::Feed, 30, 0,
                           static_cast<std::uint32_t>(i), 0});
        g.scene.addSegment({1.0 * i, 0, 0}, {1.0 * i + 0.5, 0, 0});
    }
    const DecimatedLayer d = decimateLayer(g, false, 0.01, 100);
    EXPECT_EQ(d.cellCount(), 100u);
    EXPECT_TRUE(d.dropped);
    EXPECT_EQ(d.segmentsOf(1), std::make_pair(10u, 11u));
}

/// A top view of 0..100 mm onto 1000 x 1000 pixels (10 pixels per mm).
ScreenProjection topView() {
    ScreenProjection view;
    view.toNdc = {0.02, 0, 0, -1, 0, 0.02, 0, -1, 0, 0, 0.02, 0, 0, 0, 0, 1};
    view.width = view.height = 1000;
    return view;
}

/// Pixel distance of segment `s` from (x, y) in `view`.
double onScreen(const ToolpathGeometry& g, const ScreenProjection& view, std::uint32_t s, double x,
                double y) {
    const float* v = g.scene.xyz.data() + 3 * static_cast<std::size_t>(g.scene.segmentStart[s]);
    const auto a = view.pixel(v), b = view.pixel(v + 3);
    return distanceToSegment({x, y, 0}, {a[0], a[1], 0}, {b[0], b[1], 0});
}

TEST(ToolpathPick, CoarseCopyPicksTheSameSegmentAsMeasuringAll) {
    // Zigzag passes 0.3 mm apart of 0.25 mm segments with a wiggle: the
    // coarse copy (tolerance 0.1 mm = 1 pixel) joins each pass into a few cells.
    std::vector<Point> points;
    for (int pass = 0; pass < 40; ++pass)
        for (int step = 0; step <= 400; ++step) {
            const double x = pass % 2 ? 100.0 - step * 0.25 : step * 0.25;
            points.push_back({x, 40 + pass * 0.3 + (step % 2) * 0.004, 0});
        }
    const auto g = allFeed(points);
    const DecimatedLayer coarse = decimateLayer(g, false, 0.1, 5000);
    ASSERT_LT(coarse.cellCount(), g.scene.segmentCount() / 20);
    const ScreenProjection view = topView();
    EXPECT_EQ(view.pixel(g.scene.xyz.data())[0], 0.0);
    std::mt19937 random(8);
    std::uniform_real_distribution<double> px(0, 1000), py(390, 530);
    int picked = 0;
    for (int i = 0; i < 300; ++i) {
        const double x = px(random), y = py(random);
        const auto all = pickSegment(g.scene, DecimatedLayer{}, view, x, y, 6);
        const auto viaCoarse = pickSegment(g.scene, coarse, view, x, y, 6);
        ASSERT_EQ(all.has_value(), viaCoarse.has_value()) << x << " " << y;
        if (!all) continue;
        ++picked;
        // Same segment, or one exactly as near (they share the nearest vertex).
        if (*all != *viaCoarse) {
            EXPECT_NEAR(onScreen(g, view, *all, x, y), onScreen(g, view, *viaCoarse, x, y), 1e-9);
        }
    }
    EXPECT_GT(picked, 100);
    EXPECT_FALSE(pickSegment(g.scene, coarse, view, 500, 900, 6));  // far from every pass
}

TEST(ToolpathPick, ClickOnASegmentPicksIt) {
    const auto g = allFeed(wave(1000));
    const DecimatedLayer coarse = decimateLayer(g, false, 0.05, 200);
    const ScreenProjection view = topView();
    for (std::uint32_t s : {0u, 137u, 500u, 999u}) {
        float middle[3];
        for (int i = 0; i < 3; ++i)
            middle[i] = (g.scene.xyz[3 * g.scene.segmentStart[s] + i] +
                         g.scene.xyz[3 * (g.scene.segmentStart[s] + 1) + i]) /
                        2;
        const auto at = view.pixel(middle);
        EXPECT_EQ(pickSegment(g.scene, coarse, view, at[0], at[1], 6), s);
    }
}

}  // namespace
