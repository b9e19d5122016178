// Adaptive feed control in the interpreter and the simulated machine (seed
// 002): G25/G26 and ITM in NC blocks, AXD P-7-3651/3652, the feed the axes
// get under G26, errors 508/509/510 as runtime errors of their block,
// refusals, the update moments of page 30 and of PxxS.THMIS / PxxS.EXCTH,
// deactivation at program end and control reset, the trend recorder.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "InterpTestSupport.h"
#include "cnc_core/afc/AdaptiveFeedControl.h"
#include "cnc_core/afc/AfcMotion.h"
#include "cnc_core/afc/AfcTrendRecorder.h"
#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/machine/MachineConfigReader.h"
#include "cnc_core/machine/SimulatedMachine.h"
#include "cnc_core/machine_data/MachineDataStore.h"

namespace {

using namespace mtc::core;
using namespace mtc::test;

/// Process `index` of the demo cell; without its raw part (stock) unless
/// `withStock`: then every feed move cuts (AFC-017).
ProcessConfig demoProcess(int index, bool withStock) {
    ProcessConfig process = *demoCell().process(index);
    if (!withStock) process.stock.clear();
    return process;
}

/// The demo mill on a simulated machine with adaptive feed control wired as
/// in the panel (CellSession) and the CLI.
struct AfcCell {
    explicit AfcCell(std::map<std::string, double> torqueModel = {}, int processIndex = 0,
                     std::map<std::string, std::string> parameters = {}, bool withStock = false)
        : process(demoProcess(processIndex, withStock)),
          data(std::make_shared<MachineDataStore>(demoCell())),
          machine(process),
          recorder(5000) {
        process.torqueModel = std::move(torqueModel);
        for (const auto& [number, value] : parameters)
            process.parameters[number] = value;
        afc = std::make_shared<AdaptiveFeedControl>(process, *data, torqueModelFromConfig(process),
                                                    &signals);
        InterpreterServices services;
        services.machineData = data;
        interpreter = std::make_unique<Interpreter>(process, store, machine, services);
        interpreter->setAdaptiveFeed(afc);
        machine.attachAdaptiveFeed(afc.get(), &recorder);
    }
    /// Stores and selects `source` as program 1.
    void load(const std::string& source) {
        store.put(process.index, 1, parse(source, 1));
        ASSERT_TRUE(interpreter->select(1));
    }
    RunResult run(const std::string& source) {
        load(source);
        RunResult result = interpreter->run();
        finishQueuedWork();
        return result;
    }
    /// Simulated time passes only in advance() (as the Station drives it):
    /// lets the machine do what the interpreter queued.
    void finishQueuedWork() {
        for (int i = 0; i < 1'000'000 && !machine.idle(); ++i)
            machine.advance(kAfcMaxMoveSeconds);
    }
    /// Seconds spindle 1 needs from rest to `rpm` (its ramp, MOT-007).
    double spindleRunUp(double rpm) const {
        for (const AxisConfig& axis : process.axes)
            if (axis.kind == AxisKind::Spindle && axis.spindleIndex == 1)
                return rpm / (axis.maxAcceleration / 6.0);
        return 0.0;
    }
    /// Executes blocks up to and including the one with number `n` (N n).
    void runThrough(int n) {
        for (int i = 0; i < 100; ++i) {
            const auto& state = interpreter->state();
            const int number = state.program->blocks[state.block].number;
            const RunResult result = interpreter->step();
            finishQueuedWork();
            ASSERT_EQ(result.status, RunStatus::Running) << diagnosticsText(result.diagnostics);
            if (number == n) return;
        }
        FAIL() << "block N" << n << " not reached";
    }
    double md(int element) const {
        double value = -1;
        data->read({30, process.index, 0, element}, value);
        return value;
    }
    int signal(const char* name) const { return signals.get(std::string("P00S") + name); }

    ProcessConfig process;
    std::shared_ptr<MachineDataStore> data;
    SignalTable signals;
    ProgramStore store;
    SimulatedMachine machine;
    AfcTrendRecorder recorder;
    std::shared_ptr<AdaptiveFeedControl> afc;
    std::unique_ptr<Interpreter> interpreter;
};

// Spindle on, then a cut at 1500 mm/min: 60 % * 1.5^0.8 = 83 % cutting torque
// against the limiting machining torque of 50 % (Bxx.064 default).
const char* const kHeavyCut =
    "N0010 S1=4000 M3\n"
    "N0020 G1 X0 Y0 F1500\n"
    "N0030 G26 X200\n"
    "N0040 G25\n"
    "N0050 M30\n";

TEST(AfcInterp, G26SlowsTheFeedAndTheClock) {
    AfcCell cell;
    cell.load(kHeavyCut);
    cell.runThrough(20);
    EXPECT_FALSE(cell.machine.lastMoveAdapted());
    const double before = cell.interpreter->state().modal.time;
    cell.runThrough(30);
    EXPECT_TRUE(cell.machine.lastMoveAdapted());
    EXPECT_EQ(cell.md(1), 1);
    EXPECT_GT(cell.md(11), 5.0);                     // 011 current feed reduction
    EXPECT_LT(cell.machine.lastMoveFeed(), 1400.0);  // the axes got less than F1500
    EXPECT_NEAR(cell.md(7), 50.0, 6.0);              // 007 settles at 010
    const double planned = 200.0 / 1500.0 * 60.0;
    EXPECT_GT(cell.interpreter->state().modal.time - before, planned * 1.05);
    EXPECT_NEAR(cell.machine.position(0), 200.0, 1e-9);
    EXPECT_GT(cell.recorder.size(), 100u);
}

TEST(AfcInterp, UnderG26TheAxesFollowTheControllersCourseNotItsMean) {
    // The controller starts at F1500 and reduces the feed within the first
    // second: the axes move faster than the mean at first, slower at the end.
    AfcCell cell;
    cell.load(kHeavyCut);
    cell.runThrough(20);
    ASSERT_EQ(cell.interpreter->step().status, RunStatus::Running);  // N0030 queued
    std::vector<double> feeds;
    for (int i = 0; i < 100'000 && !cell.machine.idle(); ++i) {
        cell.machine.advance(0.02);
        if (!cell.machine.idle()) feeds.push_back(cell.machine.actualFeed());
    }
    ASSERT_GT(feeds.size(), 100u);
    const double mean = cell.machine.lastMoveFeed();
    EXPECT_GT(feeds.front(), mean * 1.05);
    EXPECT_LT(feeds.back(), mean * 0.99);
    EXPECT_LE(*std::max_element(feeds.begin(), feeds.end()), 1500.0 + 1e-6);
    EXPECT_NEAR(cell.machine.position(0), 200.0, 1e-9);
}

TEST(AfcInterp, TheControllerActsOnTheFeedAtTheOverride) {
    // At 50 % the heavy cut meets the tool at 750 mm/min: less cutting
    // torque, so the controller reduces less and the axes get more than half
    // of what they get at 100 %.
    struct Cut {
        double reduction, feed, seconds;
    };
    auto cutAt = [](double percent) {
        AfcCell cell;
        cell.machine.setFeedOverride(percent);
        cell.load(kHeavyCut);
        cell.runThrough(20);
        const double before = cell.machine.seconds();
        cell.runThrough(30);
        EXPECT_TRUE(cell.machine.lastMoveAdapted());
        EXPECT_NEAR(cell.machine.position(0), 200.0, 1e-9);
        return Cut{cell.md(11), cell.machine.lastMoveFeed(), cell.machine.seconds() - before};
    };
    const Cut full = cutAt(100), half = cutAt(50);
    EXPECT_LT(half.reduction, full.reduction - 5.0);  // 011 current feed reduction
    EXPECT_GT(half.feed, full.feed / 2 * 1.1);
    EXPECT_LT(half.feed, 750.0);
    // the time the axes took is the path at the feed they got
    EXPECT_NEAR(half.seconds, 200.0 / half.feed * 60.0, 0.5);
}

TEST(AfcInterp, G25StoresThePeaksAndProgramEndResetsTheSignals) {
    AfcCell cell;
    cell.load(kHeavyCut);
    cell.runThrough(30);
    EXPECT_EQ(cell.signal("EXCTH"), 0);  // 011 stays below 013 = 70 %
    EXPECT_EQ(cell.md(8), 0.0);          // 008 not yet: written at G25
    cell.runThrough(40);
    EXPECT_EQ(cell.md(1), 0);
    EXPECT_GT(cell.md(8), 50.0);
    EXPECT_GT(cell.md(12), 5.0);
    EXPECT_GT(cell.md(11), 0.0);         // the last 011 stays after G25
    EXPECT_EQ(cell.signal("THMIS"), 0);  // 009 = 10 % was exceeded
    EXPECT_EQ(cell.interpreter->step().status, RunStatus::Ended);
    EXPECT_EQ(cell.signal("THMIS"), 0);
}

TEST(AfcInterp, ExcessiveThrustFollowsTheReductionWhileG26) {
    // 013 = 10 % through the page (002 != 0: the page rules): EXCTH 0 -> 1.
    AfcCell cell;
    const RunResult result = cell.run(
        "N0010 S1=4000 M3\n"
        "N0020 MTD(30,0,2)=10 MTD(30,0,13)=10\n"
        "N0030 G1 G26 X200 F1500\n"
        "N0040 G25\n"
        "N0050 M0\n"
        "N0060 M30\n");
    ASSERT_EQ(result.status, RunStatus::Stopped) << diagnosticsText(result.diagnostics);
    EXPECT_EQ(cell.signal("EXCTH"), 1);  // kept after G25
    EXPECT_EQ(cell.interpreter->run().status, RunStatus::Ended);
    EXPECT_EQ(cell.signal("EXCTH"), 0);  // program end resets it
    bool rose = false;
    for (const SignalChange& change : cell.signals.log())
        rose = rose || (change.name == "P00SEXCTH" && change.value == 1);
    EXPECT_TRUE(rose);
}

TEST(AfcInterp, ThrustMissingWhenTheToolCutsAir) {
    AfcCell cell({{"engagement", 0.0}});
    const RunResult result = cell.run(
        "N0010 S1=4000 M3\n"
        "N0020 G1 G26 X100 F1000\n"
        "N0030 G25\n"
        "N0040 M0\n"
        "N0050 G26 X0\n"
        "N0060 M30\n");
    ASSERT_EQ(result.status, RunStatus::Stopped);
    EXPECT_EQ(cell.signal("THMIS"), 1);  // 007 never exceeded 009 = 10 %
    EXPECT_EQ(cell.interpreter->step().status, RunStatus::Running);
    EXPECT_EQ(cell.signal("THMIS"), 0);  // G26 resets it
    EXPECT_EQ(cell.interpreter->run().status, RunStatus::Ended);
    EXPECT_EQ(cell.md(1), 0);  // program end switched G26 off
    EXPECT_EQ(cell.signal("THMIS"), 0);
}

TEST(AfcInterp, ItmMeasuresTheIdlingTorque) {
    AfcCell cell;
    const RunResult result = cell.run(
        "N0010 S1=4000 M3\n"
        "N0020 G0 X400 ITM\n"
        "N0030 M30\n");
    ASSERT_EQ(result.status, RunStatus::Ended) << diagnosticsText(result.diagnostics);
    // Friction 6 % .. 10 % at half the spindle's speed: about 8 %, noise +-1 %.
    EXPECT_NEAR(cell.md(5), 8.0, 0.5);
}

TEST(AfcInterp, Error508WhenTheItmBlockIsTooShort) {
    AfcCell cell;
    RunResult result = cell.run("N0010 S1=4000 M3\nN0020 G1 X1 F1000 ITM\nN0030 M30\n");
    ASSERT_EQ(result.status, RunStatus::Error);
    ASSERT_EQ(errorCodes(result.diagnostics), std::vector<std::string>{"AFC_ERROR_508"});
    const Diagnostic& d = result.diagnostics.items().back();
    EXPECT_EQ(d.where.block, "N0020");
    EXPECT_EQ(d.where.line, 2);
    EXPECT_EQ(d.where.program, 1);
    // ITM in a block without a move: 508 before anything is executed.
    AfcCell still;
    result = still.run("N0010 ITM\nN0020 M30\n");
    EXPECT_EQ(errorCodes(result.diagnostics), std::vector<std::string>{"AFC_ERROR_508"});
}

TEST(AfcInterp, Error509StopsTheMoveAfterTheMeasurement) {
    AfcCell cell;
    const RunResult result = cell.run(
        "N0010 S1=4000 M3\n"
        "N0020 MTD(30,0,2)=10 MTD(30,0,6)=2.0\n"
        "N0030 G1 X100 F1000 ITM\n"
        "N0040 M30\n");
    ASSERT_EQ(errorCodes(result.diagnostics), std::vector<std::string>{"AFC_ERROR_509"});
    EXPECT_EQ(result.diagnostics.items().back().where.block, "N0030");
    EXPECT_GT(cell.md(5), 2.0);  // 005 shows what was measured
    EXPECT_LT(cell.machine.position(0), 50.0);
}

TEST(AfcInterp, Error510NeedsClearErrorThatIsControlReset) {
    // A jammed axis (constant load 200 %): the reduction reaches 100 %.
    AfcCell cell({{"load", 200.0}});
    RunResult result = cell.run("N0010 S1=4000 M3\nN0020 G1 G26 X200 F1000\nN0030 M30\n");
    ASSERT_EQ(errorCodes(result.diagnostics), std::vector<std::string>{"AFC_ERROR_510"});
    EXPECT_EQ(result.diagnostics.items().back().where.block, "N0020");
    EXPECT_LT(cell.machine.position(0), 200.0);
    EXPECT_EQ(cell.md(11), 100.0);
    EXPECT_TRUE(cell.afc->errorPending());
    // Without Clear Error the next G26 is refused.
    cell.afc->switchOff();
    cell.load("N0010 G1 G26 X0 F1000\nN0020 M30\n");
    result = cell.interpreter->run();
    EXPECT_EQ(errorCodes(result.diagnostics), std::vector<std::string>{"AFC_ERROR_PENDING"});
    cell.interpreter->controlReset();
    EXPECT_FALSE(cell.afc->errorPending());
    EXPECT_EQ(cell.md(1), 0);
}

TEST(AfcInterp, RefusedWithExcludingFunctions) {
    // The lathe with adaptive feed control on its spindle S1: G32 excludes G26.
    const std::map<std::string, std::string> afcLathe = {{"B062", "yes"}, {"B063", "10"}};
    const char* const cylinder = "N0001 G0 X80 Z50 C0\nN0002 G20 Z0 C0 X0\nN0003 G32 RI 40\n";
    AfcCell cell({}, 1, afcLathe);
    RunResult result = cell.run(std::string(cylinder) + "N0004 G26\nN0005 M30\n");
    EXPECT_EQ(errorCodes(result.diagnostics), std::vector<std::string>{"AFC_INCOMPATIBLE"});
    EXPECT_EQ(result.diagnostics.items().back().where.block, "N0004");
    EXPECT_EQ(cell.md(1), 0);  // nothing changed
    AfcCell later({}, 1, afcLathe);
    result = later.run("N0001 S1=500 M3\nN0002 G26\nN0003 G20 Z0 C0 X0\nN0004 G32 RI 40\n");
    EXPECT_EQ(errorCodes(result.diagnostics), std::vector<std::string>{"AFC_INCOMPATIBLE"});
    EXPECT_EQ(result.diagnostics.items().back().where.block, "N0004");
    AfcCell stop;
    result = stop.run("N0010 G26 G75 X10 F100\nN0020 M30\n");
    EXPECT_EQ(errorCodes(result.diagnostics), std::vector<std::string>{"AFC_INCOMPATIBLE"});
    AfcCell active;
    result = active.run("N0010 S1=1000 M3\nN0020 G26\nN0030 G74 X0\nN0040 M30\n");
    EXPECT_EQ(errorCodes(result.diagnostics), std::vector<std::string>{"AFC_INCOMPATIBLE"});
    EXPECT_EQ(result.diagnostics.items().back().where.block, "N0030");
    // The lathe (process 1) has Bxx.062 = no.
    AfcCell lathe({}, 1);
    result = lathe.run("N0010 G26\nN0020 M30\n");
    EXPECT_EQ(errorCodes(result.diagnostics), std::vector<std::string>{"AFC_NOT_AVAILABLE"});
}

TEST(AfcInterp, Element002DecidesWhoseLimitsCount) {
    // 002 != 0: the page's 010 = 150 % rules, the cut stays unreduced.
    AfcCell page;
    RunResult result = page.run(
        "N0010 S1=4000 M3\nN0020 MTD(30,0,2)=10 MTD(30,0,10)=150\nN0030 G1 G26 X100 F1500\n"
        "N0040 M30\n");
    ASSERT_EQ(result.status, RunStatus::Ended) << diagnosticsText(result.diagnostics);
    EXPECT_EQ(page.md(12), 0.0);
    EXPECT_EQ(page.md(10), 150.0);
    // 002 = 0: G26 copies Bxx.064 = 50 % over the page and reduces.
    AfcCell parameters;
    result = parameters.run(
        "N0010 S1=4000 M3\nN0020 MTD(30,0,10)=150\nN0030 G1 G26 X100 F1500\nN0040 M30\n");
    ASSERT_EQ(result.status, RunStatus::Ended);
    EXPECT_EQ(parameters.md(10), 50.0);
    EXPECT_EQ(parameters.md(2), 10.0);
    EXPECT_GT(parameters.md(12), 5.0);
}

TEST(AfcInterp, ControlResetSwitchesG26Off) {
    AfcCell cell;
    cell.load(kHeavyCut);
    cell.runThrough(30);
    EXPECT_EQ(cell.md(1), 1);
    cell.interpreter->controlReset();
    EXPECT_EQ(cell.md(1), 0);
    EXPECT_FALSE(cell.afc->active());
    EXPECT_EQ(cell.signal("EXCTH"), 0);
}

TEST(AfcInterp, StallTorqueRecordedAndReadThroughAxd) {
    AfcCell cell({{"stall", -5.0}, {"noise", 0.0}});
    const RunResult result = cell.run(
        "N0010 @160=300\n"
        "N0020 AXD(S1:P-7-3651)=@160\n"
        "N0030 @122=AXD(S1:P-7-3652)\n"
        "N0040 @123=AXD(S:P-7-3652)\n"
        "N0050 M30\n");
    ASSERT_EQ(result.status, RunStatus::Ended) << diagnosticsText(result.diagnostics);
    EXPECT_DOUBLE_EQ(cell.interpreter->state().variables.values[122], -50.0);  // 0.1 %
    EXPECT_DOUBLE_EQ(cell.interpreter->state().variables.values[123], -50.0);
    EXPECT_DOUBLE_EQ(cell.md(14), 5.0);  // 014 = |P-7-3652|
    AfcCell bad;
    EXPECT_EQ(errorCodes(bad.run("N0010 AXD(X:P-7-3651)=70000\n").diagnostics),
              std::vector<std::string>{"AFC_BAD_PERIOD"});
    AfcCell other;
    EXPECT_EQ(errorCodes(other.run("N0010 @1=AXD(X:P-7-3600)\n").diagnostics),
              std::vector<std::string>{"AXD_NOT_READABLE"});
}

TEST(AfcInterp, WithoutAdaptiveFeedControlG26IsRefused) {
    Station station(demoCell(), 0);
    station.interpreter->setAdaptiveFeed(nullptr);
    const RunResult result = station.run("N0010 G26\nN0020 M30\n");
    EXPECT_EQ(errorCodes(result.diagnostics), std::vector<std::string>{"AFC_NOT_AVAILABLE"});
    EXPECT_EQ(station.run("N0010 G25\nN0020 M30\n").status, RunStatus::Ended);
    // A sink that is no simulated machine: G26 switches, ITM measures nothing.
    Station recording(demoCell(), 0);
    EXPECT_EQ(recording.run("N0010 S1=1000 M3\nN0020 G1 G26 X10 F100 ITM\nN0030 M30\n").status,
              RunStatus::Ended);
    double idle = -1;
    recording.interpreter->machineData().read({30, 0, 0, 5}, idle);
    EXPECT_EQ(idle, 0.0);
}

TEST(AfcTrend, RingBufferKeepsTheNewestAndWritesCsv) {
    AfcTrendRecorder recorder(3);
    for (int i = 0; i < 5; ++i) {
        AfcTrendSample sample;
        sample.time = i;
        sample.feedReduction = 10.5 * i;
        recorder.add(sample);
    }
    ASSERT_EQ(recorder.size(), 3u);
    EXPECT_EQ(recorder.at(0).time, 2.0);
    EXPECT_EQ(recorder.at(2).time, 4.0);
    const std::string csv = recorder.csv();
    EXPECT_EQ(csv.substr(0, csv.find(',')), "time_s");
    EXPECT_NE(csv.find("\n4.0000,"), std::string::npos);
    EXPECT_NE(csv.find(",42.000,"), std::string::npos);
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 4);
    recorder.clear();
    EXPECT_EQ(recorder.size(), 0u);
}

TEST(AfcConfig, TorqueModelSection) {
    MachineConfigReadResult good = readMachineConfig(
        "[process 0]\n[process 0 axis X]\ndefinition = X\n[process 0 torque-model]\ncutting = "
        "80\nload = 5\n");
    ASSERT_FALSE(good.diagnostics.hasErrors()) << diagnosticsText(good.diagnostics);
    const TorqueModelParameters p = torqueModelFromConfig(good.config.processes[0]);
    EXPECT_EQ(p.cuttingTorque, 80.0);
    EXPECT_EQ(p.constantLoad, 5.0);
    EXPECT_EQ(p.referenceFeed, 1000.0);
    MachineConfigReadResult bad = readMachineConfig(
        "[process 0]\n[process 0 axis X]\ndefinition = X\n[process 0 torque-model]\nwear = "
        "3\ncutting = x\n");
    EXPECT_EQ(errorCodes(bad.diagnostics),
              (std::vector<std::string>{"CFG_TORQUE_MODEL", "CFG_TORQUE_MODEL"}));
}

TEST(AfcInterp, AfterError509TheStateStandsWhereTheAxesStopped) {
    // AFC-012 (regression): the final position was the programmed end point.
    AfcCell cell;
    const RunResult result = cell.run(
        "N0010 S1=4000 M3\n"
        "N0020 MTD(30,0,2)=10 MTD(30,0,6)=2.0\n"
        "N0030 G1 X100 F1000 ITM\n"
        "N0040 M30\n");
    ASSERT_EQ(errorCodes(result.diagnostics), std::vector<std::string>{"AFC_ERROR_509"});
    const double stopped = cell.machine.position(0);
    EXPECT_GT(stopped, 1.0);   // acceleration and 200 ms measuring at F1000 ...
    EXPECT_LT(stopped, 10.0);  // ... about 3.4 mm
    EXPECT_DOUBLE_EQ(cell.interpreter->state().modal.machine[0], stopped);
    EXPECT_DOUBLE_EQ(cell.interpreter->programmedPosition(0), stopped);
}

TEST(AfcInterp, AfterError510TheDistanceToGoIsWhatIsLeftOfTheBlock) {
    AfcCell cell({{"load", 200.0}});
    const RunResult result = cell.run("N0010 S1=4000 M3\nN0020 G1 G26 X200 F1000\nN0030 M30\n");
    ASSERT_EQ(errorCodes(result.diagnostics), std::vector<std::string>{"AFC_ERROR_510"});
    const double left = 200.0 - cell.machine.position(0);
    EXPECT_GT(left, 1.0);
    EXPECT_NEAR(cell.machine.distanceToGo(0), left, 1e-9);
    EXPECT_NEAR(cell.machine.distanceToGo(1), 0.0, 1e-9);
    cell.machine.stop();  // control reset: the block is given up
    EXPECT_EQ(cell.machine.distanceToGo(0), 0.0);
}

TEST(AfcInterp, AfterError510OnAnArcTheAxesStandOnTheArc) {
    AfcCell cell({{"load", 200.0}});
    const RunResult result = cell.run(
        "N0010 S1=4000 M3\n"
        "N0020 G1 X0 Y0 F1000\n"
        "N0030 G2 G26 X100 Y0 I50 J0\n"
        "N0040 M30\n");
    ASSERT_EQ(errorCodes(result.diagnostics), std::vector<std::string>{"AFC_ERROR_510"});
    const auto& machine = cell.interpreter->state().modal.machine;
    EXPECT_DOUBLE_EQ(machine[0], cell.machine.position(0));
    EXPECT_DOUBLE_EQ(machine[1], cell.machine.position(1));
    EXPECT_GT(machine[1], 1.0) << "on the arc above its chord";
    EXPECT_NEAR(std::hypot(machine[0] - 50.0, machine[1]), 50.0, 1e-9);
}

TEST(AfcInterp, AMoveLongerThanAnHourUnderG26StopsWithADiagnostic) {
    // Regression: 400 mm at F1 (24000 s) cost a CPU second per 2 million cycles.
    AfcCell cell;
    const RunResult result = cell.run("N0010 S1=4000 M3\nN0020 G1 G26 X400 F1\nN0030 M30\n");
    ASSERT_EQ(errorCodes(result.diagnostics), std::vector<std::string>{"AFC_MOVE_TOO_LONG"});
    EXPECT_EQ(result.diagnostics.items().back().where.block, "N0020");
    EXPECT_NEAR(cell.machine.position(0), 60.0, 1e-6);  // 3600 s at 1 mm/min
    EXPECT_NEAR(cell.interpreter->programmedPosition(0), 60.0, 1e-6);
    EXPECT_NEAR(cell.machine.seconds(), cell.spindleRunUp(4000) + kAfcMaxMoveSeconds, 1.0);
}

TEST(AfcInterp, ANegativeStallTorqueIsCompensatedWithItsSign) {
    // An inclined axis pulling with -5 %: 014 shows 5 %, but the idling and
    // machining torques subtract -5 % (seed 002 Fig. 5-5 / 5-7), so the run
    // is the same as on an axis without stall torque.
    const char* const program =
        "N0010 S1=4000 M3\n"
        "N0020 AXD(S1:P-7-3651)=300\n"
        "N0030 G0 X400 ITM\n"
        "N0040 G1 G26 X0 F1500\n"
        "N0050 M30\n";
    AfcCell inclined({{"stall", -5.0}, {"noise", 0.0}});
    AfcCell level({{"noise", 0.0}});
    inclined.load(program);
    level.load(program);
    inclined.runThrough(40);
    level.runThrough(40);
    EXPECT_DOUBLE_EQ(inclined.md(14), 5.0);
    EXPECT_NEAR(inclined.md(5), 8.0, 1e-9);  // friction only (with |014|: 0)
    EXPECT_NEAR(inclined.md(5), level.md(5), 1e-9);
    EXPECT_NEAR(inclined.md(7), level.md(7), 1e-9);
    EXPECT_NEAR(inclined.machine.lastMoveFeed(), level.machine.lastMoveFeed(), 1e-6);
}

TEST(AfcInterp, MovesInTheAirAreIdleAndTheTrendAgreesWithElement005) {
    // With the raw part of the demo mill (G54 plate X0..X100, Y0..Y60, Z-12..0).
    AfcCell cell({}, 0, {}, true);
    cell.load(
        "N0001 G0 G17 G54 G90 X-30 Y30 Z50\n"
        "N0002 S4000 M3\n"
        "N0003 Z2\n"
        "N0004 G1 X-10 F1000 ITM\n"
        "N0005 Z-4 F300\n"
        "N0006 G26 X25 F800\n"
        "N0007 X100 F2000\n"
        "N0008 G25\n"
        "N0009 M30\n");
    cell.runThrough(3);
    const double itmStart = cell.machine.seconds();
    cell.runThrough(4);
    const double itmEnd = cell.machine.seconds();
    cell.runThrough(6);
    const double slotEnd = cell.machine.seconds();
    const double idle = cell.md(5);
    EXPECT_NEAR(idle, 8.0, 0.5);
    int measuring = 0, inAir = 0, cutting = 0;
    for (const AfcTrendSample& s : cell.recorder.samples()) {
        if (s.time > itmStart && s.time <= itmEnd) {
            EXPECT_NEAR(s.torqueActual, idle, 2.1) << "ITM block at " << s.time;
            measuring += s.measuringIdle ? 1 : 0;
        }
        if (s.time > itmEnd && s.time <= slotEnd && s.active) {
            inAir += s.machiningTorque < 2.1 ? 1 : 0;
            cutting += s.machiningTorque > 10.0 ? 1 : 0;
        }
    }
    EXPECT_GE(measuring, 15);  // 200 ms measuring period, a sample every 10 ms
    EXPECT_GT(inAir, 10);      // X-10 .. X0: in the air before the plate
    EXPECT_GT(cutting, 10);    // X0 .. X25: in the plate
}

}  // namespace
