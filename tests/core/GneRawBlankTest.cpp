// The RAW contour (initial part contour, seed 001 ch. 3) is the blank of the
// roughing cycle after it (G-007), and no GNE value can make a pass count
// or a tessellation grow without bound (issue 15 §1).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "cnc_core/contour/Geometry2D.h"
#include "cnc_core/contour/GneExpansion.h"
#include "cnc_core/contour/GneText.h"

namespace mtc::core::gne {
namespace {

// The final part: a shaft of radius 12 over the whole window.
const char* kWindowAndPart =
    "WINDOW_01 (-48, 2, 40)\n"
    "CONT (2)\n"
    "START Z0 X0\n"
    "LINE Z0 X12\n"
    "LINE Z-48 X12\n"
    "END_CONT\n";

// A forged preform: radius 22 from Z-20 to Z-48, radius 17 from Z-6 to Z-20.
const char* kRawPreform =
    "CONT (1, RAW)\n"
    "START Z-6 X0\n"
    "LINE Z-6 X17\n"
    "LINE Z-20 X17\n"
    "LINE Z-20 X22\n"
    "LINE Z-48 X22\n"
    "END_CONT\n";

// roughing of contour 2: T1, F0.3, default S/EDGE/TR/CA/SA, SC 1, DEPTH 2,
// AX 0.5, AZ 0.2
const char* kRoughing = "CYCLE_11 (2, 1, 0.3, , , 0, , , 1, 2, 0.5, 0.2)\n";

/// A feed pass of the roughing: the Z it starts at, the Z it ends at, its X.
struct Pass {
    double fromZ, toZ, x;
};

/// The longitudinal feed passes (G1 along -Z at constant X) of the blocks.
std::vector<Pass> passesOf(const std::vector<std::string>& blocks) {
    std::vector<Pass> passes;
    double x = 0, z = 0;
    for (const std::string& block : blocks) {
        std::istringstream in(block);
        std::string word;
        bool feed = false;
        double nx = x, nz = z;
        while (in >> word) {
            if (word[0] == ';') break;
            if (word == "G1") feed = true;
            if (word == "G0" || word == "G2" || word == "G3") feed = false;
            if (word[0] == 'X') nx = std::atof(word.c_str() + 1);
            if (word[0] == 'Z') nz = std::atof(word.c_str() + 1);
        }
        if (feed && std::fabs(nx - x) < 1e-9 && nz < z - 1e-9) passes.push_back({z, nz, x});
        x = nx, z = nz;
    }
    return passes;
}

GneExpansion expand(const std::string& text) {
    return expandGne(readGne(text));
}

/// X of the first pass: levels of at most DEPTH 2 from `top` down to the
/// bore (XMIN 0) plus the allowance AX 0.5.
double firstLevel(double top) {
    return top - (top - 0.5) / std::ceil((top - 0.5) / 2.0);
}

TEST(GneRawBlank, WithoutARawContourTheWindowIsTheBlank) {
    const GneExpansion e = expand(std::string(kWindowAndPart) + kRoughing);
    ASSERT_TRUE(e.ok()) << e.diagnostics[0].message;
    const std::vector<Pass> passes = passesOf(e.calls.at(0).blocks);
    ASSERT_FALSE(passes.empty());
    EXPECT_NEAR(passes.front().x, firstLevel(40.0), 1e-4);
    EXPECT_NEAR(passes.front().fromZ, 3.0, 1e-6);  // ZMAX + SC
}

TEST(GneRawBlank, RoughingCutsOnlyWhereTheRawContourHasMaterial) {
    const GneExpansion e = expand(std::string(kWindowAndPart) + kRawPreform + kRoughing);
    ASSERT_TRUE(e.ok()) << e.diagnostics[0].message;
    const std::vector<Pass> passes = passesOf(e.calls.at(0).blocks);
    ASSERT_FALSE(passes.empty());
    for (const Pass& p : passes) {
        EXPECT_LE(p.x, 22.0 + 1e-6) << "no pass above the preform";
        // the pass starts one clearance before the preform's material at its height
        const double material = p.x > 17.0 ? -20.0 : -6.0;
        EXPECT_NEAR(p.fromZ, material + 1.0, 1e-6) << "X" << p.x;
        EXPECT_NEAR(p.toZ, -48.0, 1e-3);
    }
    EXPECT_NEAR(passes.front().x, firstLevel(22.0), 1e-4);  // levels from the preform's top
    const GneExpansion window = expand(std::string(kWindowAndPart) + kRoughing);
    EXPECT_LT(passes.size(), passesOf(window.calls.at(0).blocks).size());
}

TEST(GneRawBlank, ANewWindowEndsTheRawBlank) {
    const GneExpansion e =
        expand(std::string(kWindowAndPart) + kRawPreform + "WINDOW_01 (-48, 2, 40)\n" + kRoughing);
    ASSERT_TRUE(e.ok()) << e.diagnostics[0].message;
    EXPECT_NEAR(passesOf(e.calls.at(0).blocks).front().x, firstLevel(40.0), 1e-4);
}

TEST(GneRawBlank, ACycleOnTheRawContourItselfIsRefused) {
    const GneExpansion e =
        expand(std::string(kWindowAndPart) + kRawPreform + "CYCLE_10 (1, 1, 0.2)\n");
    ASSERT_EQ(e.diagnostics.size(), 1u);
    EXPECT_EQ(e.diagnostics[0].code, "GNE_NO_GEOMETRY");
}

TEST(GneLimits, TooManyRoughingPassesAreRefusedAtOnce) {
    // 999,988 mm of blank at a depth of 0.01 mm were 1e8 passes
    const GneExpansion e = expand(
        "WINDOW_01 (-48, 2, 1000000)\nCONT (2)\nSTART Z0 X0\nLINE Z0 X12\nLINE Z-48 X12\n"
        "END_CONT\nCYCLE_11 (2, 1, 0.3, , , 0, , , 1, 0.01, 0.5, 0.2)\n");
    ASSERT_EQ(e.diagnostics.size(), 1u);
    EXPECT_EQ(e.diagnostics[0].code, "GNE_CYCLE");
    EXPECT_NE(e.diagnostics[0].message.find("more than 2000 passes"), std::string::npos);
}

TEST(GneLimits, ValuesBeyondTheRangeAreRefusedWhenRead) {
    const GneDocument d = readGne(
        "WINDOW_01 (-48, 2, 40)\nCONT (2)\nSTART Z0 X0\n"
        "LINE Z-1000000000000000000000000000000 X12\nRD 99999999999999999999\n"
        "LINE Z-0.0000000000000000000000000000001 X12\nEND_CONT\n");
    ASSERT_EQ(d.diagnostics.size(), 2u);
    EXPECT_EQ(d.diagnostics[0].code, "GNE_BAD_NUMBER");
    EXPECT_EQ(d.diagnostics[0].line, 4u);
    EXPECT_EQ(d.diagnostics[1].code, "GNE_BAD_NUMBER");
    EXPECT_EQ(d.diagnostics[1].line, 5u);
}

TEST(GneLimits, TessellationOfAHugeOrDegenerateArcIsBounded) {
    Segment arc;
    arc.kind = Segment::ArcCCW;
    arc.centre = Point(0, 0);
    arc.start = Point(1e300, 0);
    arc.end = Point(0, 1e300);
    EXPECT_LE(tessellate({arc}).size(), 2001u);
    arc.start = arc.end = Point(std::nan(""), 0);
    EXPECT_LE(tessellate({arc}).size(), 2001u);
}

}  // namespace
}  // namespace mtc::core::gne
