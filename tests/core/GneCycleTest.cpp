// Cycle geometry of the GNE (roughing passes inside the blank and outside
// the allowance, contour and residual cut, milling with tool radius
// compensation) and the expanded blocks running on the demo cell.

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "InterpTestSupport.h"
#include "cnc_core/contour/ContourSolver.h"
#include "cnc_core/contour/GneExpansion.h"
#include "cnc_core/contour/GneText.h"
#include "cnc_core/contour/PathOffset.h"

namespace mtc::core::gne {
namespace {

const char* kShaft =
    "WINDOW_01 (-48, 2, 40)\n"
    "CONT (1)\n"
    "START Z0 X0\n"
    "LINE Z0 X15\n"
    "CF 1\n"
    "LINE Z-12 X15\n"
    "RELIEF E R0.6 T0.2\n"
    "LINE Z-12 X25\n"
    "RD 2\n"
    "LINE A180 L6\n"
    "CW Z-28 X35 R10 TAN\n"
    "CCW Z-36 X35 K-32 I35\n"
    "LINE Z-40 X38.5\n"
    "LINE Z-45 X38.5\n"
    "END_CONT\n";

/// One straight move of the expanded blocks (arcs only as their end points).
struct Move {
    bool rapid = false;
    Point from, to;  ///< plane coordinates (Z, X) or (X, Y)
};

/// Reads "G0/G1/G2/G3 X.. Z.." blocks of the turning plane into moves.
std::vector<Move> movesOf(const std::vector<std::string>& blocks, bool turning) {
    std::vector<Move> moves;
    Point at(0, 0);
    bool known = false;
    for (const std::string& block : blocks) {
        std::istringstream in(block);
        std::string word;
        int g = -1;
        Point next = at;
        bool moved = false;
        while (in >> word) {
            if (word[0] == ';') break;
            const double v = std::atof(word.c_str() + 1);
            if (word[0] == 'G' && (v <= 3)) g = static_cast<int>(v);
            if (word[0] == 'X') (turning ? next.y() : next.x()) = v, moved = true;
            if (word[0] == (turning ? 'Z' : 'Y')) (turning ? next.x() : next.y()) = v, moved = true;
        }
        if (g >= 0 && moved) {
            if (known) moves.push_back({g == 0, at, next});
            at = next;
            known = true;
        }
    }
    return moves;
}

/// The allowance region test of the roughing: a point is forbidden when it
/// lies inside the part or within the allowance ellipse (AZ, AX) of its outline.
struct AllowanceRegion {
    std::vector<Point> outline;  // closed, part on one side
    double az, ax;

    /// Smallest distance to the outline in allowance units (1 = on the allowance boundary).
    double scaledDistance(const Point& p) const {
        double best = 1e9;
        for (std::size_t i = 0; i < outline.size(); ++i) {
            Point a = outline[i], b = outline[(i + 1) % outline.size()];
            a = Point(a.x() / az, a.y() / ax), b = Point(b.x() / az, b.y() / ax);
            const Point q(p.x() / az, p.y() / ax), d = b - a;
            const double t =
                std::clamp((q - a).dot(d) / std::max(d.squaredNorm(), 1e-18), 0.0, 1.0);
            best = std::min(best, (a + t * d - q).norm());
        }
        return best;
    }

    bool forbidden(const Point& p) const {
        for (std::size_t i = 0; i < outline.size(); ++i) {
            Point a = outline[i], b = outline[(i + 1) % outline.size()];
            a = Point(a.x() / az, a.y() / ax), b = Point(b.x() / az, b.y() / ax);
            const Point q(p.x() / az, p.y() / ax), d = b - a;
            const double t =
                std::clamp((q - a).dot(d) / std::max(d.squaredNorm(), 1e-18), 0.0, 1.0);
            if ((a + t * d - q).norm() < 1.0 - 1e-4) return true;
        }
        bool inside = false;  // even-odd rule
        for (std::size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++) {
            const Point &a = outline[i], &b = outline[j];
            if ((a.y() > p.y()) != (b.y() > p.y()) &&
                p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
                inside = !inside;
        }
        return inside;
    }
};

GneExpansion expand(const std::string& text) {
    GneDocument doc = readGne(text);
    EXPECT_TRUE(doc.ok()) << doc.diagnostics[0].message;
    GneExpansion e = expandGne(doc);
    EXPECT_TRUE(e.ok()) << e.diagnostics[0].line << " " << e.diagnostics[0].message;
    return e;
}

TEST(GneCycle, RoughingStaysInsideTheBlankAndOutsideTheAllowance) {
    for (double radius : {0.0, 0.8}) {
        const std::string cycle =
            "CYCLE_11 (1, 1, 0.3, , 3, " + formatValue(radius) + ", , , 1, 2.5, 0.5, 0.2)\n";
        GneExpansion e = expand(std::string(kShaft) + cycle);
        ASSERT_EQ(e.calls.size(), 1u);
        AllowanceRegion region{tessellate(e.geometries[0].paths[0], 0.0005), 0.2, 0.5};
        region.outline.push_back({-45, 0});
        region.outline.push_back({0, 0});
        int cuts = 0;
        double lowest = 1e9;
        for (const Move& m : movesOf(e.calls[0].blocks, true)) {
            if (m.rapid) {  // towards the part only outside the blank; never into the allowance
                if (m.to.x() < m.from.x() - 1e-9) {
                    EXPECT_GT(m.to.x(), 2.0 - 1e-9);
                }
                for (int s = 0; s <= 50; ++s)
                    EXPECT_FALSE(region.forbidden(m.from + (m.to - m.from) * (s / 50.0)));
                continue;
            }
            ++cuts;
            for (const Point& p : {m.from, m.to}) {  // blank + clearance
                EXPECT_LE(p.y(), 40.0 + 1e-9);
                EXPECT_GE(p.x(), -48.0 - 1e-9);
                EXPECT_LE(p.x(), 2.0 + 1.0 + radius + 1e-9);
            }
            lowest = std::min(lowest, m.to.y());
            for (int s = 0; s <= 40; ++s) {  // the nose circle along the move
                const Point tip = m.from + (m.to - m.from) * (s / 40.0);
                const Point centre = tip - radius * edgeVector(3);
                for (int k = 0; k < 24; ++k) {
                    const double a = k * kPi / 12;
                    const Point q = centre + radius * Point(std::cos(a), std::sin(a));
                    ASSERT_FALSE(region.forbidden(q))
                        << "nose point " << q.transpose() << " of the move to " << m.to.transpose();
                }
            }
        }
        EXPECT_GE(cuts, 2 * 16);         // (40 - 0.5) / 2.5 -> 16 levels, cut + lift each
        EXPECT_NEAR(lowest, 0.5, 1e-3);  // down to the allowance above the axis
    }
}

TEST(GneCycle, RoughingLeavesNoBlankAboveTheAllowanceOnTheCylinder) {
    GneExpansion e =
        expand(std::string(kShaft) + "CYCLE_11 (1, 1, 0.3, , 3, 0, , , 1, 2, 0.5, 0.2)\n");
    // Every level reaches the allowance region (the stop point is within a
    // small distance of the forbidden region): nothing is left standing.
    AllowanceRegion region{tessellate(e.geometries[0].paths[0], 0.0005), 0.2, 0.5};
    region.outline.push_back({-45, 0});
    region.outline.push_back({0, 0});
    for (const Move& m : movesOf(e.calls[0].blocks, true)) {
        if (m.rapid || m.to.x() > m.from.x()) continue;  // cuts towards -Z only
        if (m.to.x() <= -45 + 1e-6) continue;            // stopped by the end of the contour
        EXPECT_LT(region.scaledDistance(m.to), 1.05) << m.to.transpose();
    }
}

TEST(GneCycle, ContourCutFollowsTheContour) {
    GneExpansion e = expand(std::string(kShaft) + "CYCLE_10 (1, 2, 0.1)\n");
    const std::vector<Segment>& path = e.geometries[0].paths[0];
    int onContour = 0;
    for (const Move& m : movesOf(e.calls[0].blocks, true)) {
        if (m.rapid) continue;
        double best = 1e9;
        for (const Segment& s : path)
            best = std::min(best, distanceTo(s, m.to));
        if (best < 1e-4) ++onContour;
    }
    EXPECT_EQ(onContour, static_cast<int>(path.size()) + 1);  // start + every element end
    EXPECT_EQ(e.tools.size(), 1u);
    EXPECT_EQ(e.tools[0].edge, 3);
}

TEST(GneCycle, ResidualCutKeepsTheUniformAllowance) {
    GneExpansion e = expand(std::string(kShaft) + "CYCLE_12 (1, 1, 0.2, , 9, , , , 1, 0.3)\n");
    const std::vector<Segment>& path = e.geometries[0].paths[0];
    const auto moves = movesOf(e.calls[0].blocks, true);
    int checked = 0;
    for (std::size_t i = 1; i + 1 < moves.size(); ++i) {  // without approach and retract
        if (moves[i].rapid || moves[i - 1].rapid || moves[i + 1].rapid) continue;
        double best = 1e9;
        for (const Segment& s : path)
            best = std::min(best, distanceTo(s, moves[i].to));
        EXPECT_NEAR(best, 0.3, 1e-3) << moves[i].to.transpose();
        ++checked;
    }
    EXPECT_GT(checked, 8);
}

TEST(GneCycle, MillingOffsetsByTheToolRadius) {
    GneExpansion e = expand(
        "WINDOW_02 (0, 0, 120, 80)\nFORM_52 (3, 90, 20, 8)\nFORM_56 (7, 10, 10, 50, 40, 6)\n"
        "CYCLE_40 (3, 6, 300, , 2.5, 2, 2, -3)\nCYCLE_40 (7, 6, 300, , 4, 1, 2, -3)\n"
        "CYCLE_40 (7, 6, 300, , 4, 0, 2, -3)\n");
    ASSERT_EQ(e.calls.size(), 3u);
    auto radii = [&](std::size_t call, const Point& c) {
        std::vector<double> r;
        for (const Move& m : movesOf(e.calls[call].blocks, false))
            if (!m.rapid) r.push_back((m.to - c).norm());
        return r;
    };
    for (double r : radii(0, {90, 20}))
        EXPECT_NEAR(r, 8 + 2.5, 1e-4);  // outside (right of CCW)
    // Inside the rectangle (left of CCW): every point 4 mm inside the sides.
    for (const Move& m : movesOf(e.calls[1].blocks, false)) {
        if (m.rapid) continue;
        EXPECT_GE(m.to.x(), 14 - 1e-4);
        EXPECT_LE(m.to.x(), 46 + 1e-4);
        EXPECT_GE(m.to.y(), 14 - 1e-4);
        EXPECT_LE(m.to.y(), 36 + 1e-4);
    }
    EXPECT_NE(std::find(e.calls[1].blocks.begin(), e.calls[1].blocks.end(), "G1 Z-3 F300"),
              e.calls[1].blocks.end());
}

TEST(GneCycle, RefusalsNameTheCycleLine) {
    GneExpansion e = expandGne(
        readGne("WINDOW_02 (0, 0, 120, 80)\nFORM_57 (8, 30, 40, 20, 10, 30, 2)\n"
                "CYCLE_40 (8, 3, 800, , 5, 1, 2, -5)\nCYCLE_40 (9, 3, 800, , 5, 1, 2, -5)\n"
                "FORM_54 (5, 10, 70, 5, 0, \"A\")\nCYCLE_40 (5, 3, 800, , 5, 1, 2, -5)\n"
                "CYCLE_40 (8, 3, 800, , 0, 1, -5, 2)\n"));
    std::vector<std::string> found;
    for (const GneDiagnostic& d : e.diagnostics)
        found.push_back(std::to_string(d.line) + " " + d.code);
    EXPECT_EQ(found, (std::vector<std::string>{"3 GNE_CYCLE", "4 GNE_NO_GEOMETRY", "6 GNE_CYCLE",
                                               "7 GNE_CYCLE"}));
}

TEST(GneCycle, ToolBlockRecordsTheAssumption) {
    ToolAssumption t{4, true, 0.8, 3, 55, 93, 0};
    ToolAssumption back;
    ASSERT_TRUE(parseToolBlock(toolBlock(t), back));
    EXPECT_EQ(back.tool, 4);
    EXPECT_EQ(back.edge, 3);
    EXPECT_EQ(back.radius, 0.8);
    EXPECT_EQ(back.cornerAngle, 55);
    EXPECT_EQ(back.settingAngle, 93);
    EXPECT_FALSE(parseToolBlock("T4 ;tool", back));
}

// Numbers of a tool block come from the program text: out of range they are
// refused (they were converted with atoi and a cast, undefined behaviour).
TEST(GneCycle, ToolBlockWithNumbersOutOfRangeIsNoToolBlock) {
    ToolAssumption back;
    for (const char* text :
         {"T99999999999 ;GNE TOOL TR 1", "T4 ;GNE TOOL EDGE 1e300 TR 0.4", "T4 ;GNE TOOL EDGE -3",
          "T4 ;GNE TOOL EDGE 2.5", "T4x ;GNE TOOL TR 1", "T-4 ;GNE TOOL TR 1"})
        EXPECT_FALSE(parseToolBlock(text, back)) << text;
    ASSERT_TRUE(parseToolBlock("T9999999 ;GNE TOOL EDGE 9 TR 0.4 CA 80 SA 95", back));
    EXPECT_EQ(back.tool, 9999999);
    EXPECT_EQ(back.edge, 9);
}

/// The expanded blocks run on the demo cell without any diagnostic.
void expectRuns(const GneExpansion& e, int process) {
    std::string program;
    for (const ExpandedCall& call : e.calls)
        for (const std::string& block : call.blocks)
            program += block + "\n";
    program += "M30\n";
    mtc::test::Station station(mtc::test::demoCell(), process);
    RunResult r = station.run(program, 1);
    EXPECT_EQ(r.status, RunStatus::Ended);
    EXPECT_TRUE(r.diagnostics.empty()) << mtc::test::diagnosticsText(r.diagnostics);
    EXPECT_NE(station.sink->text.find(" cw "), std::string::npos);
}

TEST(GneCycle, TurningBlocksRunOnTheLathe) {
    expectRuns(
        expand(std::string(kShaft) + "CYCLE_11 (1, 1, 0.3, 1200, 3, 0.4, , , 1, 2, 0.5, 0.2)\n"
                                     "CYCLE_12 (1, 1, 0.2, , 3, 0.4, , , , 0.1)\n"
                                     "CYCLE_10 (1, 2, 0.1, , 3, 0.4)\n"),
        1);
}

TEST(GneCycle, MillingBlocksRunOnTheMill) {
    expectRuns(expand("WINDOW_02 (0, 0, 120, 80, 0, -20)\n"
                      "FORM_50 (1, 10, 10, 40, 10, 8)\nFORM_51 (2, 60, 40, 20, 0, 90, 6)\n"
                      "FORM_52 (3, 90, 20, 8)\nFORM_53 (4, 90, 60, 12, 6)\n"
                      "FORM_54 (5, 10, 70, 5, 0, \"MTC 200\")\n"
                      "FORM_55 (6, 60, 40, 30, 120, 4, \"INDRAMAT\")\n"
                      "FORM_56 (7, 5, 5, 115, 75, 5)\nFORM_57 (8, 30, 40, 20, 10, 30, 4)\n"
                      "CYCLE_40 (1, 1, 500, 3000, 3.5, 1, 2, -4)\n"
                      "CYCLE_40 (2, 6, 500, , 2, 1, 2, -4)\n"
                      "CYCLE_40 (3, 1, 500, , 3.5, 2, 2, -4)\n"
                      "CYCLE_40 (4, 1, 500, , 3.5, 2, 2, -4)\n"
                      "CYCLE_40 (5, 6, 300, , 2, 0, 2, -0.3)\n"
                      "CYCLE_40 (6, 6, 300, , 2, 0, 2, -0.3)\n"
                      "CYCLE_40 (7, 1, 500, , 3.5, 2, 2, -4)\n"
                      "CYCLE_40 (8, 1, 500, , 3.5, 1, 2, -4)\n"),
               0);
}

TEST(GneCycle, RunWarnsWhenTheToolDiffersFromTheCycle) {
    // The cycle was programmed for a nose radius of 0.8 and edge 2; T1 of
    // the demo lathe has 0.4 and edge 3 (seed 001 ch. 3 caution).
    mtc::test::Station station(mtc::test::demoCell(), 1);
    RunResult r = station.run("N0001 T1 ;GNE TOOL EDGE 2 TR 0.8 CA 80 SA 95\nN0002 M30\n", 1);
    EXPECT_EQ(r.status, RunStatus::Ended);
    const std::string text = mtc::test::diagnosticsText(r.diagnostics);
    EXPECT_EQ(text.rfind("warning GNE_TOOL_MISMATCH P1 N0001", 0), 0u) << text;
    EXPECT_NE(text.find("radius 0.4"), std::string::npos) << text;
    EXPECT_NE(text.find("orientation 3"), std::string::npos) << text;
    mtc::test::Station fits(mtc::test::demoCell(), 1);
    RunResult ok = fits.run("N0001 T1 ;GNE TOOL EDGE 3 TR 0.4 CA 80 SA 95\nN0002 M30\n", 1);
    EXPECT_TRUE(ok.diagnostics.empty()) << mtc::test::diagnosticsText(ok.diagnostics);
}

}  // namespace
}  // namespace mtc::core::gne
