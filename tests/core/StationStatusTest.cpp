// What the base screen shows of a station (core::describeStation), read
// while the station runs in simulated time: actual positions in workpiece
// and machine coordinates, the running block and its neighbours, the call
// level (program 99), spindles, tool edge, G functions and program status.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "InterpTestSupport.h"
#include "cnc_core/cell/Cell.h"
#include "cnc_core/cell/StationStatus.h"

namespace mtc::test {
namespace {

using core::ControlKey;
using core::ProgramState;

struct StatusFixture {
    StatusFixture() : cell(demoCell()) {}
    core::Station& select(int number, const std::string& source, int slot = 0) {
        core::ProgramPtr program = cell.addProgram(slot, number, "status.nc", source);
        EXPECT_FALSE(program->diagnostics.hasErrors()) << diagnosticsText(program->diagnostics);
        core::Station& station = cell.station(slot);
        EXPECT_TRUE(station.selectProgram(number));
        return station;
    }
    core::Cell cell;
};

const core::BlockLineStatus* currentBlock(const core::StationStatus& status) {
    for (const auto& block : status.blocks)
        if (block.current) return &block;
    return nullptr;
}

// 10 mm at F600 = 1 s per move; G54 of the mill is X-150 Y-80 Z-120.
const char* kOffsetMoves =
    "N0001 G54 G90 G0 X10 Y5 S1200 M3\n"
    "N0002 G1 X20 F600\n"
    "N0003 X30\n"
    "N0004 X40\n"
    "N0005 M30\n";

TEST(StationStatus, ActualPositionsInWorkpieceAndMachineCoordinates) {
    StatusFixture f;
    core::Station& mill = f.select(1, kOffsetMoves);
    EXPECT_EQ(core::describeStation(mill).state, ProgramState::Ready);
    ASSERT_TRUE(mill.press(ControlKey::Start));
    // The rapid move of N0001, then half of N0002.
    for (int tick = 0; tick < 10'000 && mill.control().currentBlock() != "N0002"; ++tick)
        mill.advance(0.01);
    mill.advance(0.5);
    const core::StationStatus status = core::describeStation(mill);
    EXPECT_EQ(status.state, ProgramState::Running);
    ASSERT_EQ(status.axes.size(), 3u) << "X, Y, Z; the spindle S1 is not a position";
    EXPECT_EQ(status.axes[0].name, "X");
    EXPECT_DOUBLE_EQ(status.axes[0].machine, mill.machine().position(0));
    EXPECT_DOUBLE_EQ(status.axes[0].work, status.axes[0].machine + 150.0);
    EXPECT_DOUBLE_EQ(status.axes[1].work, 5.0);
    EXPECT_DOUBLE_EQ(status.axes[1].machine, -75.0);
    EXPECT_EQ(status.zeroOffset, 54);
    ASSERT_EQ(status.zeroOffsetValues.size(), 3u);
    EXPECT_DOUBLE_EQ(status.zeroOffsetValues[0], -150.0);
    EXPECT_DOUBLE_EQ(status.zeroOffsetValues[2], -120.0);
    EXPECT_DOUBLE_EQ(status.programmedFeed, 600.0);
    EXPECT_FALSE(status.feedPerRevolution);
    EXPECT_DOUBLE_EQ(status.actualFeed, 600.0);
    EXPECT_DOUBLE_EQ(status.feedOverride, 100.0);
    ASSERT_EQ(status.spindles.size(), 1u);
    EXPECT_EQ(status.spindles[0].turn, core::SpindleTurn::Clockwise);
    EXPECT_DOUBLE_EQ(status.spindles[0].programmed, 1200.0);
    EXPECT_DOUBLE_EQ(status.spindles[0].actual, 1200.0);

    // The running block with its neighbours, the current one marked.
    const core::BlockLineStatus* current = currentBlock(status);
    ASSERT_NE(current, nullptr);
    EXPECT_EQ(current->id, "N0002");
    EXPECT_EQ(current->text, "N0002 G1 X20 F600");
    ASSERT_EQ(status.blocks.size(), 4u) << "two before (only one exists), two after";
    EXPECT_EQ(status.blocks.front().id, "N0001");
    EXPECT_EQ(status.blocks.back().id, "N0004");
    EXPECT_EQ(status.program, 1);
    EXPECT_EQ(status.callLevel, 0);
    EXPECT_FALSE(status.inLibrary);

    mill.advance(1.0);  // in N0003: the display follows the machine
    const core::StationStatus later = core::describeStation(mill);
    EXPECT_EQ(currentBlock(later)->id, "N0003");
    EXPECT_GT(later.axes[0].work, status.axes[0].work);
}

/// After the rapid move to the start, `ticks` calls of advance(`tick`):
/// the state shown for the block the axes work on, and the work X.
struct LoopView {
    std::string executingBlock, currentBlock;
    double shownX = 0.0, workX = 0.0;
};

LoopView runLoop(const std::string& source, int ticks, double tick) {
    StatusFixture f;
    core::Station& mill = f.select(1, source);
    EXPECT_TRUE(mill.press(ControlKey::Start));
    for (int i = 0; i < 100'000 && mill.control().currentBlock() != "N0003"; ++i)
        mill.advance(0.01);  // the rapid move to the start
    for (int i = 0; i < ticks; ++i)
        mill.advance(tick);
    LoopView view;
    view.currentBlock = mill.control().currentBlock();
    view.workX = mill.machine().position(0) + 150.0;  // G54: X-150
    if (const core::QueuedBlockState* executing = mill.executingBlockState()) {
        view.executingBlock = executing->source->blockId(executing->index);
        view.shownX = executing->modal.work[0];
    }
    return view;
}

// A loop queues the same lines once per pass. What is shown is the state of
// the pass the axes are in, not of an earlier pass still in the records:
// with the panel's ticks, and in one long advance() (the CLI's), also when
// the loop moves on one line only (the line alone cannot tell the passes
// apart; the machine's queue items do).
TEST(StationStatus, TheStateShownIsThatOfThePassOfALoopTheAxesAreIn) {
    // Every pass moves X (and Y) one millimetre further, 0.1 s each at F600.
    const std::string twoLines =
        "N0001 G54 G90 G0 X0 Y0 @1=0\nN0002 .PASS @1=@1+1\nN0003 G1 X@1 F600\n"
        "N0004 Y@1\nN0005 BRA .PASS\n";
    const std::string oneLine =
        "N0001 G54 G90 G0 X0 Y0 @1=0\nN0002 .PASS @1=@1+1\nN0003 G1 X@1 F600\n"
        "N0004 BRA .PASS\n";
    for (const std::string& source : {twoLines, oneLine}) {
        for (const auto& [ticks, tick] : {std::pair{1, 3.05}, std::pair{153, 0.02}}) {
            const LoopView view = runLoop(source, ticks, tick);
            SCOPED_TRACE((source == oneLine ? "one line, " : "two lines, ") +
                         std::to_string(ticks) + " ticks");
            ASSERT_GT(view.workX, 10.0);
            EXPECT_EQ(view.executingBlock, view.currentBlock);
            // The running pass's @1 is where X is going or stands.
            EXPECT_GE(view.shownX, view.workX - 1e-9);
            EXPECT_LT(view.shownX, view.workX + 1.0);
        }
    }
}

// MOT-020: a station that keeps no block states (the CLI's) has none to
// show, and runs exactly as one that keeps them: same time, positions and
// blocks; with them the state shown is that of the block the axes are in.
TEST(StationStatus, AStationWithoutBlockStatesRunsTheSame) {
    struct Seen {
        double seconds = 0.0, x = 0.0;
        std::string block;
        bool shown = false;
    };
    const auto run = [](bool keep) {
        StatusFixture f;
        core::Station& mill = f.select(1, kOffsetMoves);
        mill.keepBlockStates(keep);
        EXPECT_TRUE(mill.press(ControlKey::Start));
        std::vector<Seen> seen;
        for (int i = 0; i < 10'000 && mill.busy(); ++i) {
            mill.advance(0.25);
            const core::QueuedBlockState* executing = mill.executingBlockState();
            seen.push_back({mill.machine().seconds(), mill.machine().position(0),
                            mill.control().currentBlock(), executing != nullptr});
            if (executing) {
                EXPECT_EQ(executing->source->blockId(executing->index),
                          mill.control().currentBlock());
            }
        }
        EXPECT_FALSE(mill.busy());
        return seen;
    };
    const std::vector<Seen> kept = run(true), without = run(false);
    ASSERT_EQ(kept.size(), without.size());
    bool anyShown = false;
    for (std::size_t i = 0; i < kept.size(); ++i) {
        EXPECT_EQ(kept[i].seconds, without[i].seconds) << i;
        EXPECT_EQ(kept[i].x, without[i].x) << i;
        EXPECT_EQ(kept[i].block, without[i].block) << i;
        EXPECT_FALSE(without[i].shown) << i;
        anyShown = anyShown || kept[i].shown;
    }
    EXPECT_TRUE(anyShown);
}

TEST(StationStatus, ASubroutineOfProgram99IsShownAsSuch) {
    StatusFixture f;
    f.cell.addProgram(0, 99, "library.nc",
                      "N0001 BST\n.SIDE\nN0010 G1 G91 Y10 F600\nN0011 Y10\nN0012 RTS\n");
    core::Station& mill = f.select(2, "N0001 G90 G1 X0 Y0 F600\nN0002 BSR .SIDE\nN0003 M30\n");
    ASSERT_TRUE(mill.press(ControlKey::Start));
    mill.advance(0.5);  // N0010 of program 99
    const core::StationStatus status = core::describeStation(mill);
    ASSERT_NE(currentBlock(status), nullptr);
    EXPECT_EQ(currentBlock(status)->id, "N0010");
    EXPECT_EQ(status.program, 99);
    EXPECT_TRUE(status.inLibrary);
    EXPECT_EQ(status.callLevel, 1);
    mill.advance(10.0);
    EXPECT_FALSE(mill.control().programActive());
}

TEST(StationStatus, ProgramStateFollowsHoldsStopsAndErrors) {
    StatusFixture f;
    core::Station& mill =
        f.select(3, "N0001 G90 G1 X10 F600\nN0002 M00\nN0003 X20\nN0004 X30\nN0005 T999\n");
    ASSERT_TRUE(mill.press(ControlKey::Start));
    mill.advance(0.5);
    ASSERT_TRUE(mill.press(ControlKey::Stop));
    EXPECT_EQ(core::describeStation(mill).state, ProgramState::FeedHold);
    ASSERT_TRUE(mill.press(ControlKey::Start));
    mill.advance(1.0);
    EXPECT_EQ(core::describeStation(mill).state, ProgramState::ProgrammedStop);
    ASSERT_TRUE(mill.press(ControlKey::SingleBlock));
    ASSERT_TRUE(mill.press(ControlKey::Start));
    mill.advance(2.0);
    EXPECT_EQ(core::describeStation(mill).state, ProgramState::SingleBlock);
    ASSERT_TRUE(mill.press(ControlKey::SingleBlock));
    ASSERT_TRUE(mill.press(ControlKey::Start));
    mill.advance(5.0);
    EXPECT_FALSE(mill.control().programActive());
    EXPECT_EQ(core::describeStation(mill).state, ProgramState::Error);
    ASSERT_TRUE(mill.press(ControlKey::ControlReset));
    EXPECT_EQ(core::describeStation(mill).state, ProgramState::Ready);
}

TEST(StationStatus, ToolEdgeAndGFunctionsOfTheLathe) {
    StatusFixture f;
    core::Station& lathe =
        f.select(4, "N0001 G95 T2 E1 F0.2 S2 800 M203\nN0002 G1 X40 Z10\nN0003 M30\n", 1);
    ASSERT_TRUE(lathe.press(ControlKey::Start));
    lathe.advance(0.01);
    const core::StationStatus status = core::describeStation(lathe);
    EXPECT_TRUE(status.feedPerRevolution);
    EXPECT_DOUBLE_EQ(status.programmedFeed, 0.2);
    EXPECT_EQ(status.tool, 2);
    EXPECT_EQ(status.edge, 1);
    EXPECT_TRUE(status.edgeKnown);
    const core::ToolEdge* edge = lathe.interpreter().tools().edge(2, 1);
    ASSERT_NE(edge, nullptr);
    EXPECT_DOUBLE_EQ(status.edgeRadius, edge->totalRadius());
    bool feedType = false;
    for (const auto& g : status.gFunctions)
        if (g.group == core::kGroupFeedType) feedType = g.code == 95;
    EXPECT_TRUE(feedType);
    const core::SpindleStatus* s2 = nullptr;
    for (const auto& s : status.spindles)
        if (s.index == 2) s2 = &s;
    ASSERT_NE(s2, nullptr);
    EXPECT_EQ(s2->turn, core::SpindleTurn::Clockwise);
    EXPECT_DOUBLE_EQ(s2->programmed, 800.0);
}

TEST(StationStatus, KeyLampsFollowModeSingleBlockHoldAndRun) {
    StatusFixture f;
    core::Station& mill = f.select(6, "N0001 G90 G1 X10 F600\nN0002 X20\nN0003 M30\n");
    EXPECT_TRUE(core::keyLamp(mill, ControlKey::Automatic));
    EXPECT_FALSE(core::keyLamp(mill, ControlKey::Manual));
    EXPECT_FALSE(core::keyLamp(mill, ControlKey::Start));
    ASSERT_TRUE(mill.press(ControlKey::SingleBlock));
    EXPECT_TRUE(core::keyLamp(mill, ControlKey::SingleBlock));
    ASSERT_TRUE(mill.press(ControlKey::Start));
    EXPECT_TRUE(core::keyLamp(mill, ControlKey::Start));
    EXPECT_FALSE(core::keyLamp(mill, ControlKey::Stop));
    mill.advance(2.0);  // held after N0001: a prompt, not an alarm
    EXPECT_EQ(core::programStateOf(mill), ProgramState::SingleBlock);
    EXPECT_TRUE(core::keyLamp(mill, ControlKey::Stop));
    EXPECT_FALSE(core::keyLamp(mill, ControlKey::Start));
    EXPECT_TRUE(mill.control().alarm().empty()) << mill.control().alarm();
    EXPECT_NE(mill.control().prompt().find("Start"), std::string::npos);
    ASSERT_TRUE(mill.press(ControlKey::SingleBlock));
    ASSERT_TRUE(mill.press(ControlKey::Start));
    EXPECT_TRUE(mill.control().prompt().empty()) << "Start clears the prompt";
    EXPECT_FALSE(core::keyLamp(mill, ControlKey::SingleBlock));
    ASSERT_TRUE(mill.press(ControlKey::Stop));
    EXPECT_TRUE(core::keyLamp(mill, ControlKey::Stop));
    EXPECT_STREQ(core::programStateWord(core::programStateOf(mill)), "feed hold");
    ASSERT_TRUE(mill.press(ControlKey::ControlReset));
    EXPECT_FALSE(core::keyLamp(mill, ControlKey::Stop));
    EXPECT_FALSE(core::keyLamp(mill, ControlKey::ControlReset));
    ASSERT_TRUE(mill.press(ControlKey::Manual));
    EXPECT_TRUE(core::keyLamp(mill, ControlKey::Manual));
    EXPECT_FALSE(core::keyLamp(mill, ControlKey::Automatic));
    ASSERT_TRUE(mill.press(ControlKey::ProgramRestart));
    EXPECT_TRUE(core::keyLamp(mill, ControlKey::ProgramRestart));
}

TEST(StationStatus, BlockIndexAtLineFindsTheBlockOfAContinuationLine) {
    core::ProgramPtr program = parse("N0001 G1 X1\n\nN0002 X2\nN0003 X3\n", 5);
    EXPECT_EQ(core::blockIndexAtLine(*program, 1), 0u);
    EXPECT_EQ(core::blockIndexAtLine(*program, 2), 0u);
    EXPECT_EQ(core::blockIndexAtLine(*program, 3), 1u);
    EXPECT_EQ(core::blockIndexAtLine(*program, 4), 2u);
    EXPECT_EQ(core::blockIndexAtLine(*program, 99), 2u);
}

}  // namespace
}  // namespace mtc::test
