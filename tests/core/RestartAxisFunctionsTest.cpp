// Interpreter additions for NC program restart: G74 (homing), G75 (hard
// stop), G77 (REPOS to the re-entry point), G32 without RI while restoring,
// takeMachinePositions (docs/decisions/restart.md ).
#include <gtest/gtest.h>

#include "InterpTestSupport.h"

namespace {

using namespace mtc::core;
using namespace mtc::test;

/// Sets a re-entry point on the station's interpreter.
void setReentry(Station& s, std::array<double, kMaxAxes> machine, double speed1 = 0.0) {
    InterpreterState state = s.interpreter->state();
    state.reentry.valid = true;
    state.reentry.machine = machine;
    state.reentry.spindleSpeed[1] = speed1;
    s.interpreter->restoreState(state);
}

TEST(RestartAxisFunctions, G74HomesTheNamedAxesToMachineZero) {
    Station mill(demoCell(), 0);
    const RunResult r = mill.run("N1 G0 G54 X10 Y20 Z5\nN2 G74 X0 Z0\nN3 M30\n");
    EXPECT_EQ(r.status, RunStatus::Ended) << diagnosticsText(r.diagnostics);
    EXPECT_NE(mill.sink->text.find("motion P1 N0002 L2 rapid X=0.0000 Z=0.0000\n"),
              std::string::npos)
        << mill.sink->text;
}

TEST(RestartAxisFunctions, G74ClampsTheReferencePointIntoTheTravelRange) {
    Station lathe(demoCell(), 1);
    const RunResult r = lathe.run("N1 G0 Z2 300\nN2 G74 Z2 0\nN3 M30\n");
    EXPECT_EQ(r.status, RunStatus::Ended) << diagnosticsText(r.diagnostics);
    EXPECT_EQ(lathe.interpreter->state().modal.machine[4], 0.0) << "Z2 range 0..700";
}

TEST(RestartAxisFunctions, G75IsAFeedMoveThatLeavesTheInterpolationGroup) {
    Station mill(demoCell(), 0);
    const RunResult r = mill.run("N1 G0 X10\nN2 G75 X30 F200\nN3 @1=G(1)\nN4 M30\n");
    EXPECT_EQ(r.status, RunStatus::Ended) << diagnosticsText(r.diagnostics);
    EXPECT_NE(mill.sink->text.find("motion P1 N0002 L2 linear X=30.0000"), std::string::npos);
    EXPECT_EQ(mill.interpreter->state().variables.values[1], 0.0) << "G0 stays modal";
}

TEST(RestartAxisFunctions, AxisFunctionsNeedAxes) {
    Station mill(demoCell(), 0);
    EXPECT_EQ(errorCodes(mill.run("N1 G74\n").diagnostics),
              std::vector<std::string>{"AXIS_FUNCTION_NO_AXIS"});
    EXPECT_EQ(errorCodes(mill.run("N1 G74 G77 X0\n").diagnostics),
              std::vector<std::string>{"G_GROUP_CONFLICT"});
    EXPECT_EQ(errorCodes(mill.run("N1 G75 G4 X1 F1\n").diagnostics),
              std::vector<std::string>{"AXIS_FUNCTION_COMBINATION"});
}

TEST(RestartAxisFunctions, G77WithoutReentryPointIsRefused) {
    Station mill(demoCell(), 0);
    EXPECT_EQ(errorCodes(mill.run("N1 G77 X0 Y0 F1000\n").diagnostics),
              std::vector<std::string>{"REPOS_NO_REENTRY_POINT"});
}

TEST(RestartAxisFunctions, G77MovesTheNamedAxesToTheReentryPoint) {
    Station mill(demoCell(), 0);
    mill.add("N1 G77 X0 Y0 F2000\nN2 G77 Z0\nN3 @1=G(1)\nN4 RTS\n", 1);
    ASSERT_TRUE(mill.interpreter->select(1));
    setReentry(mill, {-70, -32, -118});
    InterpreterState state = mill.interpreter->state();
    state.callStack.push_back({state.program, 3, 3});  // RTS needs a caller
    mill.interpreter->restoreState(state);
    const RunResult r = mill.interpreter->run(3);
    EXPECT_EQ(errorCodes(r.diagnostics), std::vector<std::string>{"BLOCK_BUDGET"});
    EXPECT_NE(mill.sink->text.find("motion P1 N0001 L1 linear X=-70.0000 Y=-32.0000 F=2000.0000\n"),
              std::string::npos)
        << mill.sink->text;
    EXPECT_NE(mill.sink->text.find("motion P1 N0002 L2 rapid Z=-118.0000\n"), std::string::npos)
        << "without a feed G77 is a rapid move\n"
        << mill.sink->text;
    EXPECT_EQ(mill.interpreter->state().modal.feed, 0.0) << "F of a G77 block is not modal";
    EXPECT_EQ(mill.interpreter->state().modal.g[kGroupInterpolation], 0);
}

TEST(RestartAxisFunctions, G77SpindleWordReestablishesSpeedAndSpindleMode) {
    Station lathe(demoCell(), 1);
    lathe.add("N1 G77 S1=0 M3\nN2 M30\n", 1);
    ASSERT_TRUE(lathe.interpreter->select(1));
    setReentry(lathe, {}, 1250.0);
    InterpreterState state = lathe.interpreter->state();
    state.modal.rotaryAxisMode[1] = 1;
    lathe.interpreter->restoreState(state);
    ASSERT_EQ(lathe.interpreter->step().status, RunStatus::Running);
    EXPECT_EQ(lathe.sink->text, "aux P1 N0001 L1 S1=1250.0000\naux P1 N0001 L1 M3\n");
    EXPECT_EQ(lathe.interpreter->state().modal.spindleSpeed[1], 1250.0);
    EXPECT_EQ(lathe.interpreter->state().modal.rotaryAxisMode[1], 0);
}

TEST(RestartAxisFunctions, ProgramEndForgetsTheReentryPoint) {
    Station mill(demoCell(), 0);
    mill.add("N1 M30\n", 1);
    ASSERT_TRUE(mill.interpreter->select(1));
    setReentry(mill, {});
    EXPECT_EQ(mill.interpreter->run().status, RunStatus::Ended);
    EXPECT_FALSE(mill.interpreter->state().reentry.valid);
}

TEST(RestartAxisFunctions, G32WithoutRiTakesTheLastRadiusOnlyWhileRestoring) {
    Station lathe(demoCell(), 1);
    const std::string program = "N1 G0 C0\nN2 G20 Z0 C0 X0\nN3 G32\nN4 M30\n";
    EXPECT_EQ(errorCodes(lathe.run(program).diagnostics),
              std::vector<std::string>{"G32_RI_MISSING"});
    lathe.add(program, 2);
    ASSERT_TRUE(lathe.interpreter->select(2));
    setReentry(lathe, {});
    InterpreterState state = lathe.interpreter->state();
    state.modal.lastEffectiveRadius = 36.5;
    lathe.interpreter->restoreState(state);
    for (int i = 0; i < 3; ++i)
        ASSERT_EQ(lathe.interpreter->step().status, RunStatus::Running);
    EXPECT_EQ(lathe.interpreter->state().modal.transformation.kind(), 32);
    EXPECT_EQ(lathe.interpreter->state().modal.transformation.effectiveRadius(), 36.5);
}

TEST(RestartAxisFunctions, TakeMachinePositionsRederivesTheProgrammedCoordinates) {
    Station mill(demoCell(), 0);
    mill.add("N1 G54 G0 X10 Y10 Z10\nN2 M30\n", 1);
    ASSERT_TRUE(mill.interpreter->select(1));
    ASSERT_EQ(mill.interpreter->step().status, RunStatus::Running);
    mill.interpreter->takeMachinePositions({-100, -50, -100});
    EXPECT_DOUBLE_EQ(mill.interpreter->programmedPosition(0), 50.0) << "G54 X-150";
    EXPECT_DOUBLE_EQ(mill.interpreter->programmedPosition(1), 30.0) << "G54 Y-80";
    EXPECT_DOUBLE_EQ(mill.interpreter->programmedPosition(2), 20.0) << "G54 Z-120";
}

}  // namespace
