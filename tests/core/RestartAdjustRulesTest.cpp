// Rules of the restart between the target and the re-entry (issue 15, seed
// 000 2.1, 4.1, 5.3, 5.4): an RTS in ADJUST before .REPOS stops the restart,
// Bxx.033 / Bxx.036 = Yes refuse it, the machine keeps its spindle modes and
// tools until ADJUST / REPOS establish them, G26 of the target comes back.
#include <gtest/gtest.h>

#include "RestartStation.h"
#include "cnc_core/afc/AdaptiveFeedControl.h"

namespace {

using namespace mtc::core;
using namespace mtc::test;

TEST(RestartAdjustRules, RtsBeforeReposStopsTheRestartAndNothingMoves) {
    RestartStation mill(0);
    mill.cell.add(
        "N0000 M30\n"
        "N0001 .ADJUST @150=1\n"
        "N0002 G77 X0 Y0 Z0 RTS ;forbidden: ADJUST returns before .REPOS\n"
        "N0003 .REPOS G77 X0 Y0 Z0 RTS\n",
        99);
    mill.cell.add(kMain, 1);
    ASSERT_EQ(mill.restartAtDemoTarget(), RestartPhase::TargetReached);
    const std::size_t moves = mill.cell.sps.motions.size();
    ASSERT_TRUE(mill.control.press(ControlKey::Start));
    EXPECT_EQ(mill.runUntilWaiting(), RestartPhase::Failed);
    EXPECT_EQ(errorCodes(mill.sequence.diagnostics()),
              std::vector<std::string>{"RESTART_ADJUST_RTS"});
    EXPECT_EQ(mill.sequence.diagnostics().items().back().where.block, "N0002");
    EXPECT_EQ(mill.cell.sps.motions.size(), moves) << "the RTS block did not run";
    EXPECT_EQ(mill.cell.live.state().variables.values[150], 1) << "ADJUST ran up to it";
    mill.expectAllRestartSignalsOff();
}

TEST(RestartAdjustRules, RtsInsideASubroutineOfAdjustIsFine) {
    RestartStation mill(0);
    mill.cell.add(
        "N0000 M30\n"
        "N0001 .ADJUST BSR .HELP\n"
        "N0002 .REPOS G77 X0 Y0 Z0 RTS\n"
        "N0003 .HELP @151=1 RTS\n",
        99);
    mill.cell.add(kMain, 1);
    ASSERT_EQ(mill.restartAtDemoTarget(), RestartPhase::TargetReached);
    ASSERT_TRUE(mill.control.press(ControlKey::Start));
    EXPECT_EQ(mill.runUntilWaiting(), RestartPhase::Reestablished)
        << diagnosticsText(mill.sequence.diagnostics());
}

TEST(RestartAdjustRules, ReverseAndJogResetParametersRefuseTheRestart) {
    for (const char* parameter : {"B033", "B036"}) {
        MachineConfig cell = demoCell();
        cell.processes[0].parameters[parameter] = "yes";
        ProgramStore store;
        store.put(0, 1, parse(kMain, 1));
        RecordingSink sps;
        ComputingProcess c(cell.processes[0], store, sps, {});
        RestartSelection s;
        s.mainProgram = 1;
        s.target = {1, 3};
        DiagnosticList d;
        EXPECT_FALSE(c.begin(s, {}, {}, 1000, d)) << parameter;
        ASSERT_EQ(errorCodes(d), std::vector<std::string>{"RESTART_PARAMETER"}) << parameter;
        EXPECT_NE(d.items()[0].message.find(parameter), std::string::npos);
    }
}

TEST(RestartAdjustRules, JoggingResetsOnlyWithB036) {
    MachineConfig cell = demoCell();
    ProgramStore store;
    store.put(1, 1, parse("N0001 G0 G19 G54 G91 X1 M8\nN0002 M30\n", 1));
    for (const char* value : {"no", "yes"}) {
        cell.processes[1].parameters["B036"] = value;
        NullSink sink;
        Interpreter lathe(cell.processes[1], store, sink);
        ASSERT_TRUE(lathe.select(1));
        ASSERT_EQ(lathe.step().status, RunStatus::Running);
        const bool reset = lathe.manualJogPerformed();
        EXPECT_EQ(reset, std::string(value) == "yes");
        const InterpreterState& s = lathe.state();
        EXPECT_EQ(s.modal.g[kGroupPlane], reset ? 18 : 19) << "seed 003: the base plane again";
        EXPECT_EQ(s.modal.g[kGroupDimension], reset ? 90 : 91);
        EXPECT_EQ(s.mGroups[5], reset ? -1 : 8);
    }
}

TEST(RestartAdjustRules, SpindleModesAndToolsStayAsTheMachineHadThemUntilAdjust) {
    RestartStation lathe(1);
    lathe.cell.add("N0000 M30\nN0001 .ADJUST @150=1\nN0002 .REPOS RTS\n", 99);
    lathe.cell.add("N0001 T5 MTP\nN0002 G0 C45\nN0003 G0 X20\nN0004 M30\n", 1);
    ASSERT_TRUE(lathe.accept(lathe.cell.selection(1, 1, 3)));
    ASSERT_EQ(lathe.runUntilWaiting(), RestartPhase::TargetReached);
    const InterpreterState& computed = lathe.sequence.computing().state();
    EXPECT_EQ(computed.modal.toolSpindle[0], 5);
    EXPECT_EQ(computed.modal.rotaryAxisMode[1], 1);
    EXPECT_EQ(lathe.cell.page(60, 0, 5), 5) << "what ADJUST must establish";
    EXPECT_EQ(lathe.cell.page(60, 0, 1), 1);
    const InterpreterState& live = lathe.cell.live.state();
    EXPECT_EQ(live.modal.toolSpindle[0], 0) << "no tool was changed in the machine";
    EXPECT_EQ(live.modal.rotaryAxisMode[1], 0) << "S1 is still in spindle mode";
    EXPECT_EQ(live.modal.tool, 5) << "the T word is the NC's memory (seed 000, 5.4)";
}

TEST(RestartAdjustRules, AdaptiveFeedOfTheTargetComesBackAtTheReentry) {
    RestartStation mill(0);
    auto afc = std::make_shared<AdaptiveFeedControl>(mill.cell.config, *mill.cell.machineData);
    mill.cell.live.setAdaptiveFeed(afc);
    mill.cell.add(kLibrary, 99);
    mill.cell.add(
        "N0001 G0 X10 Y10 Z5 S3000 M3 M108\nN0002 G1 Z-2 F300\nN0003 G26 X50 F900\n"
        "N0004 X80 ;target\nN0005 G25\nN0006 M30\n",
        1);
    ASSERT_TRUE(mill.accept(mill.cell.selection(1, 1, 4)));
    ASSERT_EQ(mill.runUntilWaiting(), RestartPhase::TargetReached)
        << diagnosticsText(mill.sequence.diagnostics());
    EXPECT_TRUE(mill.sequence.computing().state().modal.adaptiveFeed) << "G26 remembered";
    EXPECT_FALSE(afc->active()) << "ADJUST and REPOS run without it";
    ASSERT_TRUE(mill.control.press(ControlKey::Start));
    ASSERT_EQ(mill.runUntilWaiting(), RestartPhase::ManualMode);
    EXPECT_FALSE(afc->active());
    ASSERT_TRUE(mill.control.press(ControlKey::Automatic));
    ASSERT_TRUE(mill.control.press(ControlKey::Start));
    ASSERT_EQ(mill.runUntilWaiting(), RestartPhase::Reestablished)
        << diagnosticsText(mill.sequence.diagnostics());
    EXPECT_TRUE(afc->active()) << "the target block runs under G26 again";
}

TEST(RestartAdjustRules, AdaptiveFeedWithoutItsParameterIsStillRefused) {
    RestartCell lathe(1);  // Bxx.062 = no
    lathe.add("N0001 G26\nN0002 @1=1\nN0003 M30\n", 1);
    ComputingProcess c(lathe.config, lathe.store, lathe.sps, lathe.services());
    DiagnosticList d;
    ASSERT_TRUE(c.begin(lathe.selection(1, 1, 2), lathe.live.state(), {}, 1000, d));
    EXPECT_EQ(c.runToEnd().status, ComputingStatus::Failed);
    EXPECT_EQ(errorCodes(c.diagnostics()), std::vector<std::string>{"AFC_NOT_AVAILABLE"});
}

}  // namespace

namespace {

using namespace mtc::core;
using namespace mtc::test;

TEST(RestartSignals, MotionAnnouncementIsResetWhenTheComputingProcessStarts) {
    RestartStation lathe(1);
    lathe.cell.add("N0000 M30\nN0001 .ADJUST @1=1\nN0002 .REPOS RTS\n", 99);
    lathe.cell.add("N0001 G0 X20 Z5\nN0002 G1 Z-10 F100\nN0003 M30\n", 1);
    SignalTable& signals = lathe.control.signalTable();
    signals.set("A01XSMCPOS", 1);  // as a moving axis would have them
    signals.set("A01Z2SMCNEG", 1);
    ASSERT_TRUE(lathe.accept(lathe.cell.selection(1, 1, 2)));
    EXPECT_EQ(signals.get("A01XSMCPOS"), 0) << "seed 000, 6.4";
    EXPECT_EQ(signals.get("A01Z2SMCNEG"), 0);
    const auto& values = signals.values();
    for (const char* axis : {"X", "Z", "C", "Y", "Z2"})
        EXPECT_TRUE(values.count(std::string("A01") + axis + "SMCPOS")) << axis;
    EXPECT_FALSE(values.count("A01S2SMCPOS")) << "a plain spindle has no motion announcement";
}

}  // namespace
