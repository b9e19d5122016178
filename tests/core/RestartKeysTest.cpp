// Machine control keys during an NC program restart that RestartSequenceTest
// does not cover: the REPOS M key (seed 000, 6.3 step 5 and the REPOS ladder
// of Fig. 7-14) and single-block mode during the computing process (seed
// 000, 2.7). docs/decisions/restart.md.
#include <gtest/gtest.h>

#include "RestartStation.h"

namespace {

using namespace mtc::test;

/// The mill with the library's ADJUST/REPOS and kMain, restart to N0004.
struct ReposStation : RestartStation {
    ReposStation() : RestartStation(0) {
        cell.add(kLibrary, 99);
        cell.add(kMain, 1);
    }
};

TEST(RestartKeys, ReposIsRefusedWithoutARestart) {
    ReposStation mill;
    EXPECT_FALSE(mill.control.press(ControlKey::Repos));
    EXPECT_NE(mill.control.alarm().find("REPOS refused"), std::string::npos);
    EXPECT_EQ(mill.signal("CREPOS"), 0);
    EXPECT_EQ(mill.control.signalTable().get("mREPOS"), 0);
}

TEST(RestartKeys, ReposIsRefusedDuringTheComputingProcess) {
    ReposStation mill;
    mill.cell.add("N0001 .L @1=@1+1\nN0002 @2=@1-10000 BMI .L\nN0003 @3=1\nN0004 M30\n", 2);
    ASSERT_TRUE(mill.accept(mill.cell.selection(2, 2, 3)));
    ASSERT_EQ(mill.sequence.advance(100), RestartPhase::Computing);
    EXPECT_FALSE(mill.sequence.reposPhase());
    EXPECT_FALSE(mill.control.press(ControlKey::Repos));
    EXPECT_NE(mill.control.alarm().find("not possible yet"), std::string::npos);
    EXPECT_EQ(mill.signal("CREPOS"), 0);
    EXPECT_EQ(mill.sequence.phase(), RestartPhase::Computing) << "nothing else changed";
    EXPECT_EQ(mill.runUntilWaiting(), RestartPhase::TargetReached);
}

TEST(RestartKeys, ReposIsAcceptedFromTheTargetToTheReentry) {
    ReposStation mill;
    ASSERT_TRUE(mill.accept(mill.cell.selection(1, 1, 4)));
    ASSERT_EQ(mill.runUntilWaiting(), RestartPhase::TargetReached);
    EXPECT_TRUE(mill.sequence.reposPhase());
    EXPECT_TRUE(mill.control.press(ControlKey::Repos));
    EXPECT_EQ(mill.signal("CREPOS"), 1);
    EXPECT_EQ(mill.control.signalTable().get("mREPOS"), 0) << "the GUI flag is reset after a scan";
    ASSERT_TRUE(mill.control.press(ControlKey::Start));
    ASSERT_EQ(mill.runUntilWaiting(), RestartPhase::ManualMode);
    EXPECT_TRUE(mill.control.press(ControlKey::Repos)) << "manual mode between the subroutines";
    mill.control.press(ControlKey::Automatic);
    mill.control.press(ControlKey::Start);
    ASSERT_EQ(mill.runUntilWaiting(), RestartPhase::Reestablished);
    EXPECT_FALSE(mill.control.press(ControlKey::Repos)) << "state re-established: nothing to do";
    EXPECT_EQ(mill.signal("CREPOS"), 0);
}

TEST(RestartKeys, ReposKeySetsTheRetraceRequestTheSpsDropped) {
    ReposStation mill;
    ASSERT_TRUE(mill.accept(mill.cell.selection(1, 1, 4)));
    ASSERT_EQ(mill.runUntilWaiting(), RestartPhase::TargetReached);
    // The operator's SPS program dropped the automatic request (e.g. a
    // retrace-off switch that is on again now): the M key requests it again.
    mill.control.signalTable().set("P00CREPOS", 0);
    EXPECT_FALSE(mill.control.press(ControlKey::Start)) << "Start needs PxxCREPOS";
    EXPECT_TRUE(mill.control.press(ControlKey::Repos));
    EXPECT_EQ(mill.signal("CREPOS"), 1);
    EXPECT_TRUE(mill.control.press(ControlKey::Start));
    EXPECT_EQ(mill.sequence.phase(), RestartPhase::Adjusting);
}

const char* kCounting =
    "N0001 @1=1\nN0002 @1=@1+1\nN0003 M108 @1=@1+1\nN0004 @1=@1+1\nN0005 @2=1 ;target\n"
    "N0006 M30\n";

TEST(RestartKeys, SingleBlockHoldsTheComputingProcessAfterEveryBlock) {
    ReposStation mill;
    mill.cell.add(kCounting, 2);
    ASSERT_TRUE(mill.control.press(ControlKey::SingleBlock));
    EXPECT_TRUE(mill.control.singleBlock());
    EXPECT_EQ(mill.signal("CSBLK"), 1);
    ASSERT_TRUE(mill.accept(mill.cell.selection(2, 2, 5)));
    const auto& computing = mill.sequence.computing();
    for (std::uint64_t block = 1; block <= 4; ++block) {
        EXPECT_EQ(mill.sequence.advance(100'000), RestartPhase::Computing);
        EXPECT_TRUE(mill.sequence.held()) << "after block " << block;
        EXPECT_EQ(mill.signal("SHOLD"), 1);
        EXPECT_TRUE(computing.progress().singleBlockStop);
        EXPECT_EQ(computing.progress().blocksInterpreted, block);
        EXPECT_EQ(computing.state().variables.values[1], static_cast<double>(block));
        EXPECT_EQ(mill.sequence.advance(100'000), RestartPhase::Computing) << "held until Start";
        EXPECT_EQ(computing.progress().blocksInterpreted, block);
        ASSERT_TRUE(mill.control.press(ControlKey::Start));
        EXPECT_EQ(mill.signal("SHOLD"), 0);
    }
    EXPECT_EQ(mill.sequence.advance(100'000), RestartPhase::TargetReached)
        << "the target block itself is not interpreted";
    EXPECT_EQ(computing.progress().blocksInterpreted, 4u);
    EXPECT_TRUE(mill.cell.sps.motions.empty()) << "single block moves nothing either";
}

TEST(RestartKeys, SingleBlockCanBeSwitchedAtAnyTime) {
    ReposStation mill;
    mill.cell.add(kCounting, 2);
    ASSERT_TRUE(mill.accept(mill.cell.selection(2, 2, 5)));
    ASSERT_EQ(mill.sequence.advance(2), RestartPhase::Computing);
    EXPECT_FALSE(mill.sequence.held());
    ASSERT_TRUE(mill.control.press(ControlKey::SingleBlock)) << "while it runs";
    EXPECT_EQ(mill.sequence.advance(100'000), RestartPhase::Computing);
    EXPECT_TRUE(mill.sequence.held());
    EXPECT_EQ(mill.sequence.computing().progress().blocksInterpreted, 3u);
    ASSERT_TRUE(mill.control.press(ControlKey::SingleBlock)) << "off while held";
    EXPECT_EQ(mill.sequence.advance(100'000), RestartPhase::Computing) << "still held";
    ASSERT_TRUE(mill.control.press(ControlKey::Start));
    EXPECT_EQ(mill.sequence.advance(100'000), RestartPhase::TargetReached) << "runs on";
    EXPECT_EQ(mill.sequence.computing().state().variables.values[1], 4.0);
}

TEST(RestartKeys, SingleBlockStopIsNotAProgrammedStop) {
    ReposStation mill;
    mill.cell.add("N0001 @1=1\nN0002 M0\nN0003 @1=2\nN0004 @2=1\nN0005 M30\n", 2);
    ASSERT_TRUE(mill.accept(mill.cell.selection(2, 2, 4)));
    EXPECT_EQ(mill.runUntilWaiting(), RestartPhase::Computing);
    EXPECT_TRUE(mill.sequence.held()) << "M0";
    EXPECT_FALSE(mill.sequence.computing().progress().singleBlockStop);
    mill.control.press(ControlKey::SingleBlock);
    mill.control.press(ControlKey::Start);
    EXPECT_EQ(mill.sequence.advance(100'000), RestartPhase::Computing);
    EXPECT_TRUE(mill.sequence.computing().progress().singleBlockStop);
    mill.control.press(ControlKey::ControlReset);
    mill.expectAllRestartSignalsOff();
    EXPECT_TRUE(mill.control.singleBlock()) << "the switch itself stays as the operator set it";
}

TEST(RestartKeys, SingleBlockAlsoHoldsAdjustAndRepos) {
    ReposStation mill;
    mill.cell.add("N0000 M30\nN0001 .ADJUST @150=1\nN0002 .REPOS G77 X0 Y0 Z0 RTS\n", 99);
    ASSERT_TRUE(mill.accept(mill.cell.selection(1, 1, 4)));
    ASSERT_EQ(mill.runUntilWaiting(), RestartPhase::TargetReached);
    mill.control.press(ControlKey::SingleBlock);
    ASSERT_TRUE(mill.control.press(ControlKey::Start));
    EXPECT_EQ(mill.runUntilWaiting(), RestartPhase::Adjusting);
    EXPECT_TRUE(mill.sequence.held());
    EXPECT_EQ(mill.sequence.sequenceBlocks(), 1u);
    int starts = 1;
    while (mill.sequence.phase() != RestartPhase::Reestablished && starts < 10) {
        ASSERT_TRUE(mill.control.press(ControlKey::Start));
        ++starts;
        mill.runUntilWaiting();
    }
    EXPECT_EQ(mill.sequence.phase(), RestartPhase::Reestablished);
    EXPECT_EQ(starts, 3) << "held after ADJUST's block and after REPOS's block (with its RTS); "
                            "the third Start re-enters at the target block";
}

}  // namespace
