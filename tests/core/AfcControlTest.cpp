// Adaptive feed control (seed 002): parameters and the precedence rule of
// page 30 element 002, G26/G25 with the status elements, the I controller on
// the torque model, THMIS/EXCTH, errors 508/509/510, stall torque recording,
// refusals with incompatible functions, deactivation at program end/reset.
#include <gtest/gtest.h>

#include <cmath>

#include "InterpTestSupport.h"
#include "cnc_core/afc/AdaptiveFeedControl.h"

namespace {

using namespace mtc::core;
using namespace mtc::test;

/// The demo mill (B062 yes, reference axis S1) with its machine data and signals.
struct Mill {
    explicit Mill(TorqueModelParameters model = {})
        : data(demoCell()), afc(process(), data, model, &signals) {}
    static const ProcessConfig& process() { return *demoCell().process(0); }
    double md(int element) const {
        double v = -1;
        data.read({30, 0, 0, element}, v);
        return v;
    }
    void setMd(int element, double value) {
        ASSERT_EQ(data.write({30, 0, 0, element}, value, MachineDataWriter::Nc),
                  MachineDataStatus::Ok);
    }
    /// Runs the controller for `seconds` in 2 ms cycles; returns the last feed.
    double cut(double seconds, double feed, double engagement) {
        double effective = feed;
        for (int i = 0; i < static_cast<int>(std::lround(seconds / 0.002)); ++i)
            effective = afc.advance(0.002, feed, 0.5, engagement);
        return effective;
    }
    /// Mean machining torque of the trend's last `seconds`.
    double meanMachining(double seconds) const {
        const auto& t = afc.trend();
        double sum = 0;
        int n = 0;
        for (auto it = t.rbegin(); it != t.rend() && t.back().time - it->time < seconds; ++it, ++n)
            sum += it->machiningTorque;
        return n ? sum / n : 0;
    }
    MachineDataStore data;
    SignalTable signals;
    AdaptiveFeedControl afc;
};

TorqueModelParameters quiet() {
    TorqueModelParameters p;
    p.noiseAmplitude = 0.0;
    return p;
}

TEST(AfcParameters, DefaultsRangesAndBadValues) {
    DiagnosticList d;
    AfcParameters p = readAfcParameters(Mill::process(), d);
    EXPECT_TRUE(d.empty());
    EXPECT_TRUE(p.available);
    EXPECT_EQ(p.settings.referenceAxis, 10);
    EXPECT_EQ(p.settings.limitingTorque, 50);
    EXPECT_EQ(p.settings.minimumTorque, 10);
    EXPECT_EQ(p.settings.maximumIdleTorque, 30);
    EXPECT_EQ(p.settings.maximumReduction, 70);
    EXPECT_EQ(p.settings.amplification, 1);
    EXPECT_EQ(p.settings.measuringPeriodMs, 200);
    ProcessConfig custom = Mill::process();
    custom.parameters["B064"] = "80";
    custom.parameters["B065"] = "600";  // above 500.0
    custom.parameters["B068"] = "0";    // below 0.01
    custom.parameters["B069"] = "1.5";  // not whole
    custom.parameters["B063"] = "13";
    p = readAfcParameters(custom, d);
    EXPECT_EQ(errorCodes(d), std::vector<std::string>(4, "AFC_PARAMETER"));
    EXPECT_EQ(p.settings.limitingTorque, 80);
    EXPECT_EQ(p.settings.minimumTorque, 10) << "default kept";
    EXPECT_EQ(p.settings.amplification, 1);
    EXPECT_EQ(p.settings.measuringPeriodMs, 200);
    EXPECT_EQ(p.settings.referenceAxis, 0) << "default 0 = not defined";
    EXPECT_FALSE(readAfcParameters(*demoCell().process(1), d).available) << "lathe: B062 = no";
}

TEST(AfcPrecedence, Element002DecidesWhoseLimitsCount) {
    Mill mill;
    EXPECT_EQ(mill.md(2), 0);
    EXPECT_EQ(mill.afc.effectiveSettings().limitingTorque, 50) << "process parameters";
    ASSERT_EQ(mill.afc.switchOn(), AfcStatus::Ok);
    EXPECT_EQ(mill.md(2), 10) << "002 takes Bxx.063";
    EXPECT_EQ(mill.md(10), 50);
    EXPECT_EQ(mill.md(13), 70);
    EXPECT_EQ(mill.md(3), 1);
    EXPECT_EQ(mill.md(4), 200);
    EXPECT_EQ(mill.md(6), 30);
    EXPECT_EQ(mill.md(9), 10);
    mill.afc.switchOff();
    mill.setMd(10, 35);  // MTD in the program: page 30 now rules
    EXPECT_EQ(mill.afc.effectiveSettings().limitingTorque, 35);
    ASSERT_EQ(mill.afc.switchOn(), AfcStatus::Ok);
    EXPECT_EQ(mill.md(10), 35) << "002 != 0: the page is not overwritten";
    mill.afc.switchOff();
    mill.setMd(2, 0);  // back to the process parameters
    EXPECT_EQ(mill.afc.effectiveSettings().limitingTorque, 50);
    EXPECT_EQ(mill.md(10), 35) << "the page keeps its entries until G26";
    ASSERT_EQ(mill.afc.switchOn(), AfcStatus::Ok);
    EXPECT_EQ(mill.md(10), 50) << "reset to the process parameters on activation";
    EXPECT_EQ(mill.md(2), 10);
}

TEST(AfcSwitching, StatusElementsAndTheirMoments) {
    Mill mill(quiet());
    ASSERT_EQ(mill.afc.switchOn(), AfcStatus::Ok);
    EXPECT_EQ(mill.md(1), 1);
    mill.cut(2.0, 1000, 1.5);  // 60 % * 1.5 + friction: above the 50 % limit
    EXPECT_GT(mill.md(7), 0) << "007 follows while G26 is active";
    EXPECT_GT(mill.md(11), 0);
    EXPECT_EQ(mill.md(8), 0) << "008 is updated at G25 only";
    EXPECT_EQ(mill.md(12), 0) << "012 is updated at G25 only";
    const double reduction = mill.afc.feedReduction();
    mill.afc.switchOff();
    EXPECT_EQ(mill.md(1), 0);
    EXPECT_GT(mill.md(8), 50);
    EXPECT_NEAR(mill.md(12), reduction, 0.06) << "peak reduction of a rising reduction";
    EXPECT_NEAR(mill.md(11), reduction, 0.06) << "011 keeps its last value after G25";
    EXPECT_EQ(mill.cut(0.1, 800, 3.0), 800) << "off: the programmed feed";
    ASSERT_EQ(mill.afc.switchOn(), AfcStatus::Ok);
    EXPECT_EQ(mill.md(11), 0) << "011 is set back to 0 at G26";
}

TEST(AfcController, MachiningTorqueSettlesAtTheLimit) {
    Mill mill;
    mill.afc.measureIdleTorque(1000, 0.5, 1.0);
    ASSERT_EQ(mill.afc.switchOn(), AfcStatus::Ok);
    const double feed = mill.cut(6.0, 1000, 1.4);
    EXPECT_NEAR(mill.meanMachining(1.0), 50.0, 1.5) << "the I controller holds 010";
    EXPECT_LT(feed, 1000 * 0.9);
    EXPECT_GT(feed, 1000 * 0.4);
    // Expected steady state: 60 * 1.4 * (f/1000)^0.8 = 50  =>  f = 1000 * (50/84)^(1/0.8)
    EXPECT_NEAR(feed, 1000 * std::pow(50.0 / 84.0, 1.25), 25);
}

TEST(AfcController, ALimitWrittenWhileCuttingActsOnTheNextCycle) {
    // The controller keeps page 30 between cycles (AdaptiveFeedControl's
    // memo); a write to 010 between two cycles must reach it at once.
    Mill mill(quiet());
    mill.afc.measureIdleTorque(1000, 0.5, 1.0);
    ASSERT_EQ(mill.afc.switchOn(), AfcStatus::Ok);
    mill.cut(6.0, 1000, 1.4);
    EXPECT_NEAR(mill.meanMachining(1.0), 50.0, 1.5);
    mill.setMd(10, 35);  // 002 != 0 after G26: page 30 rules
    EXPECT_EQ(mill.afc.effectiveSettings().limitingTorque, 35);
    mill.cut(6.0, 1000, 1.4);
    EXPECT_NEAR(mill.meanMachining(1.0), 35.0, 1.5);
}

TEST(AfcController, HigherAmplificationReactsFaster) {
    auto timeTo80PercentOfFinal = [](double amplification) {
        Mill mill(quiet());
        mill.afc.switchOn();
        mill.setMd(3, amplification);
        mill.cut(8.0, 1000, 1.4);
        const auto& t = mill.afc.trend();
        const double final = t.back().feedReduction;
        for (const AfcSample& s : t)
            if (s.feedReduction >= 0.8 * final) return s.time;
        return 1e9;
    };
    const double slow = timeTo80PercentOfFinal(0.2);
    const double fast = timeTo80PercentOfFinal(2.0);
    EXPECT_LT(fast * 5, slow) << "gain 10x: response about 10x quicker";
}

TEST(AfcController, NeverFasterThanProgrammed) {
    Mill mill;
    mill.afc.switchOn();
    EXPECT_EQ(mill.cut(1.0, 1200, 0.1), 1200) << "light cut: no reduction, no increase";
    EXPECT_EQ(mill.afc.feedReduction(), 0);
}

TEST(AfcSignals, ExcessiveThrustFollowsTheReduction) {
    Mill mill(quiet());
    mill.afc.measureIdleTorque(1000, 0.5, 1.0);
    mill.afc.switchOn();
    mill.setMd(13, 20);  // maximum feed reduction 20 %
    mill.cut(0.2, 1000, 1.0);
    EXPECT_EQ(mill.signals.get("P00SEXCTH"), 0);
    mill.cut(6.0, 1000, 2.0);
    EXPECT_GT(mill.afc.feedReduction(), 20);
    EXPECT_EQ(mill.signals.get("P00SEXCTH"), 1);
    mill.cut(8.0, 1000, 0.7);  // lighter cut (42 % < 50 %): the reduction goes back
    EXPECT_LT(mill.afc.feedReduction(), 20);
    EXPECT_EQ(mill.signals.get("P00SEXCTH"), 0);
    mill.cut(6.0, 1000, 2.0);
    EXPECT_EQ(mill.signals.get("P00SEXCTH"), 1);
    mill.afc.switchOff();
    EXPECT_EQ(mill.signals.get("P00SEXCTH"), 1) << "G25 leaves it";
    mill.afc.programEnd();
    EXPECT_EQ(mill.signals.get("P00SEXCTH"), 0) << "reset at program end";
}

TEST(AfcSignals, ThrustMissingAtG25) {
    Mill mill(quiet());
    mill.afc.measureIdleTorque(1000, 0.5, 1.0);
    mill.afc.switchOn();
    mill.cut(1.0, 1000, 0.0);  // air cut: no machining torque
    EXPECT_EQ(mill.signals.get("P00STHMIS"), 0) << "only set when switching off";
    mill.afc.switchOff();
    EXPECT_EQ(mill.signals.get("P00STHMIS"), 1);
    mill.afc.switchOn();
    EXPECT_EQ(mill.signals.get("P00STHMIS"), 0) << "reset at G26";
    mill.cut(1.0, 1000, 0.5);
    mill.afc.switchOff();
    EXPECT_EQ(mill.signals.get("P00STHMIS"), 0) << "the minimum was exceeded";
    mill.setMd(9, 0);  // 009 = 0: not monitored
    mill.afc.switchOn();
    mill.cut(1.0, 1000, 0.0);
    mill.afc.switchOff();
    EXPECT_EQ(mill.signals.get("P00STHMIS"), 0) << "not updated with 009 = 0";
    mill.setMd(9, 10);
    mill.afc.switchOn();
    mill.cut(0.5, 1000, 0.0);
    mill.afc.switchOff();
    ASSERT_EQ(mill.signals.get("P00STHMIS"), 1);
    mill.afc.controlReset();
    EXPECT_EQ(mill.signals.get("P00STHMIS"), 0) << "reset at control reset";
}

TEST(AfcErrors, Error510NeedsClearError) {
    Mill mill(quiet());
    mill.afc.switchOn();
    mill.cut(0.5, 1000, 1.0);
    mill.afc.model().setConstantLoad(80);  // clamping not released: the load stays at 0 feed
    mill.cut(4.0, 1000, 1.0);
    ASSERT_TRUE(mill.afc.errorPending());
    EXPECT_NE(mill.afc.message().find("510"), std::string::npos);
    EXPECT_EQ(mill.cut(0.1, 1000, 0.0), 0) << "machining stops";
    const auto& t = mill.afc.trend();
    int zeroSamples = 0;
    for (const AfcSample& s : t)
        zeroSamples += s.feedReduction >= 100.0;
    EXPECT_EQ(zeroSamples, 10) << "20 ms of 2 ms cycles at 0 feed, then the error";
    mill.afc.controlReset();
    EXPECT_EQ(mill.md(1), 0);
    EXPECT_TRUE(mill.afc.errorPending()) << "control reset does not clear 510";
    EXPECT_EQ(mill.afc.switchOn(), AfcStatus::ErrorPending);
    mill.afc.clearError();
    EXPECT_EQ(mill.afc.switchOn(), AfcStatus::Ok);
}

TEST(AfcErrors, NoError510WhenMaximumReductionIs100) {
    Mill mill(quiet());
    mill.afc.switchOn();
    mill.setMd(13, 100);
    mill.afc.model().setConstantLoad(80);
    EXPECT_EQ(mill.cut(4.0, 1000, 1.0), 0);
    EXPECT_FALSE(mill.afc.errorPending());
    EXPECT_EQ(mill.afc.feedReduction(), 100);
}

TEST(AfcErrors, IdleTorqueMeasurement508And509) {
    Mill mill;
    EXPECT_EQ(mill.afc.measureIdleTorque(1000, 0.5, 0.15), AfcStatus::Error508)
        << "150 ms at constant speed < 200 ms";
    EXPECT_EQ(mill.afc.measureIdleTorque(1000, 0.5, 1.0, false), AfcStatus::Error508)
        << "override changed";
    EXPECT_EQ(mill.md(5), 0) << "nothing measured";
    ASSERT_EQ(mill.afc.measureIdleTorque(1000, 0.5, 0.25), AfcStatus::Ok);
    EXPECT_NEAR(mill.md(5), 8.0, 0.2) << "friction 6 % + 4 % * 0.5, noise averaged out";
    TorqueModelParameters stiff;
    stiff.frictionAtRest = 25;
    stiff.frictionAtMaxSpeed = 45;
    Mill jammed(stiff);
    EXPECT_EQ(jammed.afc.measureIdleTorque(1000, 0.5, 1.0), AfcStatus::Error509);
    EXPECT_NEAR(jammed.md(5), 35, 0.3) << "005 shows what was measured";
    EXPECT_NE(jammed.afc.message().find("509"), std::string::npos);
    jammed.afc.switchOn();  // page 30 takes the process parameters (006 = 30)
    jammed.setMd(6, 0);     // 0: idling torque not monitored
    EXPECT_EQ(jammed.afc.measureIdleTorque(1000, 0.5, 1.0), AfcStatus::Ok);
    jammed.setMd(4, 1000);  // measuring period 1 s from page 30
    EXPECT_EQ(jammed.afc.measureIdleTorque(1000, 0.5, 0.5), AfcStatus::Error508);
}

TEST(AfcStallTorque, RecordedAtRestAndUsedInTheMachiningTorque) {
    TorqueModelParameters inclined = quiet();
    inclined.stallTorque = -12.0;
    Mill mill(inclined);
    mill.setMd(2, 10);  // S1 from page 30 on
    ASSERT_EQ(mill.afc.recordStallTorque("S1", 300), AfcStatus::Ok);
    EXPECT_EQ(mill.afc.measuredStallTorque("S1"), -120) << "P-7-3652 in 0.1 %";
    EXPECT_EQ(mill.md(14), 12.0) << "014 is the absolute value";
    EXPECT_EQ(mill.afc.recordStallTorque("S1", 70000), AfcStatus::BadPeriod);
    ASSERT_EQ(mill.afc.recordStallTorque("X", 100, 500), AfcStatus::Ok);
    EXPECT_NE(mill.afc.measuredStallTorque("X"), -120) << "moving: friction in the result";
    EXPECT_EQ(mill.md(14), 12.0) << "X is not the reference axis";
    EXPECT_EQ(mill.afc.measuredStallTorque("Y"), 0) << "never recorded";
}

TEST(AfcRefusals, IncompatibleFunctionsAndMissingAxis) {
    Mill mill;
    for (int g : {74, 75, 33, 63, 64, 65, 77, 31, 32}) {
        EXPECT_EQ(mill.afc.switchOn({1, g}), AfcStatus::Incompatible) << g;
        EXPECT_FALSE(mill.afc.active());
    }
    EXPECT_NE(mill.afc.message().find("G32"), std::string::npos);
    ASSERT_EQ(mill.afc.switchOn({1, 17, 90}), AfcStatus::Ok);
    EXPECT_EQ(mill.afc.checkBlock({33}), AfcStatus::Incompatible);
    EXPECT_EQ(mill.afc.checkBlock({1, 90}), AfcStatus::Ok);
    mill.afc.switchOff();
    EXPECT_EQ(mill.afc.checkBlock({33}), AfcStatus::Ok) << "G25: no restriction";
    mill.setMd(2, 5);  // V: the mill has none
    EXPECT_EQ(mill.afc.switchOn(), AfcStatus::NoReferenceAxis);
    mill.setMd(2, 3);  // Z
    EXPECT_EQ(mill.afc.switchOn(), AfcStatus::Ok);
    MachineDataStore data(demoCell());
    AdaptiveFeedControl lathe(*demoCell().process(1), data);
    EXPECT_EQ(lathe.switchOn(), AfcStatus::NotAvailable);
    EXPECT_EQ(lathe.measureIdleTorque(1000, 0.5, 1.0), AfcStatus::NotAvailable);
    EXPECT_STREQ(afcStatusCode(AfcStatus::Error510), "AFC_ERROR_510");
}

TEST(AfcDeterminism, SameSeedSameRun) {
    Mill first, second;
    for (Mill* m : {&first, &second}) {
        m->afc.switchOn();
        m->cut(1.0, 1000, 1.3);
    }
    ASSERT_EQ(first.afc.trend().size(), second.afc.trend().size());
    for (std::size_t i = 0; i < first.afc.trend().size(); ++i)
        ASSERT_EQ(first.afc.trend()[i].torqueActual, second.afc.trend()[i].torqueActual);
    TorqueModelParameters other;
    other.seed = 7;
    Mill third(other);
    third.afc.switchOn();
    third.cut(1.0, 1000, 1.3);
    EXPECT_NE(third.afc.trend()[5].torqueActual, first.afc.trend()[5].torqueActual);
}

}  // namespace
