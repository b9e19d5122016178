// Toolpath geometry builder (issue 8): segment counts and kinds per move,
// chordal tessellation of arcs within the stated tolerance, the wrap of the
// developed plane of G32 onto the cylinder of radius RI (seed 003, ch. 4),
// picking (segment -> move -> block) and the segment limit.
#include <gtest/gtest.h>

#include <cmath>

#include "InterpTestSupport.h"
#include "cnc_core/geometry/ArcSweep.h"
#include "cnc_core/toolpath/CurveMath.h"
#include "cnc_core/toolpath/ToolpathBuilder.h"
#include "cnc_core/toolpath/ToolpathRun.h"
#include "resources/EmbeddedResources.h"

namespace {

using namespace mtc::core;
using namespace mtc::test;

constexpr double kFloat = 2e-4;  // float vertices at a few hundred mm

/// Runs `source` as program 1 of `process` of the demo cell into a builder.
ToolpathRunResult run(const std::string& source, int process, ToolpathSettings settings = {}) {
    const MachineConfig& cell = demoCell();
    ProgramStore store;
    store.put(process, 1, parse(source, 1));
    return buildToolpath(cell.processes[static_cast<std::size_t>(process)], store, 1, settings);
}

double distanceFromAxis(const std::array<double, 3>& p, int axis) {
    const auto a = static_cast<std::size_t>((axis + 1) % 3),
               b = static_cast<std::size_t>((axis + 2) % 3);
    return std::hypot(p[a], p[b]);
}

TEST(ToolpathBuilder, OneSegmentPerStraightMoveWithItsKindAndBlock) {
    const auto r =
        run("N0000 (square)\nN0001 G0 X0 Y0 Z10\nN0002 G1 Z0 F500\nN0003 X50\nN0004 Y30\n"
            "N0005 G0 Z10\nN0006 M30\n",
            0);
    ASSERT_TRUE(r.complete) << diagnosticsText(r.diagnostics);
    const auto& g = r.geometry;
    ASSERT_EQ(g.moves.size(), 5u);
    EXPECT_EQ(g.scene.segmentCount(), 5u);
    EXPECT_EQ(g.developed.segmentCount(), 0u);
    const ToolpathKind kinds[] = {ToolpathKind::Rapid, ToolpathKind::Feed, ToolpathKind::Feed,
                                  ToolpathKind::Feed, ToolpathKind::Rapid};
    for (std::size_t i = 0; i < 5; ++i) {
        EXPECT_EQ(g.moves[i].kind, kinds[i]) << i;
        EXPECT_EQ(g.moves[i].block, i + 1) << "block index of move " << i;
        EXPECT_EQ(g.moves[i].line, i + 2) << "source line of move " << i;
        EXPECT_EQ(g.moves[i].program, 1);
    }
    // A continuous path stores each vertex once (first move starts at the origin).
    EXPECT_EQ(g.scene.vertexCount(), 6u);
    const auto corner = g.scene.vertex(g.scene.segmentStart[3]);
    EXPECT_NEAR(corner[0], 50.0, kFloat);
    EXPECT_NEAR(corner[1], 0.0, kFloat);
    EXPECT_NEAR(corner[2], 0.0, kFloat);
    EXPECT_NEAR(g.scene.bounds.max[0], 50.0, kFloat);
    EXPECT_NEAR(g.scene.bounds.max[2], 10.0, kFloat);
}

TEST(ToolpathBuilder, ArcChordsStayWithinTheTolerance) {
    for (double tolerance : {0.1, 0.01, 0.001}) {
        ToolpathSettings settings;
        settings.tolerance = tolerance;
        const auto r =
            run("N0001 G17 G0 X40 Y0 Z0\nN0002 G2 X0 Y-40 I0 J0 F800\nN0003 G3 X40 Y0 I0 J0\n"
                "N0004 G2 X40 Y0 I0 J0\nN0005 M30\n",
                0, settings);
        ASSERT_TRUE(r.complete) << diagnosticsText(r.diagnostics);
        const auto& g = r.geometry;
        ASSERT_EQ(g.moves.size(), 4u);
        double worst = 0.0;
        for (std::size_t m = 1; m < 4; ++m) {
            const auto [first, last] = g.sceneRange(m);
            EXPECT_GT(last - first, 4u) << "arc " << m << " is tessellated";
            for (std::uint32_t s = first; s < last; ++s) {
                const auto a = g.scene.vertex(g.scene.segmentStart[s]);
                const auto b = g.scene.vertex(g.scene.segmentStart[s] + 1);
                EXPECT_NEAR(std::hypot(a[0], a[1]), 40.0, kFloat) << "vertex on the circle";
                // The chord's farthest point from the arc is its middle.
                const double mid = std::hypot((a[0] + b[0]) / 2, (a[1] + b[1]) / 2);
                worst = std::max(worst, 40.0 - mid);
            }
        }
        EXPECT_LE(worst, tolerance + kFloat) << "tolerance " << tolerance;
        EXPECT_GT(worst, tolerance / 4) << "not needlessly fine, tolerance " << tolerance;
        // Quarter arc CW, quarter arc CCW, full circle: chords by the formula.
        const double pi = curve::kPi;
        EXPECT_EQ(g.sceneRange(1).second - g.sceneRange(1).first,
                  static_cast<std::uint32_t>(curve::arcChords(40, pi / 2, tolerance)));
        EXPECT_EQ(g.sceneRange(2).second - g.sceneRange(2).first,
                  static_cast<std::uint32_t>(curve::arcChords(40, pi / 2, tolerance)));
        EXPECT_EQ(g.sceneRange(3).second - g.sceneRange(3).first,
                  static_cast<std::uint32_t>(curve::arcChords(40, 2 * pi, tolerance)));
    }
}

TEST(ToolpathBuilder, ArcSweepDirectionAndFullCircle) {
    const double pi = curve::kPi;
    EXPECT_NEAR(arcSweep(1, 0, 0, 1, 0, 0, false, false), pi / 2, 1e-12);
    EXPECT_NEAR(arcSweep(1, 0, 0, 1, 0, 0, true, false), -1.5 * pi, 1e-12);
    EXPECT_NEAR(arcSweep(1, 0, 1, 0, 0, 0, true, false), -2 * pi, 1e-12);
    for (double r : {0.5, 5.0, 500.0})
        for (double tol : {0.001, 0.01, 0.1}) {
            const int n = curve::arcChords(r, 2 * pi, tol);
            EXPECT_LE(curve::sagitta(r, 2 * pi / n), tol + 1e-12) << r << " " << tol;
            EXPECT_GE(n, 4) << "at least one chord per quarter turn";
            if (n > 4) {
                EXPECT_GT(curve::sagitta(r, 2 * pi / (n - 1)), tol) << "fewest chords";
            }
        }
}

TEST(ToolpathBuilder, HelixInterpolatesTheThirdAxis) {
    const auto r = run("N0001 G17 G0 X20 Y0 Z0\nN0002 G3 X20 Y0 Z-10 I0 J0 F400\nN0003 M30\n", 0);
    ASSERT_TRUE(r.complete) << diagnosticsText(r.diagnostics);
    const auto& g = r.geometry;
    const auto [first, last] = g.sceneRange(1);
    const std::uint32_t n = last - first;
    for (std::uint32_t s = first; s < last; ++s) {
        const auto a = g.scene.vertex(g.scene.segmentStart[s]);
        EXPECT_NEAR(a[2], -10.0 * (s - first) / n, 1e-3);
    }
}

TEST(ToolpathWrap, DevelopedCoordinateIsArcLengthOnRi) {
    const double pi = curve::kPi;
    EXPECT_NEAR(curve::developedFromDegrees(360.0, 36.5, 0), 2 * pi * 36.5, 1e-9);
    EXPECT_NEAR(curve::developedFromDegrees(90.0, 10.0, 1), -5 * pi, 1e-9) << "Cxx.076 = 1";
    // Unit radius r = n / (2 pi) (seed 003, 4.3): mm on the surface = degrees.
    EXPECT_NEAR(curve::developedFromDegrees(123.0, 360.0 / (2 * pi), 0), 123.0, 1e-9);
    for (double mm : {-100.0, 0.0, 12.5, 400.0})
        EXPECT_NEAR(curve::developedFromDegrees(curve::degreesFromDeveloped(mm, 20, 1), 20, 1), mm,
                    1e-9);
    const auto p = curve::cylinderPoint(2, 30.0, 7.0, 90.0);
    EXPECT_NEAR(p[0], 0.0, 1e-12);
    EXPECT_NEAR(p[1], 30.0, 1e-12) << "about Z: from X towards Y";
    EXPECT_NEAR(p[2], 7.0, 1e-12);
    const auto q = curve::cylinderPoint(0, 5.0, -3.0, 0.0);
    EXPECT_NEAR(q[0], -3.0, 1e-12);
    EXPECT_NEAR(q[1], 5.0, 1e-12) << "about X: angle 0 on Y";
}

/// Demo lathe (process 1): Z, C span the plane after G20 Z0 C0 X0; X infeed.
const char* kCylinderProgram =
    "N0000 (groove on the shell)\nN0001 G0 X45 Z100\nN0002 M5\nN0003 G0 C0\n"
    "N0004 G20 Z0 C0 X0\nN0005 G32 RI 36.5\nN0006 G0 G56 Y1 0 Z1 100\nN0007 G1 X34.5 F120\n"
    "N0008 G1 Y1 30 F300\nN0009 G3 Y1 40 Z1 90 I90 J30\nN0010 G1 Z1 60\nN0011 G0 X45\n"
    "N0012 G30\nN0013 M30\n";

TEST(ToolpathWrap, G32MovesAreDevelopedAndWrappedOnRi) {
    ToolpathSettings settings;
    settings.tolerance = 0.01;
    const auto r = run(kCylinderProgram, 1, settings);
    ASSERT_TRUE(r.complete) << diagnosticsText(r.diagnostics);
    const auto& g = r.geometry;
    EXPECT_DOUBLE_EQ(g.cylinderRadius, 36.5);
    EXPECT_EQ(g.cylinderAxis, 2) << "the cylinder lies along Z";
    EXPECT_NEAR(g.cylinderFrom, 60.0, 1e-9);
    EXPECT_NEAR(g.cylinderTo, 100.0, 1e-9);
    // Moves: G0 X Z, G0 C0, then under G32: G0 Y1 Z1, G1 X, G1 Y1, G3, G1 Z1, G0 X.
    ASSERT_EQ(g.moves.size(), 8u);
    EXPECT_EQ(g.moves[1].transformation, 30);
    EXPECT_EQ(g.moves[4].transformation, 32);
    // Developed plane: straight line Y1 0 -> 30 at Z1 100 is one segment.
    const auto [d0, d1] = g.developedRange(4);
    ASSERT_EQ(d1 - d0, 1u);
    const auto a = g.developed.vertex(g.developed.segmentStart[d0]);
    const auto b = g.developed.vertex(g.developed.segmentStart[d0] + 1);
    EXPECT_NEAR(a[0], 100.0, kFloat);
    EXPECT_NEAR(a[1], 0.0, kFloat);
    EXPECT_NEAR(b[0], 100.0, kFloat);
    EXPECT_NEAR(b[1], 30.0, kFloat);
    // Wrapped: the same move turns 30 / 36.5 rad about Z on radius RI.
    const auto [s0, s1] = g.sceneRange(4);
    EXPECT_EQ(s1 - s0, static_cast<std::uint32_t>(curve::arcChords(36.5, 30 / 36.5, 0.01)));
    double worst = 0.0;
    for (std::uint32_t s = g.moves[2].firstScene; s < g.scene.segmentCount(); ++s) {
        const long move = g.moveOfSceneSegment(s);
        if (move < 0 || g.moves[static_cast<std::size_t>(move)].transformation != 32) continue;
        const auto p = g.scene.vertex(g.scene.segmentStart[s]);
        const auto q = g.scene.vertex(g.scene.segmentStart[s] + 1);
        EXPECT_NEAR(distanceFromAxis(p, 2), 36.5, kFloat) << "vertex on the cylinder";
        const std::array<double, 3> mid{(p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2};
        worst = std::max(worst, 36.5 - distanceFromAxis(mid, 2));
    }
    EXPECT_LE(worst, 0.01 + kFloat);
    const auto end = g.scene.vertex(g.scene.segmentStart[s1 - 1] + 1);
    const double angle = 30.0 / 36.5;
    EXPECT_NEAR(end[0], 36.5 * std::cos(angle), kFloat);
    EXPECT_NEAR(end[1], 36.5 * std::sin(angle), kFloat);
    EXPECT_NEAR(end[2], 100.0, kFloat);
}

TEST(ToolpathWrap, ArcInTheDevelopedPlaneKeepsItsRadius) {
    const auto r = run(kCylinderProgram, 1);
    ASSERT_TRUE(r.complete) << diagnosticsText(r.diagnostics);
    const auto& g = r.geometry;
    const auto [first, last] = g.developedRange(5);  // G3 Y1 40 Z1 90 around Z1 90 Y1 30: R10
    ASSERT_GT(last - first, 4u);
    for (std::uint32_t s = first; s < last; ++s) {
        const auto p = g.developed.vertex(g.developed.segmentStart[s]);
        EXPECT_NEAR(std::hypot(p[0] - 90.0, p[1] - 30.0), 10.0, kFloat);
    }
}

TEST(ToolpathPicking, EverySegmentLeadsBackToItsMoveAndBlock) {
    const auto r = run(kCylinderProgram, 1);
    const auto& g = r.geometry;
    for (std::size_t m = 0; m < g.moves.size(); ++m) {
        const auto [first, last] = g.sceneRange(m);
        for (std::uint32_t s = first; s < last; ++s)
            EXPECT_EQ(g.moveOfSceneSegment(s), static_cast<long>(m));
        const auto [dfirst, dlast] = g.developedRange(m);
        for (std::uint32_t s = dfirst; s < dlast; ++s)
            EXPECT_EQ(g.moveOfDevelopedSegment(s), static_cast<long>(m));
        const auto same = g.movesOfBlock(g.moves[m].program, g.moves[m].block);
        EXPECT_NE(std::find(same.begin(), same.end(), m), same.end());
    }
    EXPECT_EQ(g.moveOfSceneSegment(static_cast<std::uint32_t>(g.scene.segmentCount())), -1);
}

TEST(ToolpathRun, SegmentLimitTruncatesAndSaysSo) {
    ToolpathSettings settings;
    settings.segmentLimit = 3;
    const auto r = run("N0001 G0 X1\nN0002 G1 X2 F100\nN0003 X3\nN0004 X4\nN0005 X5\nN0006 M30\n",
                       0, settings);
    EXPECT_TRUE(r.geometry.truncated);
    EXPECT_EQ(r.geometry.scene.segmentCount(), 3u);
    EXPECT_EQ(r.geometry.moves.size(), 5u) << "moves are still recorded";
}

TEST(ToolpathRun, RejectedBlocksAreReportedAndSkipped) {
    const auto r = run("N0001 G0 X10\nN0002 G1 X20\nN0003 G1 X30 F100\nN0004 M30\n", 0);
    EXPECT_TRUE(r.complete);
    ASSERT_TRUE(r.diagnostics.hasErrors());
    EXPECT_EQ(r.diagnostics.items().front().where.line, 2);
    EXPECT_EQ(r.geometry.moves.size(), 2u);
}

TEST(ToolpathRun, EndlessLoopStopsAtTheBudget) {
    const MachineConfig& cell = demoCell();
    ProgramStore store;
    store.put(0, 1, parse("N0001 .L G1 X1 F100\nN0002 G1 X0\nN0003 BRA .L\n", 1));
    const auto r = buildToolpath(cell.processes[0], store, 1, {}, 200000);
    EXPECT_FALSE(r.complete);
    EXPECT_EQ(r.blocks, 200000u);
    EXPECT_LE(r.diagnostics.items().size(), 100u);
}

TEST(ToolpathRun, DemoProgramsDraw) {
    const MachineConfig& cell = demoCell();
    ProgramStore store;
    for (const auto& name : mtc::resources::list("programs/")) {
        const std::string file = name.substr(name.rfind('/') + 1);  // N1010001.DAT
        store.put(file[4] - '0', std::stoi(file.substr(5, 3)),
                  parse(std::string(mtc::resources::find(name)), std::stoi(file.substr(5, 3))));
    }
    for (int process : {0, 1}) {
        SCOPED_TRACE(process);
        const auto r = buildToolpath(cell.processes[static_cast<std::size_t>(process)], store, 1);
        EXPECT_TRUE(r.complete) << diagnosticsText(r.diagnostics);
        EXPECT_TRUE(r.diagnostics.empty()) << diagnosticsText(r.diagnostics);
        EXPECT_GT(r.geometry.scene.segmentCount(), 10u);
        if (process == 1) {
            EXPECT_GT(r.geometry.developed.segmentCount(), 0u) << "G32 groove";
        }
    }
}

}  // namespace

namespace {

/// The workpiece coordinates of the end of move `m`: scene point minus the
/// offset of the move's frame (TP-019).
std::array<double, 3> sceneEnd(const ToolpathGeometry& g, std::size_t m) {
    const auto last = g.sceneRange(m).second;
    return g.scene.vertex(g.scene.segmentStart[last - 1] + 1);
}

std::array<double, 3> workpieceEnd(const ToolpathGeometry& g, std::size_t m) {
    const auto end = sceneEnd(g, m);
    const ToolpathFrame frame = g.frameOf(m);
    return {end[0] - frame.offset[0], end[1] - frame.offset[1], end[2] - frame.offset[2]};
}

}  // namespace

TEST(ToolpathFrames, EveryMoveKnowsTheZeroOffsetInForce) {
    // Demo mill: G54 = X-150 Y-80 Z-120, G55 = X50 Y-80 Z-120 (demo-cell.cfg).
    const auto r =
        run("N0001 G53 G0 X10 Y10 Z10\nN0002 G54 G0 X5 Y6 Z7\nN0003 G1 X15 F500\n"
            "N0004 G55 G0 X5 Y6 Z7\nN0005 G1 Y16\nN0006 G54 G1 X25\nN0007 M30\n",
            0);
    ASSERT_TRUE(r.complete) << diagnosticsText(r.diagnostics);
    const auto& g = r.geometry;
    ASSERT_EQ(g.moves.size(), 6u);
    ASSERT_EQ(g.frames.size(), 3u) << "G53, G54, G55: one entry each";
    const int codes[] = {53, 54, 54, 55, 55, 54};
    for (std::size_t m = 0; m < 6; ++m)
        EXPECT_EQ(g.frameOf(m).code, codes[m]) << "move " << m;
    EXPECT_EQ(g.moves[2].frame, g.moves[5].frame) << "G54 again is the same entry";
    EXPECT_EQ(g.frameOf(0).offset, (std::array<double, 3>{0, 0, 0}));
    EXPECT_EQ(g.frameOf(1).offset, (std::array<double, 3>{-150, -80, -120}));
    EXPECT_EQ(g.frameOf(3).offset, (std::array<double, 3>{50, -80, -120}));
    // Scene minus offset is what the program wrote, in every frame.
    const std::array<std::array<double, 3>, 6> programmed{
        {{10, 10, 10}, {5, 6, 7}, {15, 6, 7}, {5, 6, 7}, {5, 16, 7}, {25, 16 + 0.0, 7}}};
    for (std::size_t m = 0; m < 6; ++m) {
        const auto work = workpieceEnd(g, m);
        if (m == 5) {  // back in G54 at the machine's Y of the G55 move
            EXPECT_NEAR(work[0], 25.0, kFloat);
            continue;
        }
        for (std::size_t i = 0; i < 3; ++i)
            EXPECT_NEAR(work[i], programmed[m][i], kFloat) << "move " << m << " axis " << i;
    }
    EXPECT_EQ(g.frameOf(99).code, 53) << "out of range: no offset";
}

TEST(ToolpathFrames, TheLatheFrameHasNoYAndFollowsG20) {
    // Demo lathe: G54 = X0 Z255.5; G55 = X255.5 Z0, after G20 Z0 C0 X0 the
    // Z axis has definition X and uses that column (seed 003, 3.5).
    const auto r = run("N0001 G54 G0 X40 Z5\nN0002 G1 Z-20 F200\nN0003 M30\n", 1);
    ASSERT_TRUE(r.complete) << diagnosticsText(r.diagnostics);
    ASSERT_EQ(r.geometry.moves.size(), 2u);
    EXPECT_EQ(r.geometry.frameOf(1).code, 54);
    EXPECT_EQ(r.geometry.frameOf(1).offset, (std::array<double, 3>{0, 0, 255.5}));
    EXPECT_NEAR(workpieceEnd(r.geometry, 1)[2], -20.0, kFloat);
    const auto g20 =
        run("N0001 G54 G0 X40 Z5\nN0002 G20 Z0 C0 X0\nN0003 G55 G1 Z-10 F200\nN0004 M30\n", 1);
    ASSERT_TRUE(g20.complete) << diagnosticsText(g20.diagnostics);
    ASSERT_EQ(g20.geometry.moves.size(), 2u);
    // Z has definition X now: column X of G55 (255.5); X has definition Z (0).
    EXPECT_EQ(g20.geometry.frameOf(1).code, 55);
    EXPECT_EQ(g20.geometry.frameOf(1).offset, (std::array<double, 3>{0, 0, 255.5}));
    EXPECT_NEAR(workpieceEnd(g20.geometry, 1)[2], -10.0, kFloat);
}

TEST(ToolpathFrames, TheLatheFrameReadsDiametersUnderG16) {
    // Demo lathe: B015 = radius (G15 at the start), G54 = X0 Z255.5. The frame
    // names the scene axis G15/G16 apply to (definition X) and, under G16,
    // reads diameters there: the programmed X80 is 80, not the radius 40.
    const auto r =
        run("N0001 G54 G0 X40 Z5\nN0002 G16 G1 X80 Z-20 F200\nN0003 G15 G1 X30\nN0004 M30\n", 1);
    ASSERT_TRUE(r.complete) << diagnosticsText(r.diagnostics);
    const auto& g = r.geometry;
    ASSERT_EQ(g.moves.size(), 3u);
    const bool diameter[] = {false, true, false};
    const double programmedX[] = {40, 80, 30};
    for (std::size_t m = 0; m < 3; ++m) {
        const ToolpathFrame frame = g.frameOf(m);
        EXPECT_EQ(frame.radialAxis, 0) << "move " << m;
        EXPECT_EQ(frame.diameter, diameter[m]) << "move " << m;
        const auto end = sceneEnd(g, m);
        EXPECT_NEAR(frame.workpiece(0, end[0]), programmedX[m], kFloat) << "move " << m;
        EXPECT_NEAR(frame.sceneOf(0, programmedX[m]), end[0], kFloat) << "move " << m;
        EXPECT_NEAR(frame.workpiece(2, end[2]), m == 0 ? 5.0 : -20.0, kFloat) << "move " << m;
    }
    EXPECT_NEAR(sceneEnd(g, 1)[0], 40.0, kFloat) << "the machine moves the radius";
    EXPECT_EQ(g.frames.size(), 2u) << "G54 radius and G54 diameter";
    EXPECT_NE(g.frameOf(0), g.frameOf(1));
    EXPECT_EQ(g.frameOf(0), g.frameOf(2));
    // After G20 the Z axis has definition X: G16 applies to it (seed 003, 3.5).
    const auto g20 =
        run("N0001 G54 G0 X40 Z5\nN0002 G20 Z0 C0 X0\nN0003 G1 Z-10 F200\nN0004 M30\n", 1);
    ASSERT_TRUE(g20.complete) << diagnosticsText(g20.diagnostics);
    EXPECT_EQ(g20.geometry.frameOf(1).radialAxis, 2);
    // The mill: X has definition X, radius programming (B015 = radius).
    const auto mill = run("N0001 G54 G0 X5 Y6 Z7\nN0002 M30\n", 0);
    ASSERT_TRUE(mill.complete) << diagnosticsText(mill.diagnostics);
    EXPECT_EQ(mill.geometry.frameOf(0).radialAxis, 0);
    EXPECT_FALSE(mill.geometry.frameOf(0).diameter);
    EXPECT_DOUBLE_EQ(mill.geometry.frameOf(0).scale(0), 1.0);
}
