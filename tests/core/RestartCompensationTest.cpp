// NC program restart on compensated contours (issue 18 §4,
// docs/decisions/compensation.md TC-013): the computing process computes
// where the axes stood before the target block in an uninterrupted run (the
// compensated re-entry point), REPOS (G77) brings them there, and the
// contour goes on from there with G41/G42 and the tool's cutting edge as if
// it had never been interrupted; the restart verifier compares the axis
// positions too. Points checked by hand in the comments.
#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

#include "RestartStation.h"
#include "cnc_core/interp/ModalGroups.h"
#include "cnc_core/restart/ReposPreview.h"
#include "cnc_core/restart/RestartVerifier.h"

namespace {

using namespace mtc::core;
using namespace mtc::test;

// ADJUST / REPOS in program 99: spindle back, the plane axes, then the
// infeed axis (mill: X Y, Z; lathe: X, Z).
const char* kMillRepos =
    "N0000 M30\n"
    "N0001 .ADJUST @150=M(2)\n"
    "N0002 .REPOS G77 S0 M=@150\n"
    "N0003 G77 X0 Y0 F2000\n"
    "N0004 G77 Z0 F1000 RTS\n";

const char* kLatheRepos =
    "N0000 M30\n"
    "N0001 .ADJUST @150=M(2)\n"
    "N0002 .REPOS G77 S0 M=@150\n"
    "N0003 G77 X0 F2000\n"
    "N0004 G77 Z0 F1000 RTS\n";

// A 50 x 40 pocket milled with T2 (radius 5) under G41, counter-clockwise
// (the tool inside, left of the wall): every corner is an inside corner, the
// tool centre runs on the rectangle (15, 15) - (55, 45). G56: no offset.
const char* kPocket =
    "N0001 T2 G17 G90 G56 G0 X30 Y30 Z5 S2000 M3\n"
    "N0002 G1 Z-2 F300\n"
    "N0003 G41 X30 Y10 ;start-up, perpendicular to N0004: centre (30, 15)\n"
    "N0004 X60 ;centre (30,15) to the corner (55,15)\n"
    "N0005 Y50 ;(55,15) to (55,45)\n"
    "N0006 X10 ;(55,45) to (15,45)\n"
    "N0007 Y10 ;(15,45) to (15,15)\n"
    "N0008 X30 ;(15,15) to (30,15)\n"
    "N0009 G40 X30 Y30 ;cancel: from (30,15) to (30,30)\n"
    "N0010 G0 Z5\n"
    "N0011 M30\n";

// Outside turning with T1 (nose radius 0.4, cutting edge 3: the tip at
// (-0.4, -0.4) of the nose centre in (Z, X)) under G42. G56: no offset.
// Nose centre: start-up end (0, 6) + 0.4 (1, 1) / sqrt 2 = (0.282843,
// 6.282843); chamfer end (-3.717157, 10.282843); inserted arc around (-4, 10)
// to (-4, 10.4); cylinder to (-10, 10.4); fillet R5 - 0.4 around (-10, 15) to
// (-14.6, 15); shoulder to (-14.6, 18). Axes = nose centre + (-0.4, -0.4).
const char* kTurning =
    "N0001 T1 G18 G90 G56 G0 X30 Z5 S1200 M3\n"
    "N0002 X6 Z3\n"
    "N0003 G42 G1 Z0 F150\n"
    "N0004 X10 Z-4\n"
    "N0005 Z-10\n"
    "N0006 G2 X15 Z-15 I15 K-10\n"
    "N0007 G1 X18\n"
    "N0008 G40 G0 X24\n"
    "N0009 Z5\n"
    "N0010 M30\n";

constexpr double kTol = 1e-6;
constexpr double kS = 0.282842712474619;  // 0.4 / sqrt 2

struct Restart {
    explicit Restart(int process) : station(process) {}

    /// Restart at N`target` of program 1, through ADJUST and REPOS. The
    /// moves the station sent until then are dropped: what follows is REPOS's.
    void reestablish(int target) {
        ASSERT_TRUE(station.accept(station.cell.selection(1, 1, target)));
        ASSERT_EQ(station.runUntilWaiting(), RestartPhase::TargetReached)
            << diagnosticsText(station.sequence.diagnostics());
        station.cell.sps.motions.clear();
        station.control.press(ControlKey::Start);
        ASSERT_EQ(station.runUntilWaiting(), RestartPhase::Reestablished)
            << diagnosticsText(station.sequence.diagnostics());
        repos = station.cell.sps.motions;
        station.cell.sps.motions.clear();
    }
    /// The program from the target block to its end.
    void finish() {
        const RunResult result = station.cell.live.run(1000);
        EXPECT_EQ(result.status, RunStatus::Ended) << diagnosticsText(result.diagnostics);
    }
    int axis(const char* name) const {
        for (int a = 0; a < station.cell.live.axes().count(); ++a)
            if (station.cell.live.axisName(a) == name) return a;
        ADD_FAILURE() << "no axis " << name;
        return 0;
    }
    double end(const Motion& m, const char* name) const {
        return m.end[static_cast<std::size_t>(axis(name))];
    }

    RestartStation station;
    std::vector<Motion> repos;
};

/// The moves of an uninterrupted run of program 1 on a station of its own.
std::vector<Motion> uninterrupted(int process, const char* program, const char* library) {
    Restart run(process);
    run.station.cell.add(library, 99);
    run.station.cell.add(program, 1);
    Interpreter& live = run.station.cell.live;
    EXPECT_TRUE(live.select(1));
    EXPECT_EQ(live.run(1000).status, RunStatus::Ended);
    return run.station.cell.sps.motions;
}

/// The moves of `all` from the first one of block `from` on.
std::vector<Motion> from(const std::vector<Motion>& all, const std::string& from) {
    for (std::size_t i = 0; i < all.size(); ++i)
        if (all[i].where.block == from)
            return {all.begin() + static_cast<std::ptrdiff_t>(i), all.end()};
    ADD_FAILURE() << "no move of " << from;
    return {};
}

void expectSameMoves(const std::vector<Motion>& expected, const std::vector<Motion>& actual,
                     int axes) {
    ASSERT_EQ(actual.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        SCOPED_TRACE("move " + std::to_string(i) + " of " + expected[i].where.block);
        EXPECT_EQ(actual[i].where.block, expected[i].where.block);
        EXPECT_EQ(actual[i].type, expected[i].type);
        EXPECT_EQ(actual[i].inserted, expected[i].inserted);
        for (int a = 0; a < axes; ++a) {
            EXPECT_NEAR(actual[i].start[static_cast<std::size_t>(a)],
                        expected[i].start[static_cast<std::size_t>(a)], kTol);
            EXPECT_NEAR(actual[i].end[static_cast<std::size_t>(a)],
                        expected[i].end[static_cast<std::size_t>(a)], kTol);
        }
        EXPECT_NEAR(actual[i].center1, expected[i].center1, kTol);
        EXPECT_NEAR(actual[i].center2, expected[i].center2, kTol);
    }
}

TEST(RestartCompensation, MillPocketReentersAtTheInsideCornerOfTheToolPath) {
    Restart mill(0);
    mill.station.cell.add(kMillRepos, 99);
    mill.station.cell.add(kPocket, 1);
    mill.reestablish(5);
    // REPOS: X Y to the tool centre at the corner (55, 15), not to the
    // programmed corner (60, 10); then Z.
    ASSERT_EQ(mill.repos.size(), 2u);
    EXPECT_NEAR(mill.end(mill.repos[0], "X"), 55.0, kTol);
    EXPECT_NEAR(mill.end(mill.repos[0], "Y"), 15.0, kTol);
    EXPECT_NEAR(mill.end(mill.repos[1], "Z"), -2.0, kTol);
    const InterpreterState& state = mill.station.cell.live.state();
    EXPECT_EQ(state.modal.g[kGroupToolPath], 41) << "G41 restored";
    EXPECT_NEAR(state.modal.machine[0], 60.0, kTol) << "the programmed point stays the contour's";
    // The rest of the pocket: the same tool path as without the restart.
    mill.finish();
    const auto after = mill.station.cell.sps.motions;
    ASSERT_FALSE(after.empty());
    EXPECT_EQ(after[0].where.block, "N0005");
    EXPECT_NEAR(mill.end(after[0], "X"), 55.0, kTol);
    EXPECT_NEAR(mill.end(after[0], "Y"), 45.0, kTol);
    expectSameMoves(from(uninterrupted(0, kPocket, kMillRepos), "N0005"), after, 3);
}

TEST(RestartCompensation, MillReentersAfterTheStartUpMove) {
    Restart mill(0);
    mill.station.cell.add(kMillRepos, 99);
    mill.station.cell.add(kPocket, 1);
    mill.reestablish(4);
    ASSERT_EQ(mill.repos.size(), 2u);
    EXPECT_NEAR(mill.end(mill.repos[0], "X"), 30.0, kTol);
    EXPECT_NEAR(mill.end(mill.repos[0], "Y"), 15.0, kTol) << "the end of the start-up move";
    mill.finish();
    expectSameMoves(from(uninterrupted(0, kPocket, kMillRepos), "N0004"),
                    mill.station.cell.sps.motions, 3);
}

TEST(RestartCompensation, LatheReentersBehindTheInsertedCornerArcWithTheCuttingEdge) {
    Restart lathe(1);
    lathe.station.cell.add(kLatheRepos, 99);
    lathe.station.cell.add(kTurning, 1);
    lathe.reestablish(5);
    // Nose centre at the end of the arc inserted after the chamfer: (-4,
    // 10.4); the axes (the tip of edge 3) at (-4.4, 10.0). Programmed: (-4, 10).
    ASSERT_EQ(lathe.repos.size(), 2u);
    EXPECT_NEAR(lathe.end(lathe.repos[0], "X"), 10.0, kTol);
    EXPECT_NEAR(lathe.end(lathe.repos[1], "Z"), -4.4, kTol);
    EXPECT_EQ(lathe.station.cell.live.state().modal.g[kGroupToolPath], 42);
    lathe.finish();
    const auto after = lathe.station.cell.sps.motions;
    ASSERT_GE(after.size(), 3u);
    EXPECT_NEAR(lathe.end(after[0], "Z"), -10.4, kTol) << "cylinder: nose centre Z-10";
    EXPECT_NEAR(lathe.end(after[1], "Z"), -15.0, kTol) << "fillet: nose centre Z-14.6";
    EXPECT_NEAR(lathe.end(after[1], "X"), 14.6, kTol) << "fillet: nose centre X15";
    expectSameMoves(from(uninterrupted(1, kTurning, kLatheRepos), "N0005"), after, 2);
}

TEST(RestartCompensation, LatheReentersOnTheChamferAfterTheStartUp) {
    Restart lathe(1);
    lathe.station.cell.add(kLatheRepos, 99);
    lathe.station.cell.add(kTurning, 1);
    lathe.reestablish(4);
    ASSERT_EQ(lathe.repos.size(), 2u);
    EXPECT_NEAR(lathe.end(lathe.repos[0], "X"), 6.0 + kS - 0.4, kTol);
    EXPECT_NEAR(lathe.end(lathe.repos[1], "Z"), kS - 0.4, kTol);
    lathe.finish();
    expectSameMoves(from(uninterrupted(1, kTurning, kLatheRepos), "N0004"),
                    lathe.station.cell.sps.motions, 2);
}

TEST(RestartCompensation, ATargetWithoutPlaneMotionReentersAsAfterAStopAndWarns) {
    // Coolant on between two walls: the restart at that block cannot know
    // the corner yet. The held wall ends at its perpendicular (60, 15), as
    // at M00; the operator is told (TC-013).
    std::string pocket = kPocket;
    pocket.replace(pocket.find("N0005 Y50"), 0, "N0045 M8\n");
    Restart mill(0);
    mill.station.cell.add(kMillRepos, 99);
    mill.station.cell.add(pocket, 1);
    mill.reestablish(45);
    ASSERT_EQ(mill.repos.size(), 2u);
    EXPECT_NEAR(mill.end(mill.repos[0], "X"), 60.0, kTol);
    EXPECT_NEAR(mill.end(mill.repos[0], "Y"), 15.0, kTol);
    bool warned = false;
    for (const Diagnostic& d : mill.station.sequence.diagnostics().items())
        warned = warned || (d.code == "RESTART_COMP_INTERRUPTED" && d.where.block == "N0045");
    EXPECT_TRUE(warned) << diagnosticsText(mill.station.sequence.diagnostics());
}

TEST(RestartCompensation, TheReposPreviewEndsAtTheCompensatedPoint) {
    Restart mill(0);
    mill.station.cell.add(kMillRepos, 99);
    mill.station.cell.add(kPocket, 1);
    RestartStation& s = mill.station;
    ASSERT_TRUE(s.accept(s.cell.selection(1, 1, 5)));
    ASSERT_EQ(s.runUntilWaiting(), RestartPhase::TargetReached);
    ReposPreviewStart start;
    start.state = s.cell.live.state();
    start.options = s.cell.live.options();
    const auto& route = s.sequence.computing().route();
    start.target = {route.targetProgram->number, s.sequence.computing().selection().target.block,
                    1};
    start.targetChain = route.targetChain;
    start.beforeAdjust = true;
    const ReposPreview path =
        previewRepositioning(s.cell.config, s.cell.store, *s.cell.machineData, start);
    EXPECT_TRUE(path.reachesTarget) << diagnosticsText(path.diagnostics);
    ASSERT_FALSE(path.corners.empty());
    EXPECT_NEAR(path.corners.back()[0], 55.0, kTol);
    EXPECT_NEAR(path.corners.back()[1], 15.0, kTol);
    EXPECT_NEAR(path.corners.back()[2], -2.0, kTol);
}

VerifyReport verifyProgram(int process, const char* program, const char* library) {
    RestartCell cell(process);
    cell.add(library, 99);
    cell.add(program, 1);
    VerifyOptions options;
    options.adjust = true;
    RestartVerifier verifier(demoCell(), process, cell.store, options);
    DiagnosticList d;
    EXPECT_TRUE(verifier.begin(1, d)) << diagnosticsText(d);
    verifier.advance(~std::uint64_t{0});
    return verifier.report();
}

std::string problems(const VerifyReport& report) {
    std::string text = report.coverageLine() + "\n" + diagnosticsText(report.diagnostics);
    for (const VerifiedTarget& t : report.problems) {
        text += t.where.block + ": " + diagnosticsText(t.diagnostics);
        for (const StateDifference& d : t.cutting)
            text += "  " + d.what + " expected " + d.expectedText + " got " + d.actualText + "\n";
    }
    return text;
}

TEST(RestartCompensation, TheVerifierReestablishesEveryTargetOfCompensatedPrograms) {
    for (const auto& [process, program, library] :
         {std::tuple{0, kPocket, kMillRepos}, std::tuple{1, kTurning, kLatheRepos}}) {
        const VerifyReport report = verifyProgram(process, program, library);
        EXPECT_TRUE(report.complete) << problems(report);
        EXPECT_GE(report.targets, 8u);
        EXPECT_EQ(report.reestablished, report.targets) << problems(report);
    }
}

TEST(RestartCompensation, TheVerifierComparesWhereTheAxesStand) {
    // A REPOS that forgets the plane axes leaves them where ADJUST found
    // them (the programmed point stays right): the verifier sees the axes.
    const char* forgetful =
        "N0000 M30\n"
        "N0001 .ADJUST @150=M(2)\n"
        "N0002 .REPOS G77 S0 M=@150\n"
        "N0003 G77 Z0 F1000 RTS\n";
    const VerifyReport report = verifyProgram(0, kPocket, forgetful);
    ASSERT_FALSE(report.problems.empty());
    bool axisDiffers = false;
    for (const VerifiedTarget& t : report.problems)
        for (const StateDifference& d : t.cutting)
            axisDiffers = axisDiffers || d.what.rfind("axis.", 0) == 0;
    EXPECT_TRUE(axisDiffers) << problems(report);
}

}  // namespace
