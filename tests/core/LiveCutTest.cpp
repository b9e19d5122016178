// The part cut while the program runs (issue 19 §3, TP-027): the station
// cuts its run's blank only as far as the axes have travelled, holds with
// the feed, stops at Control reset, starts a new blank at the next Start,
// and a run to its end leaves the part mtc200-cli simulate makes.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "InterpTestSupport.h"
#include "RestartStation.h"
#include "cnc_core/cell/Cell.h"
#include "cnc_core/removal/RemovalRun.h"
#include "tests/support/SlotRestartProgram.h"

namespace mtc::test {
namespace {

using core::ControlKey;
using core::removal::HeightField;

constexpr double kPi = 3.14159265358979323846;
// The demo mill: G54 puts the program's zero at machine X-150 Y-80 Z-120,
// the top of the configuration's block.
constexpr double kZeroX = -150.0, kZeroY = -80.0, kTop = -120.0;

// A slot 2 deep along Y30 from X10 to X90 with T1 (radius 3.5): 8 s at F600.
constexpr const char* kSlot =
    "N0001 T1 G17 G90 G54 G0 X10 Y30 Z2\n"
    "N0002 S1500 M3\n"
    "N0003 G1 Z-2 F300\n"
    "N0004 X90 F600\n"
    "N0005 G0 Z2\n"
    "N0006 M30\n";

// A ring of four arcs and a pocket corner under G41: arcs, compensation
// and several moves queued at once.
constexpr const char* kRing =
    "N0001 T2 G17 G90 G54 G0 X50 Y10 Z2\n"
    "N0002 S1800 M3\n"
    "N0003 G1 Z-3 F400\n"
    "N0004 G3 X70 Y30 I50 J30 F900\n"
    "N0005 G3 X50 Y50 I50 J30\n"
    "N0006 G3 X30 Y30 I50 J30\n"
    "N0007 G3 X50 Y10 I50 J30\n"
    "N0008 G0 Z2\n"
    "N0009 X80 Y40\n"
    "N0010 G1 Z-1.5 F300\n"
    "N0011 G41 X85 Y45 F700\n"
    "N0012 X95\n"
    "N0013 Y55\n"
    "N0014 G40 X80 Y40\n"
    "N0015 G0 Z2\n"
    "N0016 M30\n";

struct LiveFixture {
    LiveFixture() : cell(demoCell()) { mill().setLiveCutting(true); }
    core::Station& select(const std::string& source) {
        core::ProgramPtr program = cell.addProgram(0, 1, "live.nc", source);
        EXPECT_FALSE(program->diagnostics.hasErrors()) << diagnosticsText(program->diagnostics);
        EXPECT_TRUE(mill().selectProgram(1));
        return mill();
    }
    core::Station& mill() { return cell.station(0); }
    const core::removal::PartModel* part() { return mill().liveCut().part(); }
    /// Height of the part at program point (x, y): the cell whose centre is nearest.
    double heightAt(double x, double y) {
        const HeightField& f = *part()->heightField();
        const auto cell = [](double at, double min, double step) {
            return static_cast<int>(std::floor((at - min) / step));
        };
        return f.height(cell(x + kZeroX, f.stock().min[0], f.cellWidth()),
                        cell(y + kZeroY, f.stock().min[1], f.cellDepth()));
    }
    /// Advances in `tick` steps until the station is done (bounded).
    void runToEnd(double tick) {
        for (int i = 0; i < 100000 && mill().busy(); ++i)
            mill().advance(tick);
        EXPECT_FALSE(mill().busy());
        EXPECT_EQ(mill().runStatus(), core::RunStatus::Ended);
    }
    /// Advances in small steps until the tool is on the slot's X move at
    /// program X `x` or beyond (bounded); returns where it is.
    double runAlongTheSlotTo(double x) {
        double at = 0.0;
        for (int i = 0; i < 4000; ++i) {
            mill().advance(0.05);
            const core::QueuedBlockState* block = mill().executingBlockState();
            at = mill().machine().position(0) - kZeroX;
            if (block && block->index == 3 && at >= x) break;  // N0004
        }
        return at;
    }
    core::Cell cell;
};

TEST(LiveCut, CutsOnlyWhereTheToolHasTravelled) {
    LiveFixture f;
    core::Station& mill = f.select(kSlot);
    ASSERT_TRUE(mill.press(ControlKey::Start));
    ASSERT_NE(f.part(), nullptr) << diagnosticsText(mill.liveCut().problems());
    EXPECT_EQ(f.part()->removedVolume(), 0.0) << "the blank at Start";
    EXPECT_NEAR(f.part()->resolution(), 0.2, 1e-12);
    const double x = f.runAlongTheSlotTo(50.0);  // half the slot
    ASSERT_GE(x, 50.0);
    ASSERT_LT(x, 52.0);
    EXPECT_NEAR(f.heightAt(30.0, 30.0), kTop - 2.0, 1e-6) << "behind the tool: cut";
    EXPECT_NEAR(f.heightAt(x - 0.5, 30.0), kTop - 2.0, 1e-6) << "under the tool: cut";
    EXPECT_NEAR(f.heightAt(x + 3.5 + 0.5, 30.0), kTop, 1e-6) << "ahead of the tool: not yet";
    EXPECT_NEAR(f.heightAt(70.0, 30.0), kTop, 1e-6) << "ahead of the tool: not yet";
    // The share of the slot cut so far: the plunge disc and the travelled length.
    const double travelled = (kPi * 3.5 * 3.5 + (x - 10.0) * 7.0) * 2.0;
    EXPECT_NEAR(f.part()->removedVolume(), travelled, 0.05 * travelled);

    f.runToEnd(0.25);
    // Within the cells on the slot's border (MaterialRemovalTest's bound).
    const double slot = (kPi * 3.5 * 3.5 + 80.0 * 7.0) * 2.0;
    const double border = (2.0 * 80.0 + 2.0 * kPi * 3.5) * std::sqrt(2.0) * 0.2 * 2.0;
    EXPECT_NEAR(f.part()->removedVolume(), slot, border);
    EXPECT_NEAR(f.heightAt(70.0, 30.0), kTop - 2.0, 1e-6);
    EXPECT_EQ(mill.liveCut().pendingMoves(), 0u);
}

TEST(LiveCut, FeedHoldHoldsTheCutAndResetStopsIt) {
    LiveFixture f;
    core::Station& mill = f.select(kSlot);
    ASSERT_TRUE(mill.press(ControlKey::Start));
    ASSERT_GE(f.runAlongTheSlotTo(30.0), 30.0);
    ASSERT_TRUE(mill.press(ControlKey::Stop));
    for (int i = 0; i < 40; ++i)  // decelerates, then stands
        mill.advance(0.05);
    const double held = f.part()->removedVolume();
    const std::uint64_t revision = mill.liveCut().revision();
    for (int i = 0; i < 40; ++i)
        mill.advance(0.05);
    EXPECT_EQ(f.part()->removedVolume(), held) << "standing axes cut nothing";
    EXPECT_EQ(mill.liveCut().revision(), revision);
    ASSERT_TRUE(mill.press(ControlKey::Start));  // resumes mid-block
    for (int i = 0; i < 20; ++i)
        mill.advance(0.05);
    const double resumed = f.part()->removedVolume();
    EXPECT_GT(resumed, held);

    ASSERT_TRUE(mill.press(ControlKey::ControlReset));
    const double stopped = f.part()->removedVolume();
    const double stoppedX = mill.machine().position(0) - kZeroX;
    mill.advance(5.0);
    EXPECT_EQ(f.part()->removedVolume(), stopped) << "after reset nothing more is cut";
    EXPECT_NEAR(f.heightAt(stoppedX + 3.5 + 0.5, 30.0), kTop, 1e-6);

    // A new Start: a new blank.
    const std::uint64_t run = mill.liveCut().run();
    ASSERT_TRUE(mill.selectProgram(1));
    ASSERT_TRUE(mill.press(ControlKey::Start));
    EXPECT_EQ(mill.liveCut().run(), run + 1);
    EXPECT_EQ(f.part()->removedVolume(), 0.0);
}

TEST(LiveCut, ARunToItsEndLeavesThePartTheSimulationMakes) {
    for (const char* source : {kSlot, kRing}) {
        SCOPED_TRACE(source == kSlot ? "slot" : "ring");
        LiveFixture f;
        core::Station& mill = f.select(source);
        ASSERT_TRUE(mill.press(ControlKey::Start));
        f.runToEnd(0.1);
        ASSERT_NE(f.part(), nullptr);
        const core::removal::RemovalRunResult simulated =
            core::removal::simulateRemoval(f.cell.config().processes[0], f.cell.store(), 1,
                                           core::removal::RemovalSettings{f.part()->resolution()});
        ASSERT_TRUE(simulated.part);
        const HeightField& live = *f.part()->heightField();
        const HeightField& whole = *simulated.part->heightField();
        ASSERT_EQ(live.columns(), whole.columns());
        ASSERT_EQ(live.rows(), whole.rows());
        int different = 0;
        for (int j = 0; j < live.rows(); ++j)
            for (int i = 0; i < live.columns(); ++i)
                if (std::abs(live.height(i, j) - whole.height(i, j)) > 1e-4) ++different;
        EXPECT_EQ(different, 0) << "cells that differ from the simulated part";
        EXPECT_GT(f.part()->removedVolume(), 100.0);
        EXPECT_NEAR(f.part()->removedVolume(), simulated.part->removedVolume(), 1e-3);
    }
}

// Program 99 for the restart below: up to a safe height, over the part,
// down into the slot; or straight across the part at slot depth.
constexpr const char* kOverThePart =
    "N0000 M30\n"
    "N0001 .ADJUST G0 G54 Z20\n"
    "N0002 .REPOS G77 X0 Y0 F3000\n"
    "N0003 G77 Z0 F600 RTS\n";
constexpr const char* kThroughThePart =
    "N0000 M30\n"
    "N0001 .ADJUST @150=0\n"
    "N0002 .REPOS G77 X0 Y0 F3000\n"
    "N0003 G77 Z0 F600 RTS\n";

/// Restarts the slot program at N0050 with the axes beside the part at slot
/// depth, runs it to its end; the removed volume at the target (from the
/// check) and at the end.
std::array<double, 2> restartTheSlot(const char* library) {
    RestartStation mill(0);
    core::Station& station = mill.cell.station;
    station.setLiveCutting(true);
    mill.cell.add(library, 99);
    mill.cell.add(kSlotRestartProgram, 1);
    mill.cell.live.takeMachinePositions({50.0 + kZeroX, 70.0 + kZeroY, -4.0 + kTop});
    DiagnosticList refused;
    EXPECT_TRUE(station.acceptRestart(mill.cell.selection(1, 1, 50), refused))
        << diagnosticsText(refused);
    EXPECT_EQ(station.liveCut().part(), nullptr) << "no part before the target is known";
    for (int i = 0; i < 200 && station.restart().phase() != RestartPhase::TargetReached; ++i)
        station.advance(0.05);
    EXPECT_EQ(station.restart().phase(), RestartPhase::TargetReached);
    const auto& check = station.checkReentry();
    EXPECT_TRUE(check && check->checked);
    if (!check || !station.liveCut().part()) return {-1.0, -1.0};
    const double atTarget = station.liveCut().part()->removedVolume();
    EXPECT_EQ(atTarget, check->removedVolume) << "the live part is the part at the target";
    EXPECT_TRUE(station.liveCut().fromRestart());
    EXPECT_TRUE(station.press(ControlKey::Start));  // ADJUST, REPOS, the rest of the slot
    for (int i = 0; i < 20000 && (station.busy() || station.restart().active()); ++i)
        station.advance(0.1);
    EXPECT_FALSE(station.busy());
    return {atTarget, station.liveCut().part()->removedVolume()};
}

TEST(LiveCut, ARestartCutsOnFromThePartAtItsTarget) {
    const core::ProcessConfig& mill = demoCell().processes[0];
    core::ProgramStore store;
    store.put(0, 1, parse(kSlotRestartProgram, 1));
    const core::removal::RemovalRunResult finished =
        core::removal::simulateRemoval(mill, store, 1, core::removal::RemovalSettings{});
    ASSERT_TRUE(finished.part);

    const std::array<double, 2> over = restartTheSlot(kOverThePart);
    EXPECT_GT(over[0], 0.0) << "the slot was cut before the target";
    EXPECT_GT(over[1], over[0]) << "the target block cuts on";
    EXPECT_NEAR(over[1], finished.part->removedVolume(), 1e-6)
        << "a way back over the part leaves the finished part";

    const std::array<double, 2> through = restartTheSlot(kThroughThePart);
    EXPECT_EQ(through[0], over[0]);
    EXPECT_GT(through[1], finished.part->removedVolume() + 100.0)
        << "the way back across the part cut a groove into it";
}

// The lathe: a groove milled along the bar and around it under G32 with
// the driven end mill T9, after the jacket is reached through a plunge.
constexpr const char* kJacketGroove =
    "N0001 T9 G18 G90 G54 G0 X46 Z-20\n"
    "N0002 G0 C0\n"
    "N0003 G20 Z0 C0 X0\n"
    "N0004 G32 RI 40\n"
    "N0005 G0 G56 Y1 30 Z1 230\n"
    "N0006 G1 X37.5 F150\n"
    "N0007 G1 Z1 180 F400\n"
    "N0008 G1 Y1 90\n"
    "N0009 G0 X46\n"
    "N0010 G30\n"
    "N0011 G18\n"
    "N0012 M30\n";

TEST(LiveCut, GroovesOnTheLathesJacketAreCutLiveToo) {
    core::Cell cell(demoCell());
    core::Station& lathe = cell.station(cell.slotOfProcess(1));
    lathe.setLiveCutting(true);
    cell.addProgram(cell.slotOfProcess(1), 1, "jacket.nc", kJacketGroove);
    ASSERT_TRUE(lathe.selectProgram(1));
    ASSERT_TRUE(lathe.press(ControlKey::Start));
    for (int i = 0; i < 100000 && lathe.busy(); ++i)
        lathe.advance(0.1);
    ASSERT_EQ(lathe.runStatus(), core::RunStatus::Ended) << diagnosticsText(lathe.runDiagnostics());
    const core::removal::PartModel* live = lathe.liveCut().part();
    ASSERT_NE(live, nullptr);
    ASSERT_NE(live->jacket(), nullptr) << "the G32 moves reached the jacket";
    const core::removal::RemovalRunResult simulated = core::removal::simulateRemoval(
        *cell.config().process(1), cell.store(), 1,
        core::removal::RemovalSettings{live->resolution(), core::removal::kViewCells});
    ASSERT_TRUE(simulated.part && simulated.part->jacket());
    EXPECT_GT(live->removedVolume(), 1000.0);
    EXPECT_NEAR(live->removedVolume(), simulated.part->removedVolume(), 1e-6);
}

// After the run, MDI entries and jogs cut on the part it left (TP-028).
struct ByHandFixture : LiveFixture {
    ByHandFixture() {
        core::Station& station = select(kSlot);
        EXPECT_TRUE(station.press(ControlKey::Start));
        runToEnd(0.25);
        EXPECT_TRUE(station.press(ControlKey::Manual));
    }
    void settle() {
        for (int i = 0; i < 100'000 && (mill().jogging() || mill().busy()); ++i)
            mill().advance(0.02);
    }
    /// Jogs Y (machine axis 1) with the held key until program Y `y`, then releases.
    void holdJogTo(double y) {
        ASSERT_TRUE(mill().jogStart(1, +1));
        for (int i = 0; i < 10'000 && mill().machine().position(1) - kZeroY < y; ++i)
            mill().advance(0.01);
        mill().jogRelease();
        settle();
    }
};

TEST(LiveCut, JogsAfterTheRunCutOnItsPart) {
    ByHandFixture f;
    core::Station& mill = f.mill();
    const double afterRun = f.part()->removedVolume();
    EXPECT_FALSE(mill.liveCut().cutOnByHand());
    ASSERT_TRUE(mill.jogBy(2, -3.0));  // from Z2 into the slot's end: air
    f.settle();
    EXPECT_EQ(f.part()->removedVolume(), afterRun) << "inside the slot nothing is left to cut";
    EXPECT_TRUE(mill.liveCut().cutOnByHand());
    ASSERT_TRUE(mill.jogBy(1, 10.0));  // along Y at Z-1: out of the slot into the block
    mill.advance(0.1);
    const double y = mill.machine().position(1) - kZeroY;
    ASSERT_GT(y, 31.0);
    ASSERT_LT(y, 39.0) << "mid-jog";
    EXPECT_NEAR(f.heightAt(90.0, y + 3.5 + 0.5), kTop, 1e-6) << "ahead of the tool: not yet";
    f.settle();
    // The tool centre keeps the run's distance to the axes: Z-1 is 1 deep.
    EXPECT_NEAR(f.heightAt(90.0, 38.0), kTop - 1.0, 1e-6);
    EXPECT_NEAR(f.heightAt(90.0, 45.0), kTop, 1e-6) << "beyond the jog's end and radius";
    const double groove = 10.0 * 7.0 * 1.0;  // 10 long, 7 wide, 1 deep, less the slot's round end
    EXPECT_GT(f.part()->removedVolume() - afterRun, 0.7 * groove);
    EXPECT_LT(f.part()->removedVolume() - afterRun, 1.2 * groove);
}

TEST(LiveCut, AReleasedJogIsCutOnlyToWhereTheAxisStopped) {
    ByHandFixture f;
    core::Station& mill = f.mill();
    ASSERT_TRUE(mill.jogBy(2, -3.0));
    f.settle();
    f.holdJogTo(40.0);
    const double stopped = mill.machine().position(1) - kZeroY;
    ASSERT_GE(stopped, 40.0);
    ASSERT_LT(stopped, 45.0);
    EXPECT_NEAR(f.heightAt(90.0, stopped - 1.0), kTop - 1.0, 1e-6);
    EXPECT_NEAR(f.heightAt(90.0, stopped + 3.5 + 0.5), kTop, 1e-6)
        << "the continuous jog's far target is not cut";
    EXPECT_EQ(mill.liveCut().pendingMoves(), 0u);
    const double volume = f.part()->removedVolume();
    mill.advance(1.0);
    EXPECT_EQ(f.part()->removedVolume(), volume);
}

TEST(LiveCut, AnMdiEntryAfterTheRunCutsOnItsPart) {
    ByHandFixture f;
    core::Station& mill = f.mill();
    ASSERT_TRUE(mill.jogBy(2, -3.0));
    f.settle();
    const double before = f.part()->removedVolume();
    ASSERT_TRUE(mill.press(ControlKey::Mdi));
    mill.setMdiInput("G91 G1 Y12 F900");
    ASSERT_TRUE(mill.press(ControlKey::Start)) << mill.control().alarm();
    f.settle();
    EXPECT_NEAR(mill.machine().position(1) - kZeroY, 42.0, 1e-9);
    EXPECT_NEAR(f.heightAt(90.0, 40.0), kTop - 1.0, 1e-6);
    EXPECT_GT(f.part()->removedVolume(), before + 50.0);
    EXPECT_TRUE(mill.liveCut().cutOnByHand());
    // The next Start of the program takes a new blank.
    ASSERT_TRUE(mill.press(ControlKey::Automatic));
    ASSERT_TRUE(mill.selectProgram(1));
    ASSERT_TRUE(mill.press(ControlKey::Start));
    EXPECT_EQ(f.part()->removedVolume(), 0.0);
    EXPECT_FALSE(mill.liveCut().cutOnByHand());
}

TEST(LiveCut, OffByDefault) {
    LiveFixture f;
    f.mill().setLiveCutting(false);
    core::Station& mill = f.select(kSlot);
    ASSERT_TRUE(mill.press(ControlKey::Start));
    f.runToEnd(0.5);
    EXPECT_EQ(mill.liveCut().run(), 0u) << "the CLI's runs make no part";
    EXPECT_EQ(f.part(), nullptr);
}

}  // namespace
}  // namespace mtc::test
