// The restart sequence after the computing process (seed 000, 2.8, 2.9, 6.3,
// 7): interface signals in the order of Fig. 6-8, ADJUST / manual mode /
// REPOS on the process's interpreter, abort consistency, refusals, and every
// numbered block of the built-in demo programs as a target.
#include <gtest/gtest.h>

#include <thread>

#include "RestartStation.h"
#include "cnc_core/restart/RestartRoute.h"
#include "cnc_core/restart/RestartSequence.h"
#include "resources/EmbeddedResources.h"

namespace {

using namespace mtc::core;
using namespace mtc::test;

TEST(RestartSequence, SignalsFollowFigure68) {
    RestartStation mill(0);
    mill.addDemoPrograms();
    mill.control.press(ControlKey::ProgramRestart);
    ASSERT_TRUE(mill.accept(mill.cell.selection(1, 1, 4)));
    EXPECT_EQ(mill.runUntilWaiting(), RestartPhase::TargetReached);
    EXPECT_EQ(mill.signal("CREPOS"), 1) << "the SPS activated multi-block retrace";
    ASSERT_TRUE(mill.control.press(ControlKey::Start));
    EXPECT_EQ(mill.runUntilWaiting(), RestartPhase::ManualMode) << "Q9500 at the end of ADJUST";
    EXPECT_EQ(mill.control.mode(), OperatingMode::Manual);
    EXPECT_FALSE(mill.control.press(ControlKey::Start)) << "Start needs automatic mode";
    ASSERT_TRUE(mill.control.press(ControlKey::Automatic));
    EXPECT_EQ(mill.sequence.phase(), RestartPhase::AutomaticAgain);
    ASSERT_TRUE(mill.control.press(ControlKey::Start));
    EXPECT_EQ(mill.runUntilWaiting(), RestartPhase::Reestablished)
        << diagnosticsText(mill.sequence.diagnostics());
    const std::vector<std::string> expected = {
        "mBPREP=1",    "mBPREP=0",    "P00SBPACT=1", "P00CBPSTR=1", "P00SACTIV=1",
        "P00SBPACT=0", "P00SREPOS=1", "P00CBPSTR=0", "P00CREPOS=1", "P00CADV=1",
        "P00CADV=0",   "P00SAUTO=0",  "P00SMANU=1",  "P00SAUTO=1",  "P00SMANU=0",
        "P00CADV=1",   "P00CADV=0",   "P00SCREST=1", "P00CREPOS=0", "P00SREPOS=0"};
    EXPECT_EQ(mill.log(), expected);
    EXPECT_EQ(mill.signal("SACTIV"), 1) << "the program goes on at the target";
    EXPECT_EQ(mill.control.keyHandler(), nullptr);
    const InterpreterState& live = mill.cell.live.state();
    EXPECT_EQ(live.block, mill.cell.block(1, 4)) << "program pointer on the target block";
    EXPECT_TRUE(live.callStack.empty());
    EXPECT_EQ(live.modal.machine, mill.sequence.reentry().machine) << "REPOS reached it";
    EXPECT_EQ(live.modal.machine[0], -140.0);
    EXPECT_EQ(live.modal.machine[2], -122.0);
}

TEST(RestartSequence, AdjustAndReposMoveFromWhereTheAxesAre) {
    RestartStation mill(0);
    mill.addDemoPrograms();
    mill.cell.live.takeMachinePositions({5, 6, 7});
    ASSERT_EQ(mill.adjustUntilManualMode(), RestartPhase::ManualMode);
    const auto& moves = mill.cell.sps.motions;
    ASSERT_EQ(moves.size(), 1u);
    EXPECT_EQ(moves[0].start[0], 5.0) << "the computing process moved nothing";
    EXPECT_EQ(moves[0].end[2], 90.0);
    EXPECT_TRUE(mill.sequence.jog(1, 40.0)) << "jog Y in manual mode";
    EXPECT_FALSE(mill.sequence.jog(1, 900.0)) << "outside the travel range";
    mill.control.press(ControlKey::Automatic);
    mill.control.press(ControlKey::Start);
    ASSERT_EQ(mill.runUntilWaiting(), RestartPhase::Reestablished);
    ASSERT_EQ(moves.size(), 4u) << "ADJUST, jog, G77 X Y, G77 Z";
    EXPECT_EQ(moves[1].end[1], 40.0);
    EXPECT_EQ(moves[2].start[1], 40.0) << "REPOS starts where the operator jogged to";
    EXPECT_EQ(moves[2].type, MotionType::Linear);
    EXPECT_EQ(moves[2].feed, 2000.0);
    bool speed = false;
    for (const AuxOutput& a : mill.cell.sps.aux)
        speed = speed || (a.type == 'S' && a.value == 2000);
    EXPECT_TRUE(speed) << "G77 S0 outputs the speed of the target";
}

TEST(RestartSequence, AdjustWithoutManualModeFlowsIntoRepos) {
    RestartStation mill(0);
    mill.cell.add("N0000 M30\nN0001 .ADJUST @150=1\nN0002 .REPOS G77 X0 Y0 Z0 RTS\n", 99);
    mill.cell.add(kMain, 1);
    ASSERT_TRUE(mill.accept(mill.cell.selection(1, 1, 4)));
    mill.runUntilWaiting();
    mill.control.press(ControlKey::Start);
    EXPECT_EQ(mill.runUntilWaiting(), RestartPhase::Reestablished);
    EXPECT_EQ(mill.control.mode(), OperatingMode::Automatic);
}

TEST(RestartSequence, AdjustMissingFailsWithEverySignalReset) {
    RestartStation mill(0);
    mill.cell.add(kMain, 1);
    DiagnosticList d;
    ASSERT_TRUE(mill.sequence.accept(mill.cell.selection(1, 1, 4), d));
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d.items()[0].code, "RESTART_ADJUST_MISSING");
    EXPECT_EQ(d.items()[0].severity, Severity::Warning) << "known before the computing process";
    ASSERT_EQ(mill.runUntilWaiting(), RestartPhase::TargetReached);
    EXPECT_FALSE(mill.control.press(ControlKey::Start));
    EXPECT_EQ(mill.sequence.phase(), RestartPhase::Failed);
    EXPECT_EQ(errorCodes(mill.sequence.diagnostics()),
              std::vector<std::string>{"RESTART_ADJUST_MISSING"});
    mill.expectAllRestartSignalsOff();
    EXPECT_FALSE(mill.cell.live.state().reentry.valid) << "the interpreter was reset";
}

TEST(RestartSequence, StopThenControlResetDuringTheComputingProcess) {
    RestartStation mill(0);
    mill.cell.add(kLibrary, 99);
    mill.cell.add(
        "N0001 @5=5\nN0002 .L @1=@1+1\nN0003 @2=@1-500000 BMI .L\nN0004 @3=1\n"
        "N0005 M30\n",
        1);
    const InterpreterState before = mill.cell.live.state();
    ASSERT_TRUE(mill.accept(mill.cell.selection(1, 1, 4)));
    EXPECT_EQ(mill.sequence.advance(1000), RestartPhase::Computing);
    mill.control.press(ControlKey::Stop);
    EXPECT_TRUE(mill.sequence.held());
    EXPECT_EQ(mill.signal("SHOLD"), 1);
    EXPECT_EQ(mill.sequence.advance(1000), RestartPhase::Computing);
    EXPECT_EQ(mill.sequence.computing().progress().blocksInterpreted, 1000u) << "held";
    mill.control.press(ControlKey::ControlReset);
    EXPECT_EQ(mill.sequence.phase(), RestartPhase::Aborted);
    mill.expectAllRestartSignalsOff();
    EXPECT_EQ(mill.cell.live.state().variables.written, before.variables.written)
        << "the process's interpreter never saw the computing process";
    EXPECT_TRUE(mill.accept(mill.cell.selection(1, 1, 4))) << "a new restart can be selected";
}

TEST(RestartSequence, RequestAbortFromAnotherThread) {
    RestartStation mill(0);
    mill.cell.add("N0001 .L @1=@1+1\nN0002 BRA .L\nN0003 @2=1\n", 1);
    DiagnosticList d;
    ASSERT_TRUE(mill.sequence.accept(mill.cell.selection(1, 1, 3), d, ~0ull));
    std::thread stopper([&] {
        while (mill.sequence.computing().blocksSoFar() < 100'000)
            std::this_thread::yield();
        mill.sequence.requestAbort();
    });
    RestartPhase phase = RestartPhase::Computing;
    while (phase == RestartPhase::Computing)
        phase = mill.sequence.advance(~0ull);
    stopper.join();
    EXPECT_EQ(phase, RestartPhase::Aborted);
    mill.expectAllRestartSignalsOff();
}

TEST(RestartSequence, ControlResetInManualModeAfterAdjust) {
    RestartStation mill(0);
    mill.addDemoPrograms();
    ASSERT_EQ(mill.adjustUntilManualMode(), RestartPhase::ManualMode);
    mill.control.press(ControlKey::ControlReset);
    mill.expectAllRestartSignalsOff();
    EXPECT_EQ(mill.signal("SMANU"), 1) << "the mode the SPS selected stays";
    const InterpreterState& live = mill.cell.live.state();
    EXPECT_TRUE(live.callStack.empty()) << "the ADJUST call is gone";
    EXPECT_FALSE(live.reentry.valid);
    EXPECT_EQ(live.modal.machine[2], 90.0) << "the axes stay where ADJUST left them";
    EXPECT_TRUE(mill.control.press(ControlKey::Automatic)) << "keys work normally again";
}

TEST(RestartSequence, ProgrammedStopInAdjustHoldsUntilStart) {
    RestartStation mill(0);
    mill.cell.add("N0000 M30\nN0001 .ADJUST M0\nN0002 .REPOS G77 X0 Y0 Z0 RTS\n", 99);
    mill.cell.add(kMain, 1);
    ASSERT_TRUE(mill.accept(mill.cell.selection(1, 1, 4)));
    mill.runUntilWaiting();
    mill.control.press(ControlKey::Start);
    EXPECT_EQ(mill.runUntilWaiting(), RestartPhase::Adjusting);
    EXPECT_TRUE(mill.sequence.held());
    EXPECT_EQ(mill.signal("SHOLD"), 1);
    mill.control.press(ControlKey::Start);
    EXPECT_EQ(mill.runUntilWaiting(), RestartPhase::Reestablished);
    EXPECT_EQ(mill.signal("SHOLD"), 0);
}

TEST(RestartSequence, TargetInsideASubroutineThatAdjustCallsToo) {
    RestartStation mill(0);
    mill.cell.add(
        "N0000 M30\nN0001 .ADJUST BSR .TAP\nN0002 .REPOS G77 X0 Y0 Z0 RTS\n"
        "N0010 .TAP @11=@11+1\nN0011 @12=1\nN0012 RTS\n",
        99);
    mill.cell.add("N0001 G0 X5 BSR .TAP\nN0002 M30\n", 1);
    RestartSelection s = mill.cell.selection(1, 99, 11);
    s.path = {mill.cell.ref(1, 1)};
    ASSERT_TRUE(mill.accept(s));
    ASSERT_EQ(mill.runUntilWaiting(), RestartPhase::TargetReached);
    mill.control.press(ControlKey::Start);
    EXPECT_EQ(mill.runUntilWaiting(), RestartPhase::Reestablished)
        << diagnosticsText(mill.sequence.diagnostics());
    const InterpreterState& live = mill.cell.live.state();
    EXPECT_EQ(live.variables.values[11], 2) << "ADJUST's own call ran the target block";
    ASSERT_EQ(live.callStack.size(), 1u) << "re-entry with the call chain of the target";
    EXPECT_EQ(live.program->number, 99);
}

TEST(RestartSequence, RefusedWhenNotReady) {
    RestartStation mill(0);
    mill.cell.add(kMain, 1);
    mill.control.press(ControlKey::Manual);
    DiagnosticList d;
    EXPECT_FALSE(mill.sequence.accept(mill.cell.selection(1, 1, 4), d));
    EXPECT_EQ(errorCodes(d), std::vector<std::string>{"RESTART_NOT_READY"});
    mill.control.press(ControlKey::Automatic);
    mill.control.setProgramActive(true);
    EXPECT_FALSE(mill.sequence.accept(mill.cell.selection(1, 1, 4), d));
    mill.control.setProgramActive(false);
    EXPECT_EQ(mill.signal("SBPACT"), 0);
    RestartSelection bad = mill.cell.selection(1, 1, 4);
    bad.runs = 0;
    DiagnosticList e;
    EXPECT_FALSE(mill.sequence.accept(bad, e));
    EXPECT_EQ(errorCodes(e), std::vector<std::string>{"RESTART_RUNS_RANGE"});
    EXPECT_EQ(mill.sequence.phase(), RestartPhase::Idle);
    EXPECT_EQ(mill.signal("SBPACT"), 0) << "nothing switched for a refused selection";
}

TEST(RestartSequence, TargetNotFoundResetsTheSignals) {
    RestartStation mill(0);
    mill.cell.add(kLibrary, 99);
    mill.cell.add("N0001 @1=1\nN0002 M30\nN0003 @2=2\n", 1);
    ASSERT_TRUE(mill.accept(mill.cell.selection(1, 1, 3)));
    EXPECT_EQ(mill.runUntilWaiting(), RestartPhase::Failed);
    EXPECT_EQ(errorCodes(mill.sequence.diagnostics()),
              std::vector<std::string>{"RESTART_TARGET_NOT_FOUND"});
    mill.expectAllRestartSignalsOff();
}

bool hasM30(const Program& program, std::uint32_t block) {
    const Block b = program.blocks[block];
    for (std::uint32_t w = b.firstWord; w < b.firstWord + b.wordCount; ++w)
        if (program.words[w].kind == WordKind::M && program.words[w].number == 30) return true;
    return false;
}

/// The path to block `target` of `main`: empty up to the M30 block, else
/// through the first BSR to the label the target's subroutine starts with.
std::vector<BlockRef> pathTo(const Program& main, std::uint32_t target) {
    std::uint32_t end = 0;
    while (end + 1 < main.blocks.size() && !hasM30(main, end))
        ++end;
    if (target <= end) return {};
    std::uint32_t entry = target;
    while (entry > 0 && main.blocks[entry].label.empty())
        --entry;
    const std::string_view label = main.text(main.blocks[entry].label);
    for (std::uint32_t b = 0; b < end; ++b) {
        const std::optional<Word> jump = jumpWordOf(main, b);
        if (jump && jump->jump == JumpKind::BSR && main.text(jump->text) == label)
            return {{main.number, b}};
    }
    return {};
}

/// Every numbered block of the built-in demo programs as target: the
/// computing process, ADJUST and REPOS of program 99 run without any
/// diagnostic, and REPOS brings the axes back to the re-entry point.
TEST(RestartSequence, EveryBlockOfTheDemoProgramsIsARestartTarget) {
    for (int process : {0, 1}) {
        RestartStation station(process);
        const std::string prefix = "programs/N101" + std::to_string(process);
        station.cell.add(std::string(mtc::resources::find(prefix + "099.DAT")), 99);
        const ProgramPtr main =
            station.cell.add(std::string(mtc::resources::find(prefix + "001.DAT")), 1);
        for (std::uint32_t b = 0; b < main->blocks.size(); ++b) {
            if (main->blocks[b].number < 0 || (main->blocks[b].flags & kBlockProgramEnd)) continue;
            SCOPED_TRACE("process " + std::to_string(process) + " target " + main->blockId(b));
            RestartStation s(process);
            s.cell.store = station.cell.store;
            RestartSelection selection = s.cell.selection(1, 1, main->blocks[b].number);
            selection.path = pathTo(*main, b);
            ASSERT_TRUE(s.accept(selection));
            ASSERT_EQ(s.runUntilWaiting(), RestartPhase::TargetReached);
            s.control.press(ControlKey::Start);
            for (int i = 0; i < 4 && s.sequence.active(); ++i) {
                const RestartPhase p = s.runUntilWaiting();
                if (p == RestartPhase::ManualMode) s.control.press(ControlKey::Automatic);
                if (s.sequence.phase() == RestartPhase::AutomaticAgain)
                    s.control.press(ControlKey::Start);
            }
            ASSERT_EQ(s.sequence.phase(), RestartPhase::Reestablished)
                << diagnosticsText(s.sequence.diagnostics());
            EXPECT_TRUE(s.sequence.diagnostics().empty())
                << diagnosticsText(s.sequence.diagnostics());
            const ReentryPoint& r = s.sequence.reentry();
            const InterpreterState& live = s.cell.live.state();
            for (int a = 0; a < s.cell.live.axes().count(); ++a) {
                const AxisModel& axis = s.cell.live.axes().axis(a);
                if (axis.name.toString() == "Y" && process == 1) continue;  // never moved
                if (axis.spindle && r.rotaryAxisMode[static_cast<size_t>(axis.spindleIndex)] == 0)
                    continue;  // a spindle in spindle mode has no position to regain
                EXPECT_NEAR(live.modal.machine[static_cast<size_t>(a)],
                            r.machine[static_cast<size_t>(a)], 1e-9)
                    << axis.displayName();
            }
        }
    }
}

}  // namespace
