// Material removal (issue 19 §3, D-020): the swept-disc geometry, the mill's
// height field against hand-computed pocket volumes, the lathe's turned
// profile against the programmed contour, the bounds on resolution and
// cells, and the closed STL surface of the finished part.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <set>
#include <vector>

#include "InterpTestSupport.h"
#include "cnc_core/removal/PartStl.h"
#include "cnc_core/removal/RemovalRun.h"
#include "cnc_core/removal/SweptDisc.h"

namespace {

using namespace mtc::core;
using namespace mtc::core::removal;
using namespace mtc::test;

constexpr double kPi = 3.14159265358979323846;

RemovalRunResult simulate(const std::string& source, int process, double resolution) {
    ProgramStore store;
    store.put(process, 1, parse(source, 1));
    RemovalSettings settings;
    settings.resolution = resolution;
    return simulateRemoval(demoCell().processes[static_cast<std::size_t>(process)], store, 1,
                           settings);
}

/// Cells on the border of a region of `perimeter` can be counted wrongly:
/// those whose centre lies within a cell diagonal of it.
double borderBound(double perimeter, double resolution, double depth) {
    return perimeter * std::sqrt(2.0) * resolution * depth;
}

TEST(SweptDisc, RowOfADiagonalChordIsTheStadiumCut) {
    const SweptDisc d{0, 0, 10, 10, 1};
    const Span mid = sweptRow(d, 5);  // the band: |x - 5| <= sqrt(2)
    EXPECT_NEAR(mid.lo, 5 - std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(mid.hi, 5 + std::sqrt(2.0), 1e-12);
    const Span end = sweptRow(d, 10.5);  // the band's corner, then the end disc
    EXPECT_NEAR(end.lo, 10.5 - std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(end.hi, 10 + std::sqrt(0.75), 1e-12);
    EXPECT_TRUE(sweptRow(d, 11.01).empty());
    EXPECT_TRUE(sweptRow(d, -1.01).empty());
}

TEST(SweptDisc, CoveringPositionsOfAPoint) {
    const SweptDisc d{0, 0, 10, 0, 1};
    const Span t = coveringPositions(d, 5, 0.6);  // |x - 5| <= 0.8
    EXPECT_NEAR(t.lo, 0.42, 1e-12);
    EXPECT_NEAR(t.hi, 0.58, 1e-12);
    EXPECT_TRUE(coveringPositions(d, 5, 1.2).empty());
    const Span still = coveringPositions(SweptDisc{3, 3, 3, 3, 1}, 3.5, 3);
    EXPECT_EQ(still.lo, 0.0);
    EXPECT_EQ(still.hi, 1.0);
}

TEST(HeightField, HugeCoordinatesCutOnlyTheGrid) {
    HeightField f(Box{{0, 0, -10}, {10, 10, 0}}, 50, 50);
    const double huge = 1e300;
    f.cut({-huge, 5, -2}, {huge, 5, -2}, 1);  // a line through the whole world
    EXPECT_NEAR(f.removedVolume(), 10 * 2 * 2, borderBound(20, 0.2, 2));
    const double before = f.removedVolume();
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_FALSE(f.cut({0, 0, -5}, {inf, 0, -5}, 1));
    EXPECT_FALSE(f.cut({0, 0, -5}, {std::nan(""), 0, -5}, 1));
    EXPECT_EQ(f.removedVolume(), before);
    // A plunge from far above to far below with a huge cutter: everything
    // down to the bottom, nothing below it.
    EXPECT_TRUE(f.cut({5, 5, 1e300}, {5, 5, -1e300}, 1e300));
    EXPECT_NEAR(f.removedVolume(), 10.0 * 10.0 * 10.0, 1e-6);
}

TEST(HeightField, RampCutsTheLowestFaceThatCoversACell) {
    HeightField f(Box{{0, 0, -10}, {20, 2, 0}}, 200, 20);
    f.cut({0, 1, 0}, {20, 1, -4}, 5);  // the ramp descends 0.2 mm per mm
    // A cell centre at x is covered from face positions x - 5 .. x + 5 (on
    // the chord line): its height is the face at min(x + 5, 20).
    for (int i = 0; i < f.columns(); i += 17) {
        const double x = f.columnX(i);
        EXPECT_NEAR(f.height(i, 10), -0.2 * std::min(x + std::sqrt(25 - 0.05 * 0.05), 20.0), 1e-4)
            << x;
    }
}

// A 40 x 20 x 4 pocket at X20..60 Y20..40 (G54) cleared by T1 (radius 3.5)
// with its centre on three zig-zag lines and a finishing lap: the cutter
// takes the rectangle with corners rounded by its radius.
const char* kPocketByCentre =
    "N0001 T1 G17 G90 G54 G0 X23.5 Y23.5 Z2\n"
    "N0002 S2000 M3\n"
    "N0003 G1 Z-4 F200\n"
    "N0004 X56.5\n"
    "N0005 Y30\n"
    "N0006 X23.5\n"
    "N0007 Y36.5\n"
    "N0008 X56.5\n"
    "N0009 Y23.5\n"
    "N0010 X23.5\n"
    "N0011 Y36.5\n"
    "N0012 G0 Z2\n"
    "N0013 M30\n";

// The same pocket with its wall programmed and G41 keeping the cutter inside.
const char* kPocketByContour =
    "N0001 T1 G17 G90 G54 G0 X40 Y30 Z2\n"
    "N0002 S2000 M3\n"
    "N0003 G1 Z-4 F200\n"
    "N0004 X23.5 Y23.5\n"
    "N0005 X56.5\n"
    "N0006 Y30\n"
    "N0007 X23.5\n"
    "N0008 Y36.5\n"
    "N0009 X56.5\n"
    "N0010 X40 Y30\n"
    "N0011 G41 Y20\n"
    "N0012 X60\n"
    "N0013 Y40\n"
    "N0014 X20\n"
    "N0015 Y20\n"
    "N0016 X40\n"
    "N0017 G40 Y30\n"
    "N0018 G0 Z2\n"
    "N0019 M30\n";

double pocketVolume() {
    return (40.0 * 20.0 - (4.0 - kPi) * 3.5 * 3.5) * 4.0;
}

TEST(MillRemoval, PocketVolumeWithinTheResolution) {
    for (double resolution : {0.2, 0.1}) {
        for (const char* program : {kPocketByCentre, kPocketByContour}) {
            SCOPED_TRACE(std::to_string(resolution) +
                         (program == kPocketByCentre ? " centre" : " G41"));
            const RemovalRunResult r = simulate(program, 0, resolution);
            ASSERT_TRUE(r.part) << diagnosticsText(r.diagnostics);
            EXPECT_TRUE(r.complete);
            EXPECT_FALSE(r.diagnostics.hasErrors()) << diagnosticsText(r.diagnostics);
            EXPECT_NEAR(r.part->removedVolume(), pocketVolume(), borderBound(120, resolution, 4.0));
            EXPECT_EQ(r.counts.rapidCuts, 0u);
            // Outside the pocket the block is untouched, inside it is 4 deep.
            const HeightField& f = *r.part->heightField();
            const double top = -120.0, floor = -124.0;  // G54 Z-120
            for (int j = 0; j < f.rows(); j += 7)
                for (int i = 0; i < f.columns(); i += 7) {
                    const double x = f.columnX(i) + 150.0, y = f.rowY(j) + 80.0;  // program
                    const double h = f.height(i, j);
                    if (x < 19.9 || x > 60.1 || y < 19.9 || y > 40.1) {
                        ASSERT_NEAR(h, top, 1e-4) << x << " " << y;
                    } else if (x > 23.6 && x < 56.4 && y > 20.1 && y < 39.9) {
                        ASSERT_NEAR(h, floor, 1e-4) << x << " " << y;
                    }
                }
        }
    }
}

TEST(MillRemoval, HelixIntoACircle) {
    // Centre circle of radius 3 around (50, 30): helix down 3 mm in one turn,
    // then a turn at the bottom: a hole of radius 3 + 3.5, 3 deep.
    const RemovalRunResult r = simulate(
        "N0001 T1 G17 G90 G54 G0 X53 Y30 Z1\nN0002 G1 Z0 F100\n"
        "N0003 G2 X53 Y30 Z-3 I50 J30\nN0004 G2 X53 Y30 I50 J30\nN0005 G0 Z5\nN0006 M30\n",
        0, 0.1);
    ASSERT_TRUE(r.part) << diagnosticsText(r.diagnostics);
    EXPECT_FALSE(r.diagnostics.hasErrors()) << diagnosticsText(r.diagnostics);
    const double radius = 6.5;
    EXPECT_NEAR(r.part->removedVolume(), kPi * radius * radius * 3.0,
                borderBound(2 * kPi * radius, 0.1, 3.0));
}

TEST(MillRemoval, RapidIntoThePartIsReportedWithItsBlock) {
    const RemovalRunResult r = simulate(
        "N0001 T1 G17 G90 G54 G0 X10 Y10 Z2\nN0002 Z-2\nN0003 G1 X20 F100\nN0004 M30\n", 0, 0.5);
    ASSERT_TRUE(r.part);
    EXPECT_EQ(r.counts.rapidCuts, 1u);
    EXPECT_EQ(r.counts.cuttingMoves, 2u);
    ASSERT_FALSE(r.diagnostics.empty());
    const Diagnostic& d = r.diagnostics.items().front();
    EXPECT_EQ(d.code, "REMOVAL_RAPID_CUT");
    EXPECT_EQ(d.where.block, "N0002");
    EXPECT_EQ(d.where.line, 2);
    EXPECT_EQ(d.severity, Severity::Warning);
}

// Turned with T1 (cutting edge orientation 3, nose radius 0.4) under G40:
// the theoretical tip follows the contour — face at Z0 past the axis,
// radius 30 to Z-40, shoulder, radius 35 to Z-80, out.
const char* kTurnedShaft =
    "N0001 T1 G18 G90 G54 G0 X42 Z0\n"
    "N0002 S1200 M4\n"
    "N0003 G1 X-1 F300\n"
    "N0004 G0 Z2\n"
    "N0005 X30\n"
    "N0006 G1 Z-40\n"
    "N0007 X35\n"
    "N0008 Z-80\n"
    "N0009 X41\n"
    "N0010 G0 X50 Z5\n"
    "N0011 M30\n";

double shaftRadius(double z) {  // program Z
    if (z > 0) return 0;
    if (z > -40) return 30;
    if (z > -80) return 35;
    return 40;
}

TEST(LatheRemoval, TurnedProfileFollowsTheProgrammedContour) {
    const double nose = 0.4, resolution = 0.1;
    const RemovalRunResult r = simulate(kTurnedShaft, 1, resolution);
    ASSERT_TRUE(r.part) << diagnosticsText(r.diagnostics);
    EXPECT_FALSE(r.diagnostics.hasErrors()) << diagnosticsText(r.diagnostics);
    const TurnedProfile& p = *r.part->profile();
    for (int k = 0; k < p.slices(); ++k) {
        const double z = p.sliceCentre(k) - 255.5;  // G54 Z255.5
        const double nearCorner = std::min({std::fabs(z), std::fabs(z + 40), std::fabs(z + 80)});
        if (nearCorner > nose + resolution) {
            ASSERT_NEAR(p.radiusAt(k), shaftRadius(z), 1e-3) << z;
        } else {  // the nose rounds the inner corners: within its radius
            ASSERT_GE(p.radiusAt(k), std::min(shaftRadius(z - nose), shaftRadius(z + nose)) - 1e-3)
                << z;
            ASSERT_LE(p.radiusAt(k), std::max(shaftRadius(z - nose), shaftRadius(z + nose)) + 1e-3)
                << z;
        }
    }
    // Stock Z 140..257.5 (program -115.5..2): removed 2 mm of face, 40 mm
    // down to radius 30, 40 mm down to radius 35.
    const double expected = kPi * (1600.0 * 2 + (1600.0 - 900.0) * 40 + (1600.0 - 1225.0) * 40);
    EXPECT_NEAR(r.part->removedVolume(), expected, 0.002 * expected);
}

TEST(LatheRemoval, NoseCompensationGivesTheSameDiameters) {
    // G42 (nose on the +X side) along the radius-30 stretch.
    const RemovalRunResult r = simulate(
        "N0001 T1 G18 G90 G54 G0 X45 Z2\nN0002 G1 G42 X30 F300\nN0003 Z-40\n"
        "N0004 G40 X45\nN0005 G0 Z5\nN0006 M30\n",
        1, 0.1);
    ASSERT_TRUE(r.part) << diagnosticsText(r.diagnostics);
    EXPECT_FALSE(r.diagnostics.hasErrors()) << diagnosticsText(r.diagnostics);
    const TurnedProfile& p = *r.part->profile();
    for (int k = 0; k < p.slices(); ++k) {
        const double z = p.sliceCentre(k) - 255.5;
        if (z < -1 && z > -39) {
            ASSERT_NEAR(p.radiusAt(k), 30.0, 1e-3) << z;
        }
        if (z < -41) {
            ASSERT_NEAR(p.radiusAt(k), 40.0, 1e-9) << z;
        }
    }
}

TEST(LatheRemoval, DrivenToolStandsRadiallyWithAFlatTip) {
    // T9: driven end mill, radius 4.85, no cutting edge orientation. A
    // radial plunge to X30 at Z-50 cuts a groove 9.7 wide with a flat floor;
    // the way out at X40 (above the bar's radius 40) touches nothing.
    const RemovalRunResult r = simulate(
        "N0001 T9 G18 G90 G54 G0 X45 Z-50\nN0002 G1 X30 F100\nN0003 X45\n"
        "N0004 G0 X40 Z-10\nN0005 Z-100\nN0006 M30\n",
        1, 0.1);
    ASSERT_TRUE(r.part) << diagnosticsText(r.diagnostics);
    EXPECT_TRUE(r.diagnostics.empty()) << diagnosticsText(r.diagnostics);
    const TurnedProfile& p = *r.part->profile();
    for (int k = 0; k < p.slices(); ++k) {
        const double z = p.sliceCentre(k) - 255.5;
        ASSERT_DOUBLE_EQ(p.radiusAt(k), std::fabs(z + 50) <= 4.85 ? 30.0 : 40.0) << z;
    }
    EXPECT_EQ(r.counts.rapidCuts, 0u);
}

TEST(PartModel, ResolutionAndCellsAreBounded) {
    Stock block;
    block.shape = Stock::Shape::Block;
    block.min = {0, 0, 0};
    block.max = {1000, 1000, 10};
    std::string error;
    for (double bad :
         {0.0, -1.0, std::nan(""), 1e9, std::numeric_limits<double>::infinity(), 0.001}) {
        RemovalSettings s;
        s.resolution = bad;
        EXPECT_FALSE(PartModel::create(block, s, false, error)) << bad;
        EXPECT_NE(error.find("resolution must be"), std::string::npos) << error;
    }
    RemovalSettings fine;
    fine.resolution = 0.2;  // 5000 x 5000 cells
    EXPECT_FALSE(PartModel::create(block, fine, false, error));
    EXPECT_NE(error.find("at most 2000000"), std::string::npos) << error;
    EXPECT_NE(error.find("try 0.708 mm"), std::string::npos) << error;
    fine.resolution = 0.708;
    EXPECT_TRUE(PartModel::create(block, fine, false, error)) << error;
    EXPECT_FALSE(PartModel::create(Stock{}, fine, false, error));
    EXPECT_NE(error.find("no stock"), std::string::npos) << error;
    // A block on a lathe, a bar on a mill: refused, not modelled wrongly.
    EXPECT_FALSE(PartModel::create(block, fine, true, error));
    EXPECT_NE(error.find("turning process"), std::string::npos) << error;
    Stock bar;
    bar.shape = Stock::Shape::Cylinder;
    bar.radius = 20;
    bar.to = 50;
    EXPECT_FALSE(PartModel::create(bar, fine, false, error));
    EXPECT_NE(error.find("milling process"), std::string::npos) << error;
    EXPECT_TRUE(PartModel::create(bar, fine, true, error)) << error;
    // Few cells but a volume beyond every double: refused, the removed
    // volume could not be a number (fuzz finding reentry 5a25b86).
    bar.radius = std::numeric_limits<double>::max();
    EXPECT_FALSE(PartModel::create(bar, fine, true, error));
    EXPECT_NE(error.find("too large"), std::string::npos) << error;
    block.max = {1, 1, std::numeric_limits<double>::max()};
    block.min = {0, 0, -std::numeric_limits<double>::max()};
    EXPECT_FALSE(PartModel::create(block, fine, false, error));
    EXPECT_NE(error.find("too large"), std::string::npos) << error;
}

/// Every edge of a closed surface is used twice, once in each direction.
void expectClosed(const std::string& stl, std::uint64_t triangles) {
    ASSERT_EQ(stl.size(), 84 + 50 * triangles);
    std::uint32_t count = 0;
    std::memcpy(&count, stl.data() + 80, 4);
    ASSERT_EQ(count, triangles);
    std::map<std::pair<std::array<float, 3>, std::array<float, 3>>, int> edges;
    for (std::uint64_t t = 0; t < triangles; ++t) {
        std::array<std::array<float, 3>, 3> v{};
        std::memcpy(v.data(), stl.data() + 84 + 50 * t + 12, 36);
        for (int e = 0; e < 3; ++e)
            ++edges[{v[static_cast<std::size_t>(e)], v[static_cast<std::size_t>((e + 1) % 3)]}];
    }
    for (const auto& [edge, uses] : edges) {
        const auto back = edges.find({edge.second, edge.first});
        ASSERT_TRUE(back != edges.end()) << "open edge";
        ASSERT_EQ(back->second, uses);
    }
}

/// The volume the surface encloses (divergence theorem); positive when the
/// facets face outwards.
double enclosedVolume(const std::string& stl) {
    std::uint32_t count = 0;
    std::memcpy(&count, stl.data() + 80, 4);
    double sum = 0.0;
    for (std::uint32_t t = 0; t < count; ++t) {
        float v[9];
        std::memcpy(v, stl.data() + 84 + 50 * std::size_t{t} + 12, 36);
        const double ax = v[0], ay = v[1], az = v[2], bx = v[3], by = v[4], bz = v[5], cx = v[6],
                     cy = v[7], cz = v[8];
        sum += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
    }
    return sum / 6.0;
}

// A ring groove milled under G32 with T9 (radius 4.85) 2 mm into the bar
// (D-027): the jacket's facets carry it into the STL.
const char* kRingGroove =
    "N0001 T9 G18 G90 G54 G0 X45 Z-30\nN0002 G0 C0\nN0003 G20 Z0 C0 X0\nN0004 G32 RI 40\n"
    "N0005 G0 G56 Y1 0 Z1 200\nN0006 G1 X38 F100\nN0007 G1 Y1 251.3274123 F300\n"
    "N0008 G0 X45\nN0009 G30\nN0010 G18\nN0011 M30\n";

TEST(PartStl, TheJacketsGrooveIsInTheSurface) {
    const double resolution = 1.0;  // 252 columns x 118 slices: a fast edge check
    const RemovalRunResult run = simulate(kRingGroove, 1, resolution);
    ASSERT_TRUE(run.part && run.part->jacket());
    ASSERT_GT(run.part->removedVolume(), 4000.0);
    const std::string stl = partStl(*run.part);
    expectClosed(stl, stlTriangleCount(*run.part));
    // The facets run through the cell centres: the groove's two walls are
    // slanted over a slice each (half a slice of the ring on each side),
    // and the polygon of 252 facets loses (2 pi / 252)^2 / 6 of the bar;
    // without the groove the surface would enclose 4,000 mm3 more.
    const double bar = kPi * 40.0 * 40.0 * 117.5;
    const double ring = kPi * (40.0 * 40.0 - 38.0 * 38.0);
    EXPECT_NEAR(enclosedVolume(stl), bar - run.part->removedVolume(),
                2.0 * resolution * ring + 2e-4 * bar);
}

TEST(PartStl, SurfacesEncloseTheFinishedPart) {
    // Mill: the block less the pocket; the top runs through the cell
    // centres, so the pocket's border may differ by half a cell.
    const double resolution = 0.5;
    const RemovalRunResult mill = simulate(kPocketByCentre, 0, resolution);
    ASSERT_TRUE(mill.part);
    const double block = 100.0 * 60.0 * 12.0;
    EXPECT_NEAR(enclosedVolume(partStl(*mill.part)), block - mill.part->removedVolume(),
                borderBound(120, resolution, 4.0));
    // Lathe: the bar less the turned volume, within the facets' chordal
    // error (a quarter of the resolution on the radius) and the slices.
    const RemovalRunResult lathe = simulate(kTurnedShaft, 1, resolution);
    ASSERT_TRUE(lathe.part);
    const double bar = kPi * 40.0 * 40.0 * 117.5;
    const double part = bar - lathe.part->removedVolume();
    EXPECT_NEAR(enclosedVolume(partStl(*lathe.part)), part, 0.01 * part);
}

TEST(PartStl, FinishedPartsAreClosedSurfaces) {
    const RemovalRunResult mill = simulate(kPocketByCentre, 0, 1.0);
    ASSERT_TRUE(mill.part);
    expectClosed(partStl(*mill.part), stlTriangleCount(*mill.part));
    const RemovalRunResult lathe = simulate(kTurnedShaft, 1, 1.0);
    ASSERT_TRUE(lathe.part);
    expectClosed(partStl(*lathe.part), stlTriangleCount(*lathe.part));
}

/// Volume and area of a surface given as 9 floats per triangle.
std::array<double, 2> volumeAndArea(const float* v, std::size_t triangles) {
    double volume = 0.0, area = 0.0;
    for (std::size_t t = 0; t < triangles; ++t, v += 9) {
        const double ux = v[3] - v[0], uy = v[4] - v[1], uz = v[5] - v[2];
        const double wx = v[6] - v[0], wy = v[7] - v[1], wz = v[8] - v[2];
        area += 0.5 * std::sqrt(std::pow(uy * wz - uz * wy, 2) + std::pow(uz * wx - ux * wz, 2) +
                                std::pow(ux * wy - uy * wx, 2));
        volume += (double{v[0]} * (double{v[4]} * v[8] - double{v[5]} * v[7]) -
                   double{v[1]} * (double{v[3]} * v[8] - double{v[5]} * v[6]) +
                   double{v[2]} * (double{v[3]} * v[7] - double{v[4]} * v[6])) /
                  6.0;
    }
    return {volume, area};
}

// The view's mesh (TP-029) is the STL's surface with the runs of facets in
// one plane merged: the same enclosed volume and area, far fewer triangles
// for a milled pocket and a turned shaft, on the mill the STL's heights, and
// closed edge to edge (no T-junction where a rasteriser would leave cracks).
TEST(PartStl, TheViewsMeshIsTheStlsSurfaceWithFlatRunsMerged) {
    for (const auto& [program, process] :
         {std::pair{kPocketByCentre, 0}, std::pair{kTurnedShaft, 1}, std::pair{kRingGroove, 1}}) {
        const RemovalRunResult run = simulate(program, process, 0.5);
        ASSERT_TRUE(run.part);
        const std::string stl = partStl(*run.part);
        const std::uint64_t count = stlTriangleCount(*run.part);
        std::vector<float> cells(9 * count);
        for (std::size_t t = 0; t < count; ++t)
            std::memcpy(&cells[9 * t], stl.data() + 84 + 50 * t + 12, 36);
        const std::vector<float> merged = partTriangles(*run.part);
        ASSERT_EQ(merged.size() % 9, 0u);
        std::string closed(84 + 50 * (merged.size() / 9), '\0');  // as an STL for the check
        const auto triangles = static_cast<std::uint32_t>(merged.size() / 9);
        std::memcpy(&closed[80], &triangles, 4);
        for (std::size_t t = 0; t < triangles; ++t)
            std::memcpy(&closed[84 + 50 * t + 12], &merged[9 * t], 36);
        expectClosed(closed, triangles);
        const auto full = volumeAndArea(cells.data(), count);
        const auto view = volumeAndArea(merged.data(), merged.size() / 9);
        EXPECT_NEAR(view[0], full[0], 1e-6 * full[0]) << program;
        EXPECT_NEAR(view[1], full[1], 1e-6 * full[1]) << program;
        if (process == 0 || !run.part->jacket()) {  // a groove on the jacket merges little
            EXPECT_LT(merged.size() / 9, count / 5) << program;
        } else {
            EXPECT_LE(merged.size() / 9, count) << program;
        }
        if (process != 0) continue;
        std::set<float> stlHeights, viewHeights;  // every floor of the z-map is there
        for (std::size_t i = 2; i < cells.size(); i += 3)
            stlHeights.insert(cells[i]);
        for (std::size_t i = 2; i < merged.size(); i += 3)
            viewHeights.insert(merged[i]);
        EXPECT_EQ(viewHeights, stlHeights) << program;
    }
}

}  // namespace
