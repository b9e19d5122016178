// Chamfers and roundings at their limits (issue 15 §1 and §4): absurd
// values are refused at once instead of being reduced step by step, an
// element the corners use up disappears (never a full circle that was not
// programmed), incremental chains end exactly where programmed, BRJ and
// too many blocks after an own CF/RD block are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "CompilerTestSupport.h"
#include "InterpTestSupport.h"
#include "cnc_core/compiler/CompilerText.h"
#include "cnc_core/compiler/CornerGeometry.h"
#include "cnc_core/language/Parser.h"

using namespace mtc::core;
using namespace mtc::test;

namespace {

/// Collects the motions of a run.
class MotionSink : public MachineSink {
  public:
    void motion(const Motion& m) override { motions.push_back(m); }
    void auxiliary(const AuxOutput&) override {}
    void dwell(const SourceLocation&, double) override {}
    void command(const MachineCommand&) override {}
    std::vector<Motion> motions;
};

/// Runs the object text of `result` on the demo mill; the run must end
/// without error. Returns its motions.
std::vector<Motion> runObject(const CompileResult& result) {
    const ProcessConfig& process = *demoCell().process(0);
    ProgramStore store;
    auto program = std::make_shared<Program>(parseProgram(result.objectText, {1, "OBJECT", {}}));
    EXPECT_FALSE(program->diagnostics.hasErrors()) << diagnosticsText(program->diagnostics);
    store.put(process.index, 1, program);
    MotionSink sink;
    Interpreter interpreter(process, store, sink);
    DiagnosticList diagnostics;
    EXPECT_TRUE(interpreter.select(1, 0, &diagnostics));
    const RunResult run = interpreter.run(kDefaultBlockBudget);
    EXPECT_NE(run.status, RunStatus::Error) << diagnosticsText(run.diagnostics);
    return sink.motions;
}

bool isArc(const Motion& m) {
    return m.type == MotionType::ArcCW || m.type == MotionType::ArcCCW;
}

/// An arc whose start and end coincide runs as a full circle.
bool isFullCircle(const Motion& m) {
    if (!isArc(m)) return false;
    for (int a = 0; a < m.axisCount; ++a)
        if (std::fabs(m.start[static_cast<std::size_t>(a)] - m.end[static_cast<std::size_t>(a)]) >
            1e-9)
            return false;
    return true;
}

TEST(CompilerCornerLimits, HugeValuesAreRefusedAtOnce) {
    for (const char* value : {"1e23", "100000000000000000000000", "1E40", "1e308", "100000"}) {
        for (const char* kind : {"CF", "RD"}) {
            const std::string text = std::string("N0001 G1 G17 G90 X0 Y0 F1000\nN0002 X10 ") +
                                     kind + value + "\nN0003 Y10\nN0004 M30\n";
            const CompileResult r = compileText(text);
            EXPECT_EQ(codes(r), std::vector<std::string>{"COMPILER_CFRD_VALUE"}) << text;
            ASSERT_FALSE(r.errors.empty());
            EXPECT_EQ(r.errors[0].block, "N0002");
            EXPECT_EQ(r.errors[0].sourceLine, 2);
        }
    }
    // the largest value the NC can write is reduced as any other
    const CompileResult r =
        compileText("N0001 G1 X0 Y0 F1000\nN0002 X10 RD99999.9999\nN0003 Y10\n");
    EXPECT_EQ(codes(r), std::vector<std::string>{"COMPILER_CFRD_REDUCED"});
}

TEST(CompilerCornerLimits, NonFiniteAndTinyValues) {
    for (const char* value : {"=nan", "=inf", "=-1e-300"}) {
        const CompileResult r =
            compileText(std::string("N1 G1 X0 Y0\nN2 X10 RD") + value + "\nN3 Y10\n");
        EXPECT_EQ(codes(r), std::vector<std::string>{"COMPILER_CFRD_VALUE"}) << value;
    }
    // 1e-300 fits but is less than one step of 0.0001: nothing is inserted
    // (before: an arc from a point to itself, a full circle)
    const CompileResult r = compileText("N1 G1 X0 Y0 F100\nN2 X10 RD1e-300\nN3 Y10\n");
    EXPECT_EQ(r.status, CompileStatus::Compiled);
    EXPECT_EQ(codes(r), std::vector<std::string>{"COMPILER_CFRD_REDUCED"});
    EXPECT_EQ(objectBlocks(r), (std::vector<std::string>{"N0001:0000 G1 X0 Y0 F100",
                                                         "N0002:0000 X10", "N0003:0000 Y10"}));
}

TEST(CompilerCornerLimits, FittingTakesFewProbesWhateverTheSize) {
    // the old reduction stepped down by 0.0001 from the requested size
    const PathElement a = PathElement::line({0, 0}, {10, 0});
    const PathElement b = PathElement::line({10, 0}, {10, 10});
    for (double requested : {1e5, 1e23, 1e40, 1e308, std::numeric_limits<double>::infinity()}) {
        const CornerFit fit = fitCorner(CornerKind::Rounding, a, 0.0, b, requested);
        if (std::isinf(requested)) {
            EXPECT_EQ(fit.applied, 0.0);
            continue;
        }
        EXPECT_TRUE(fit.reduced);
        EXPECT_NEAR(fit.applied, 10.0, 1e-9) << requested;
    }
    const CornerFit nan = fitCorner(CornerKind::Chamfer, a, 0.0, b, std::nan(""));
    EXPECT_EQ(nan.applied, 0.0);
}

TEST(CompilerCornerLimits, CoordinatesBeyondTheComputableRangeAreRefused) {
    const CompileResult r = compileText("N1 G1 X0 Y0 F100\nN2 X99999999999999 RD1\nN3 Y10\n");
    EXPECT_EQ(codes(r), std::vector<std::string>{"COMPILER_CFRD_BAD_ELEMENT"});
}

TEST(CompilerCornerLimits, AnArcUsedUpByAChamferDisappears) {
    // The chamfer is reduced to the arc's length (20 * pi / 2 = 31.41593):
    // 31.4159 leaves 0.00003 mm of the arc, which is written as its end
    // point. Before: "N0003:0000 G3 X60 Y-20 I60 J0" from that end point, a
    // full circle.
    const CompileResult r = compileText(
        "N0001 G1 G17 G90 X0 Y0 F1000\nN0002 X40 CF40\nN0003 G3 X60 Y-20 I60 J0\n"
        "N0004 G1 X80\nN0005 M30\n");
    ASSERT_EQ(r.status, CompileStatus::Compiled);
    const std::vector<std::string> b = objectBlocks(r);
    ASSERT_EQ(b.size(), 6u);
    EXPECT_EQ(b[1], "N0002:0000 X8.5841 Y0");
    EXPECT_EQ(b[2], "N0002:0001 G1 X60 Y-20");
    EXPECT_EQ(b[3], "N0003:0000 G3");  // keeps the modal G3 of the block, no motion
    EXPECT_EQ(b[4], "N0004:0000 G1 X80");
    for (const Motion& m : runObject(r))
        EXPECT_FALSE(isFullCircle(m)) << m.where.block;
}

TEST(CompilerCornerLimits, ALineUsedUpFromBothSidesDisappears) {
    const CompileResult r =
        compileText("N1 G0 X-5 Y0\nN2 G1 X10 F100 CF4\nN3 Y8 CF4\nN4 X0\nN5 M30\n");
    ASSERT_EQ(r.status, CompileStatus::Compiled);
    EXPECT_TRUE(codes(r).empty());
    const std::vector<std::string> b = objectBlocks(r);
    ASSERT_EQ(b.size(), 7u);
    EXPECT_EQ(b[1], "N0002:0000 G1 X6 Y0 F100");
    EXPECT_EQ(b[3], "N0003:0000");  // Y8 minus 4 at each end: nothing left
    EXPECT_EQ(b[4], "N0003:0001 G1 X6 Y8");
    for (const Motion& m : runObject(r)) {
        double length = 0;
        for (int a = 0; a < m.axisCount; ++a)
            length += std::fabs(m.end[static_cast<std::size_t>(a)] -
                                m.start[static_cast<std::size_t>(a)]);
        EXPECT_GT(length, 1e-9) << m.where.block << " does not move";
    }
}

TEST(CompilerCornerLimits, RandomReducedCornersNeverRunAFullCircle) {
    std::mt19937 random(15);
    std::uniform_real_distribution<double> coordinate(-40.0, 40.0);
    std::uniform_real_distribution<double> size(0.0, 60.0);
    int arcs = 0;
    for (int program = 0; program < 40; ++program) {
        std::string text = "N0000 G1 G17 G90 X0 Y0 F1000\n";
        double x = 0, y = 0;
        for (int block = 1; block <= 12; ++block) {
            const double nx = std::round(coordinate(random) * 10) / 10;
            const double ny = std::round(coordinate(random) * 10) / 10;
            char line[160];
            const char* corner = block % 2 ? "RD" : "CF";
            if (block % 3 == 0 && (nx != x || ny != y)) {
                // a half circle from (x, y) to (nx, ny) around the midpoint
                std::snprintf(line, sizeof line, "N%04d G%d X%.1f Y%.1f I%.2f J%.2f %s%.1f\n",
                              block, block % 2 ? 2 : 3, nx, ny, (x + nx) / 2, (y + ny) / 2, corner,
                              size(random));
                ++arcs;
            } else {
                std::snprintf(line, sizeof line, "N%04d G1 X%.1f Y%.1f %s%.1f\n", block, nx, ny,
                              corner, size(random));
            }
            text += line;
            x = nx, y = ny;
        }
        text += "N0013 G1 X0 Y0\nN0014 M30\n";
        const CompileResult r = compileText(text);
        ASSERT_EQ(r.status, CompileStatus::Compiled) << text;
        for (const Motion& m : runObject(r))
            EXPECT_FALSE(isFullCircle(m)) << text << "\n" << r.objectText;
    }
    EXPECT_GT(arcs, 50);
}

TEST(CompilerCornerLimits, FiftyFiveIncrementalCornersEndExactly) {
    // Each inserted block and each shortened block is written with 4
    // decimals; differences of rounded points add up exactly, rounded
    // differences drifted 0.1 um here (0.9 um in the program).
    std::string text = "N0000 G1 G17 G90 X0 Y0 F1000\nN0001 G91\n";
    int number = 2;
    for (int i = 0; i < 55; ++i) {
        text += "N" + formatFourDigits(number++) + " X1.7 Y0.9 RD0.3\n";
        text += "N" + formatFourDigits(number++) + " X0.4 Y-1.3 CF0.7\n";
    }
    text += "N" + formatFourDigits(number) + " X1\n";
    text += "N" + formatFourDigits(number + 1) + " M30\n";
    const CompileResult r = compileText(text);
    ASSERT_EQ(r.status, CompileStatus::Compiled);
    const std::vector<Motion> motions = runObject(r);
    ASSERT_FALSE(motions.empty());
    // X: 55 * 2.1 + 1 = 116.5, Y: 55 * -0.4 = -22 (axis 0 = X, 1 = Y)
    EXPECT_NEAR(motions.back().end[0], 116.5, 1e-9);
    EXPECT_NEAR(motions.back().end[1], -22.0, 1e-9);
}

TEST(CompilerCornerLimits, BrjBetweenTheMotionBlocksIsIllegal) {
    const CompileResult r = compileText("N1 G1 X0 Y0 F100\nN2 X10 RD1\nN3 BRJ\nN4 Y10\nN5 M30\n");
    ASSERT_EQ(codes(r), std::vector<std::string>{"COMPILER_CFRD_ILLEGAL"});
    EXPECT_EQ(r.errors[0].block, "N0002");
}

TEST(CompilerCornerLimits, AnOwnCfRdBlockCountsAmongTheTwentyBlocksBetween) {
    // seed 001 ch. 2: at most twenty blocks without motion between the two
    // motion blocks; an own CF/RD block is one of them
    auto program = [](int after) {
        std::string text = "N0000 G1 X0 Y0 F100\nN0001 X10\nN0002 RD1\n";
        for (int i = 0; i < after; ++i)
            text += "N" + std::to_string(1000 + i) + " M8\n";
        return text + "N0099 Y10\n";
    };
    EXPECT_EQ(compileText(program(19)).status, CompileStatus::Compiled);
    const CompileResult r = compileText(program(20));
    EXPECT_EQ(codes(r), std::vector<std::string>{"COMPILER_CFRD_NO_TARGET"});
    EXPECT_EQ(r.errors[0].block, "N0002");
}

}  // namespace
