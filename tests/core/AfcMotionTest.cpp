// Adaptive feed control over whole moves (cnc_core/afc/AfcMotion): the cost
// of a move is bounded whatever its length and feed, the spans that stand
// for many cycles agree with the 2 ms controller, absurd durations stop with
// a diagnostic, the torque noise depends on the moment only.
#include <gtest/gtest.h>

#include <cmath>

#include "InterpTestSupport.h"
#include "cnc_core/afc/AdaptiveFeedControl.h"
#include "cnc_core/afc/AfcMotion.h"
#include "cnc_core/machine_data/MachineDataStore.h"

namespace {

using namespace mtc::core;
using namespace mtc::test;

/// The demo mill's adaptive feed control, switched on.
struct Control {
    explicit Control(TorqueModelParameters model = {})
        : data(demoCell()), afc(process(), data, model) {}
    static const ProcessConfig& process() { return *demoCell().process(0); }
    void setMd(int element, double value) {
        ASSERT_EQ(data.write({30, 0, 0, element}, value, MachineDataWriter::Nc),
                  MachineDataStatus::Ok);
    }
    AfcMoveResult cut(double length, double feed, double engagement = 1.0) {
        AfcMoveInput move;
        move.length = length;
        move.feed = feed;
        move.plannedSeconds = length / feed * 60.0;
        move.speedFraction = 0.5;
        move.engagement = engagement;
        return simulateAfcMove(afc, move, nullptr);
    }
    /// The same move with 2 ms cycles only (the reference).
    double cycleByCycleSeconds(double length, double feed, double engagement = 1.0) {
        double travelled = 0, seconds = 0;
        while (travelled < length) {
            travelled += afc.advance(0.002, feed, 0.5, engagement) / 60.0 * 0.002;
            seconds += 0.002;
        }
        return seconds;
    }
    MachineDataStore data;
    AdaptiveFeedControl afc;
};

TEST(AfcMotion, ALongSlowMoveCostsBoundedStepsAndStopsAfterAnHour) {
    // Regression: 800 mm at F1 (48000 s) ran 24 million 2 ms cycles.
    Control c;
    ASSERT_EQ(c.afc.switchOn(), AfcStatus::Ok);
    const AfcMoveResult r = c.cut(800.0, 1.0);
    EXPECT_LE(r.steps, kAfcMaxStepsPerMove);
    EXPECT_NEAR(r.seconds, kAfcMaxMoveSeconds, 1e-6);
    EXPECT_NEAR(r.fraction, 60.0 / 800.0, 1e-6);  // 3600 s at 1 mm/min
    std::string message;
    EXPECT_EQ(c.afc.takeRuntimeError(message), AfcStatus::MoveTooLong);
    EXPECT_NE(message.find("3600 s"), std::string::npos) << message;
    EXPECT_NEAR(c.afc.stopFraction(), 60.0 / 800.0, 1e-6);
}

TEST(AfcMotion, ALongHeavyCutAgreesWithTheCycleByCycleController) {
    // 5 m at F1500 with the default torque model: the controller settles
    // within seconds, the rest (minutes) is one span at the settled feed.
    TorqueModelParameters quiet;
    quiet.noiseAmplitude = 0.0;
    Control spans(quiet), cycles(quiet);
    ASSERT_EQ(spans.afc.switchOn(), AfcStatus::Ok);
    ASSERT_EQ(cycles.afc.switchOn(), AfcStatus::Ok);
    const AfcMoveResult r = spans.cut(5000.0, 1500.0);
    const double reference = cycles.cycleByCycleSeconds(5000.0, 1500.0);
    EXPECT_LT(r.steps, kAfcMaxStepsPerMove / 2) << "settled while reacting, then one span";
    EXPECT_GT(reference, 250.0);
    EXPECT_NEAR(r.seconds, reference, reference * 0.001);
    EXPECT_NEAR(spans.afc.feedReduction(), cycles.afc.feedReduction(), 0.05);
    EXPECT_DOUBLE_EQ(r.fraction, 1.0);
}

TEST(AfcMotion, ASlowControllerIsIntegratedInBoundedSpans) {
    // Amplification 0.05 1/s: the controller needs minutes; after 20 s of
    // cycles the rest is integrated in spans, and ends where the cycles end.
    TorqueModelParameters quiet;
    quiet.noiseAmplitude = 0.0;
    Control spans(quiet), cycles(quiet);
    for (Control* c : {&spans, &cycles}) {
        ASSERT_EQ(c->afc.switchOn(), AfcStatus::Ok);  // 002 = Bxx.063: the page rules
        c->setMd(3, 0.05);
    }
    const AfcMoveResult r = spans.cut(6000.0, 1500.0);  // about 5 minutes
    const double reference = cycles.cycleByCycleSeconds(6000.0, 1500.0);
    EXPECT_LE(r.steps, kAfcMaxStepsPerMove);
    EXPECT_NEAR(r.seconds, reference, reference * 0.01);
    EXPECT_NEAR(spans.afc.feedReduction(), cycles.afc.feedReduction(), 0.5);
}

TEST(AfcMotion, TheStandstillOf013At100PercentEndsAfterAMinuteInFewSteps) {
    TorqueModelParameters jammed;
    jammed.constantLoad = 200.0;
    Control c(jammed);
    ASSERT_EQ(c.afc.switchOn(), AfcStatus::Ok);  // 002 = Bxx.063: the page rules
    c.setMd(13, 100.0);
    const AfcMoveResult r = c.cut(100.0, 1000.0);
    std::string message;
    EXPECT_EQ(c.afc.takeRuntimeError(message), AfcStatus::FeedStopped);
    EXPECT_LE(r.steps, kAfcMaxStepsPerMove);
    EXPECT_GT(r.seconds, kAfcStandstillLimitSeconds);
    EXPECT_LT(r.fraction, 1.0);
}

TEST(AfcMotion, TheNoiseDependsOnTheMomentOnly) {
    const TorqueModel model;
    const double at = model.noise(12.345);
    for (int i = 0; i < 100; ++i)
        model.noise(i * 0.001);  // other samples in between change nothing
    EXPECT_EQ(model.noise(12.345), at);
    EXPECT_NE(model.noise(12.346), at);
    EXPECT_LE(std::fabs(at), model.parameters().noiseAmplitude);
    TorqueModelParameters other;
    other.seed = 7;
    EXPECT_NE(TorqueModel(other).noise(12.345), at);
    EXPECT_EQ(model.noise(std::nan("")), model.noise(0.0));
}

}  // namespace
