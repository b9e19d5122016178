// The station's backplot (issue 19 §2, TP-016): the moves a program run has
// given the machine since Start and how far the axes have travelled along
// them, mid-block included; feed hold, Control reset and a new Start.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "InterpTestSupport.h"
#include "cnc_core/cell/Cell.h"

namespace mtc::test {
namespace {

using core::ControlKey;

struct TraceFixture {
    TraceFixture() : cell(demoCell()) { mill().setRunTracing(true); }
    core::Station& select(const std::string& source) {
        core::ProgramPtr program = cell.addProgram(0, 1, "trace.nc", source);
        EXPECT_FALSE(program->diagnostics.hasErrors()) << diagnosticsText(program->diagnostics);
        EXPECT_TRUE(mill().selectProgram(1));
        return mill();
    }
    core::Station& mill() { return cell.station(0); }
    const core::RunTrace& trace() { return mill().runTrace(); }
    /// The scene point where the travelled part of the trace ends.
    std::array<double, 3> tracedEnd() {
        const core::TracedExtent e = trace().extent(false);
        const auto& layer = trace().geometry().scene;
        if (e.share == 0.0) {
            EXPECT_GT(e.segments, 0u);
            return layer.vertex(layer.segmentStart[e.segments - 1] + 1);
        }
        const auto a = layer.vertex(layer.segmentStart[e.segments]);
        const auto b = layer.vertex(layer.segmentStart[e.segments] + 1);
        return {a[0] + (b[0] - a[0]) * e.share, a[1] + (b[1] - a[1]) * e.share,
                a[2] + (b[2] - a[2]) * e.share};
    }
    core::Cell cell;
};

constexpr const char* kSquare =
    "N0001 G1 G90 X0 Y0 Z0 F600\n"
    "N0002 X50\n"
    "N0003 Y50\n"
    "N0004 X0\n"
    "N0005 Y0\n"
    "N0006 M30\n";

TEST(RunTrace, EndsWhereTheAxesAreMidBlockAndGrowsWithTime) {
    TraceFixture f;
    core::Station& mill = f.select(kSquare);
    EXPECT_TRUE(f.trace().geometry().moves.empty());
    ASSERT_TRUE(mill.press(ControlKey::Start));
    std::size_t lastSegments = 0;
    double lastShare = 0.0;
    for (int tick = 0; tick < 200; ++tick) {  // 0.5 s ticks through the square
        mill.advance(0.5);
        const core::TracedExtent e = f.trace().extent(false);
        EXPECT_TRUE(e.segments > lastSegments ||
                    (e.segments == lastSegments && e.share >= lastShare))
            << "the travelled part never shrinks (tick " << tick << ")";
        lastSegments = e.segments;
        lastShare = e.share;
        if (!mill.busy()) break;
        const auto end = f.tracedEnd();
        for (int axis = 0; axis < 3; ++axis)
            EXPECT_NEAR(end[static_cast<std::size_t>(axis)], mill.machine().position(axis), 1e-3)
                << "tick " << tick << " axis " << axis;
    }
    EXPECT_FALSE(mill.busy());
    EXPECT_EQ(f.trace().doneMoves(), f.trace().geometry().moves.size());
    EXPECT_EQ(f.trace().extent(false).segments, f.trace().geometry().scene.segmentCount());
    EXPECT_GE(f.trace().geometry().scene.segmentCount(), 4u);
    const long current = f.trace().currentMove();
    ASSERT_GE(current, 0);
    EXPECT_EQ(f.trace().geometry().moves[static_cast<std::size_t>(current)].block, 4u)
        << "standing: the last move travelled (N0005)";
}

TEST(RunTrace, FeedHoldStopsItControlResetCutsItStartBeginsAnew) {
    TraceFixture f;
    core::Station& mill = f.select(kSquare);
    ASSERT_TRUE(mill.press(ControlKey::Start));
    mill.advance(6.0);  // into N0003 (5 s along X at 10 mm/s plus the ramps)
    const std::uint64_t run = f.trace().run();
    const long moving = f.trace().currentMove();
    ASSERT_GE(moving, 0);
    EXPECT_EQ(f.trace().geometry().moves[static_cast<std::size_t>(moving)].block, 2u);
    EXPECT_GT(f.trace().share(), 0.0);
    ASSERT_TRUE(mill.press(ControlKey::Stop));
    mill.advance(2.0);  // the axes brake on the path and stand
    const core::TracedExtent held = f.trace().extent(false);
    mill.advance(5.0);
    const core::TracedExtent stillHeld = f.trace().extent(false);
    EXPECT_EQ(stillHeld.segments, held.segments);
    EXPECT_EQ(stillHeld.share, held.share);
    ASSERT_TRUE(mill.press(ControlKey::Start));
    mill.advance(1.0);
    const core::TracedExtent resumed = f.trace().extent(false);
    EXPECT_TRUE(resumed.segments > held.segments ||
                (resumed.segments == held.segments && resumed.share > held.share));
    mill.press(ControlKey::ControlReset);
    const auto stopped = f.tracedEnd();
    mill.advance(5.0);
    const auto later = f.tracedEnd();
    EXPECT_EQ(later, stopped) << "after Control reset the trace ends where the axes stopped";
    for (int axis = 0; axis < 2; ++axis)
        EXPECT_NEAR(stopped[static_cast<std::size_t>(axis)], mill.machine().position(axis), 1e-3);
    ASSERT_TRUE(mill.press(ControlKey::Start));
    EXPECT_GT(f.trace().run(), run);
    EXPECT_EQ(f.trace().extent(false).segments, 0u) << "a new Start begins a new backplot";
    mill.advance(1.0);
    EXPECT_FALSE(f.trace().geometry().moves.empty());
}

TEST(RunTrace, OnlyAStationThatTracesKeepsIt) {
    core::Cell cell(demoCell());  // as the CLI has it: no backplot
    core::Station& mill = cell.station(0);
    cell.addProgram(0, 1, "trace.nc", kSquare);
    ASSERT_TRUE(mill.selectProgram(1));
    ASSERT_TRUE(mill.press(ControlKey::Start));
    mill.advance(3.0);
    EXPECT_EQ(mill.runTrace().run(), 0u);
    EXPECT_TRUE(mill.runTrace().geometry().moves.empty());
}

TEST(RunTrace, AnArcIsTravelledAlongItsChords) {
    TraceFixture f;
    core::Station& mill =
        f.select("N0001 G1 G90 G17 X0 Y0 Z0 F600\nN0002 G2 X20 Y0 I10 J0\nN0003 M30\n");
    ASSERT_TRUE(mill.press(ControlKey::Start));
    for (int tick = 0; tick < 8; ++tick) {
        mill.advance(0.5);
        if (!mill.busy()) break;
        const auto end = f.tracedEnd();
        // On the circle of radius 10 around (10, 0) within the chordal tolerance.
        const double r = std::hypot(end[0] - 10.0, end[1]);
        EXPECT_NEAR(r, 10.0, 0.011) << "tick " << tick;
        EXPECT_NEAR(end[0], mill.machine().position(0), 0.02);
        EXPECT_NEAR(end[1], mill.machine().position(1), 0.02);
    }
}

}  // namespace
}  // namespace mtc::test
