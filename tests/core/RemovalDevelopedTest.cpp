// Material removal on the developed cylinder surface (issue 19 §3, D-027):
// the jacket's depth map against hand-computed groove volumes (a ring
// groove around the circumference, a straight groove along the axis with
// the end mill's flat floor), a G32 move above the surface that cuts
// nothing, turning after milling, fewer columns under the cell cap, and
// bounded work for moves of many turns.
#include <gtest/gtest.h>

#include <cmath>

#include "InterpTestSupport.h"
#include "cnc_core/program/ProgramLoader.h"
#include "cnc_core/removal/DevelopedSurface.h"
#include "cnc_core/removal/RemovalRun.h"
#include "resources/EmbeddedResources.h"

namespace {

using namespace mtc::core;
using namespace mtc::core::removal;
using namespace mtc::test;

constexpr double kPi = 3.14159265358979323846;

RemovalRunResult simulate(const std::string& source, double resolution,
                          std::uint64_t maxCells = kMaxRemovalCells) {
    ProgramStore store;
    store.put(1, 1, parse(source, 1));
    RemovalSettings settings;
    settings.resolution = resolution;
    settings.maxCells = maxCells;
    return simulateRemoval(demoCell().processes[1], store, 1, settings);
}

/// The demo lathe's bar is R40 from machine Z 140 to 257.5; T9 is a driven
/// end mill of radius 4.85. `moves` run under G20 Z0 C0 X0 G32 RI 40 in G56
/// (all zero: Z1 is the machine Z), from Y1 0 Z1 `z` with X at 45.
std::string cylinderProgram(int z, const std::string& moves) {
    return "N0001 T9 G18 G90 G54 G0 X45 Z-30\n"
           "N0002 G0 C0\n"
           "N0003 G20 Z0 C0 X0\n"
           "N0004 G32 RI 40\n"
           "N0005 G0 G56 Y1 0 Z1 " +
           std::to_string(z) + "\n" + moves +
           "N0090 G0 X45\n"
           "N0091 G30\n"
           "N0092 G18\n"
           "N0093 M30\n";
}

/// Cells on the border of a groove's footprint of `perimeter` (mm on the
/// surface) can be counted wrongly: those within a cell diagonal of it.
double borderBound(double perimeter, double resolution, double depth) {
    return perimeter * std::sqrt(2.0) * resolution * depth;
}

/// Simpson's rule over [a, b] with n (even) intervals.
template <typename F>
double integrate(F f, double a, double b, int n = 2000) {
    const double h = (b - a) / n;
    double sum = f(a) + f(b);
    for (int i = 1; i < n; ++i)
        sum += f(a + i * h) * (i % 2 == 1 ? 4.0 : 2.0);
    return sum * h / 3.0;
}

/// The material of a bar of radius `bar` above the plane at distance `face`
/// from the axis, at distance y beside the tool's centre (the flat end
/// mill's floor is that plane).
double heightAboveFace(double bar, double face, double y) {
    return std::max(0.0, std::sqrt(std::max(0.0, bar * bar - y * y)) - face);
}

/// The volume of an axial groove of `length` cut with a flat end mill of
/// radius `r` at face radius `face` into a bar of radius `bar`: the
/// cross-section along its length and the two half-disc ends.
double axialGrooveVolume(double bar, double face, double r, double length) {
    const double section =
        integrate([&](double y) { return heightAboveFace(bar, face, y); }, -r, r);
    const double ends = integrate(
        [&](double y) {
            return 2.0 * std::sqrt(std::max(0.0, r * r - y * y)) * heightAboveFace(bar, face, y);
        },
        -r, r);
    return section * length + ends;
}

TEST(DevelopedSurface, RingGrooveIsTheAnnulusTimesTheWidth) {
    // A full turn at face radius 38 with a tool of radius 5: the groove is
    // the annulus R40 - R38 times the width 10.
    const TurnedProfile profile(40.0, 0.0, 100.0, 500);
    DevelopedSurface jacket(profile, static_cast<int>(DevelopedSurface::columnsFor(40.0, 0.2)));
    EXPECT_EQ(jacket.columns(), 1257);
    EXPECT_TRUE(jacket.cut({0.0, 50.0, 38.0}, {2.0 * kPi, 50.0, 38.0}, 5.0, profile));
    const double expected = kPi * (40.0 * 40.0 - 38.0 * 38.0) * 10.0;
    EXPECT_NEAR(jacket.removedVolume(profile), expected,
                2.0 * profile.sliceLength() * kPi * (40.0 * 40.0 - 38.0 * 38.0));
    for (int i = 0; i < jacket.columns(); i += 97)
        EXPECT_FLOAT_EQ(jacket.radius(i, 250), 38.0f) << "a round floor at the face radius";
}

TEST(DevelopedSurface, AxialGrooveHasTheEndMillsFlatFloor) {
    // Along the axis at angle 0, 0.5 mm deep: the floor is the plane at
    // 39.5, so beside the centre it lies higher (39.5 / cos), and the
    // cross-section is the bar's segment above that plane within the
    // tool's width.
    const TurnedProfile profile(40.0, 0.0, 100.0, 500);
    DevelopedSurface jacket(profile, static_cast<int>(DevelopedSurface::columnsFor(40.0, 0.2)));
    const double r = 4.85, length = 60.0, face = 39.5;
    ASSERT_TRUE(jacket.cut({0.0, 20.0, face}, {0.0, 20.0 + length, face}, r, profile));
    // What a round floor (the face radius all across) would remove more.
    const double flatness =
        integrate([&](double y) { return std::hypot(face, y) - face; }, -r, r) * length;
    const double bound = borderBound(2.0 * length + 2.0 * kPi * r, 0.2, 0.5);
    ASSERT_GT(flatness, 2.0 * bound) << "the test tells a flat floor from a round one";
    EXPECT_NEAR(jacket.removedVolume(profile), axialGrooveVolume(40.0, face, r, length), bound);
    const int middle = 250;
    EXPECT_NEAR(jacket.radius(0, middle), face / std::cos(jacket.columnAngle(0)), 1e-4);
}

TEST(DevelopedSurface, AboveTheSurfaceNothingIsCut) {
    const TurnedProfile profile(40.0, 0.0, 100.0, 500);
    DevelopedSurface jacket(profile, 400);
    EXPECT_FALSE(jacket.cut({0.0, 10.0, 40.5}, {3.0, 90.0, 40.5}, 5.0, profile));
    EXPECT_FALSE(jacket.cut({0.0, 10.0, 41.0}, {0.0, 10.0, 40.0}, 5.0, profile));
    EXPECT_EQ(jacket.removedVolume(profile), 0.0);
}

TEST(DevelopedSurface, TouchesAsksWithoutCutting) {
    // A ring groove to R38 at axial 50 (width 10); then the questions a
    // restart's way back asks (D-021), with a feed move's margin -0.1.
    const TurnedProfile profile(40.0, 0.0, 100.0, 500);
    DevelopedSurface jacket(profile, 1257);
    ASSERT_TRUE(jacket.cut({0.0, 50.0, 38.0}, {2.0 * kPi, 50.0, 38.0}, 5.0, profile));
    const double removed = jacket.removedVolume(profile);
    const double feed = -0.1;
    EXPECT_FALSE(jacket.touches({1.0, 50.0, 45.0}, {1.0, 50.0, 38.05}, 4.0, feed, profile))
        << "down into the groove, onto its floor";
    EXPECT_TRUE(jacket.touches({1.0, 50.0, 45.0}, {1.0, 50.0, 37.5}, 4.0, feed, profile))
        << "through the floor";
    EXPECT_TRUE(jacket.touches({1.0, 50.0, 45.0}, {1.0, 50.0, 38.0}, 5.5, feed, profile))
        << "a wider tool meets the walls";
    EXPECT_TRUE(jacket.touches({1.0, 70.0, 45.0}, {1.0, 70.0, 39.0}, 4.0, feed, profile))
        << "down beside the groove";
    EXPECT_FALSE(jacket.touches({0.0, 50.0, 38.0}, {3.0, 50.0, 38.0}, 4.0, feed, profile))
        << "along the floor";
    EXPECT_FALSE(jacket.touches({1.0, 70.0, 39.0}, {1.0, 70.0, 45.0}, 4.0, feed, profile))
        << "out of the material: moving away is no contact";
    EXPECT_TRUE(jacket.touches({1.0, 70.0, 45.0}, {1.0, 70.0, 40.05}, 4.0, 0.1, profile))
        << "a rapid within the margin above the surface";
    EXPECT_FALSE(jacket.touches({1.0, 70.0, 45.0}, {1.0, 70.0, 41.0}, 4.0, 0.1, profile));
    EXPECT_EQ(jacket.removedVolume(profile), removed) << "touches() changes nothing";
}

TEST(DevelopedSurface, ManyTurnsAndHugeNumbersAreBounded) {
    const TurnedProfile profile(40.0, 0.0, 100.0, 500);
    DevelopedSurface jacket(profile, 1257);
    // A fine helix over 1000 turns along 10 mm: every column of those rows.
    EXPECT_TRUE(jacket.cut({0.0, 45.0, 39.0}, {2000.0 * kPi, 55.0, 39.0}, 1.0, profile));
    EXPECT_NEAR(jacket.removedVolume(profile), kPi * (1600.0 - 39.0 * 39.0) * 12.0,
                2.0 * 0.2 * kPi * 79.0);
    // Angles of 1e300 rad: every turn, a row scan each; a NaN cuts nothing.
    jacket.cut({1e300, 50.0, 30.0}, {-1e308, 50.0, 30.0}, 1.0, profile);
    EXPECT_TRUE(std::isfinite(jacket.removedVolume(profile)));
    EXPECT_FALSE(jacket.cut({0.0, 50.0, std::nan("")}, {1.0, 50.0, 30.0}, 1.0, profile));
    for (int j = 0; j < jacket.rows(); j += 13)
        for (int i = 0; i < jacket.columns(); i += 11) {
            ASSERT_GE(jacket.radius(i, j), 0.0);
            ASSERT_LE(jacket.radius(i, j), 40.0);
        }
}

TEST(LatheDevelopedRemoval, RingGrooveMilledUnderG32) {
    // Plunge to X38 (2 mm into the R40 bar), one turn: 251.327 mm on RI 40.
    const RemovalRunResult r =
        simulate(cylinderProgram(200, "N0010 G1 X38 F100\nN0011 G1 Y1 251.3274123 F300\n"), 0.2);
    ASSERT_TRUE(r.part) << diagnosticsText(r.diagnostics);
    EXPECT_FALSE(r.diagnostics.hasErrors()) << diagnosticsText(r.diagnostics);
    for (const Diagnostic& d : r.diagnostics.items())
        EXPECT_NE(d.code, "REMOVAL_NOT_SIMULATED") << d.message;
    EXPECT_EQ(r.counts.transformedMoves, 0u);
    EXPECT_EQ(r.counts.cuttingMoves, 2u) << "the plunge and the turn";
    const double ring = kPi * (40.0 * 40.0 - 38.0 * 38.0);
    EXPECT_NEAR(r.part->removedVolume(), ring * 9.7, 2.0 * 0.2 * ring);
    EXPECT_EQ(r.part->removedVolume(), r.part->developedVolume());
}

TEST(LatheDevelopedRemoval, AxialGrooveFollowsTheProgrammedAngle) {
    // At Y1 62.83 (90 degrees on RI 40) along Z1 200 -> 170, 1.5 mm deep.
    const RemovalRunResult r = simulate(
        cylinderProgram(200, "N0010 G0 Y1 62.831853\nN0011 G1 X38.5 F100\nN0012 G1 Z1 170\n"), 0.2);
    ASSERT_TRUE(r.part) << diagnosticsText(r.diagnostics);
    const DevelopedSurface* jacket = r.part->jacket();
    ASSERT_NE(jacket, nullptr);
    const TurnedProfile& profile = *r.part->profile();
    const auto slice = [&](double z) {
        return static_cast<int>((z - profile.from()) / profile.sliceLength());
    };
    const auto column = [&](double degrees) {
        return static_cast<int>(degrees / 360.0 * jacket->columns());
    };
    EXPECT_NEAR(jacket->radius(column(90), slice(185)), 38.5, 0.01) << "the groove's floor";
    EXPECT_EQ(jacket->radius(column(0), slice(185)), 40.0) << "beside the groove";
    EXPECT_EQ(jacket->radius(column(90), slice(160)), 40.0) << "beyond its end";
    EXPECT_NEAR(r.part->removedVolume(), axialGrooveVolume(40.0, 38.5, 4.85, 30.0),
                borderBound(60.0 + 2.0 * kPi * 4.85, 0.2, 1.5));
}

TEST(LatheDevelopedRemoval, AboveTheSurfaceCutsNothing) {
    const RemovalRunResult r =
        simulate(cylinderProgram(200,
                                 "N0010 G1 X41 F100\nN0011 G1 Y1 100 Z1 180\nN0012 G2 Y1 120 Z1 "
                                 "160 I160 J100\n"),
                 0.2);
    ASSERT_TRUE(r.part) << diagnosticsText(r.diagnostics);
    EXPECT_FALSE(r.diagnostics.hasErrors()) << diagnosticsText(r.diagnostics);
    EXPECT_EQ(r.counts.cuttingMoves, 0u);
    EXPECT_GE(r.counts.developedMoves, 3u);
    EXPECT_EQ(r.part->removedVolume(), 0.0);
}

TEST(LatheDevelopedRemoval, TurningAfterMillingCountsEachMillimetreOnce) {
    // The ring groove to R38, then the bar turned to R39 over its length
    // with T1: the groove adds only what lies below R39.
    const std::string groove = "N0010 G1 X38 F100\nN0011 G1 Y1 251.3274123 F300\n";
    const std::string turning =
        "N0094 T1 G0 G54 Z2\nN0095 X39\nN0096 G1 Z-110 F300\nN0097 G0 X45\nN0098 M30\n";
    std::string both = cylinderProgram(200, groove);
    both.replace(both.find("N0093 M30\n"), 10, turning);
    const RemovalRunResult milledThenTurned = simulate(both, 0.2);
    const RemovalRunResult turnedOnly = simulate(
        "N0001 T1 G18 G90 G54 G0 X45 Z-30\nN0002 G0 Z2\nN0003 X39\nN0004 G1 Z-110 F300\n"
        "N0005 G0 X45\nN0006 M30\n",
        0.2);
    ASSERT_TRUE(milledThenTurned.part && turnedOnly.part);
    const double ring = kPi * (39.0 * 39.0 - 38.0 * 38.0);
    EXPECT_NEAR(milledThenTurned.part->removedVolume() - turnedOnly.part->removedVolume(),
                ring * 9.7, 2.0 * 0.2 * ring);
}

TEST(LatheDevelopedRemoval, AJacketOverTheCellCapGetsFewerColumnsAndSaysSo) {
    // 1257 columns x 588 slices at 0.2 mm: over a cap of 100,000 cells the
    // jacket gets 170 columns (1.479 mm on the R40 bar); the ring groove is
    // still cut, its walls along the circumference as fine as the slices.
    const std::string ring = "N0010 G1 X38 F100\nN0011 G1 Y1 251.3274123 F300\n";
    const RemovalRunResult r = simulate(cylinderProgram(200, ring), 0.2, 100'000);
    ASSERT_TRUE(r.part && r.part->jacket()) << diagnosticsText(r.diagnostics);
    EXPECT_EQ(r.part->jacket()->columns(), 170);
    EXPECT_EQ(r.counts.transformedMoves, 0u);
    const double annulus = kPi * (40.0 * 40.0 - 38.0 * 38.0);
    EXPECT_NEAR(r.part->removedVolume(), annulus * 9.7, 2.0 * 0.2 * annulus);
    int coarser = 0;
    for (const Diagnostic& d : r.diagnostics.items())
        if (d.code == "REMOVAL_DEVELOPED_COARSER") {
            ++coarser;
            EXPECT_EQ(d.severity, Severity::Warning);
            EXPECT_EQ(d.where.block, "N0005") << "the first move under G32";
            EXPECT_NE(d.message.find("170 columns (1.479 mm on the bar) instead of 1257"),
                      std::string::npos)
                << d.message;
            EXPECT_NE(d.message.find("at most 100000"), std::string::npos) << d.message;
        }
    EXPECT_EQ(coarser, 1);
    // Never fewer columns than the turned part's facets (588 x 63 for R40 at
    // 0.2 mm: the smallest cap the part itself fits in).
    const RemovalRunResult tight = simulate(cylinderProgram(200, ring), 0.2, 37'044);
    ASSERT_TRUE(tight.part && tight.part->jacket()) << diagnosticsText(tight.diagnostics);
    EXPECT_EQ(tight.part->jacket()->columns(), tight.part->angularSegments());
}

TEST(LatheDevelopedRemoval, TheViewsCapKeepsTheDemoProgramsGroove) {
    // The panel's part view simulates with at most 250,000 cells (TP-023):
    // the demo lathe program's G32 groove is still cut, on 425 columns.
    ProgramStore store;
    ProgramLoader(store).loadTexts(mtc::resources::demoPrograms());
    RemovalSettings fine, view;
    view.maxCells = 250'000;
    const RemovalRunResult a = simulateRemoval(demoCell().processes[1], store, 1, fine);
    const RemovalRunResult b = simulateRemoval(demoCell().processes[1], store, 1, view);
    ASSERT_TRUE(a.part && a.part->jacket() && b.part && b.part->jacket());
    EXPECT_EQ(a.part->jacket()->columns(), 1257);
    EXPECT_EQ(b.part->jacket()->columns(), 425);
    EXPECT_GT(a.part->developedVolume(), 1000.0);
    EXPECT_NEAR(b.part->developedVolume(), a.part->developedVolume(),
                0.05 * a.part->developedVolume());
}

}  // namespace
