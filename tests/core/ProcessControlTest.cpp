#include <gtest/gtest.h>

#include <cmath>

#include "cnc_core/machine/MachineConfigReader.h"
#include "cnc_core/machine/ProcessControl.h"
#include "cnc_core/machine/SimulatedMachine.h"

using namespace mtc::core;

namespace {

/// Records what ProcessControl asks of its runner.
struct FakeRunner : ProgramRunner {
    std::string start(int number) override {
        started = number;
        return startAlarm;
    }
    std::string resume() override {
        ++resumed;
        return {};
    }
    void hold() override { ++held; }
    void reset() override { ++resets; }
    int started = 0, resumed = 0, held = 0, resets = 0;
    std::string startAlarm;
};

}  // namespace

TEST(ProcessControl, StartNeedsAutomaticModeAndAProgram) {
    ProcessControl control(0);
    FakeRunner runner;
    control.setRunner(&runner);
    EXPECT_FALSE(control.press(ControlKey::Start));
    EXPECT_NE(control.alarm().find("no program"), std::string::npos);
    ASSERT_TRUE(control.selectProgram(7));
    ASSERT_TRUE(control.press(ControlKey::Manual));
    EXPECT_FALSE(control.press(ControlKey::Start));
    EXPECT_NE(control.alarm().find("automatic"), std::string::npos);
    ASSERT_TRUE(control.press(ControlKey::Automatic));
    EXPECT_TRUE(control.press(ControlKey::Start));
    EXPECT_EQ(runner.started, 7);
    EXPECT_TRUE(control.programActive());
    EXPECT_TRUE(control.alarm().empty());
    EXPECT_EQ(control.signalTable().get("P00SACTIV"), 1);
}

TEST(ProcessControl, StopHoldsStartResumesResetAbandons) {
    ProcessControl control(1);
    FakeRunner runner;
    control.setRunner(&runner);
    control.selectProgram(1);
    ASSERT_TRUE(control.press(ControlKey::Start));
    control.press(ControlKey::Stop);
    EXPECT_EQ(runner.held, 1);
    EXPECT_TRUE(control.programHeld());
    EXPECT_EQ(control.signalTable().get("P01SHOLD"), 1);
    EXPECT_FALSE(control.selectProgram(2)) << "no program selection while active";
    EXPECT_FALSE(control.press(ControlKey::Manual)) << "no mode change while active";
    control.press(ControlKey::Start);
    EXPECT_EQ(runner.resumed, 1);
    EXPECT_EQ(runner.started, 1) << "resume, not a new start";
    EXPECT_FALSE(control.programHeld());
    control.press(ControlKey::ControlReset);
    EXPECT_EQ(runner.resets, 1);
    EXPECT_FALSE(control.programActive());
    EXPECT_TRUE(control.alarm().empty());
    EXPECT_EQ(control.signalTable().get("P01SACTIV"), 0);
}

TEST(ProcessControl, RefusedStartLeavesTheProgramInactive) {
    ProcessControl control(0);
    FakeRunner runner;
    runner.startAlarm = "program 3 has errors";
    control.setRunner(&runner);
    control.selectProgram(3);
    EXPECT_FALSE(control.press(ControlKey::Start));
    EXPECT_FALSE(control.programActive());
    EXPECT_EQ(control.alarm(), "program 3 has errors");
    EXPECT_EQ(control.signalTable().get("P00SACTIV"), 0);
}

TEST(ProcessControl, SignalLogKeepsOrderAndSkipsNonChanges) {
    ProcessControl control(0);
    EXPECT_TRUE(control.signalTable().log().empty()) << "power-on state is not a change";
    control.press(ControlKey::Automatic);
    EXPECT_TRUE(control.signalTable().log().empty());
    control.press(ControlKey::Manual);
    ASSERT_EQ(control.signalTable().log().size(), 2u);
    EXPECT_EQ(control.signalTable().log()[0].name, "P00SAUTO");
    EXPECT_EQ(control.signalTable().log()[1].name, "P00SMANU");
    EXPECT_LT(control.signalTable().log()[0].step, control.signalTable().log()[1].step);
}

TEST(SimulatedMachine, MotionTimes) {
    auto config = readMachineConfig(
        "[process 0]\nname = T\n[process 0 axis X]\ndefinition = X\nmax_velocity = 6000\n"
        "[process 0 axis Y]\ndefinition = Y\nmax_velocity = 3000\n");
    ASSERT_TRUE(config.ok());
    const ProcessConfig& process = config.config.processes[0];
    Motion m;
    m.axisCount = 2;
    m.type = MotionType::Linear;
    m.end = {30, 40};
    m.feed = 600;  // 50 mm at 600 mm/min = 5 s
    EXPECT_NEAR(motionSeconds(m, process), 5.0, 1e-9);
    m.type = MotionType::Rapid;  // X 30 mm at 6000 = 0.3 s, Y 40 mm at 3000 = 0.8 s
    EXPECT_NEAR(motionSeconds(m, process), 0.8, 1e-9);
    m.type = MotionType::ArcCCW;  // quarter circle R10 around (0,0) from (10,0) to (0,10)
    m.start = {10, 0};
    m.end = {0, 10};
    m.planeAxis1 = 0;
    m.planeAxis2 = 1;
    m.feed = 60 * 3.14159265358979323846 * 10 / 2;  // quarter length per second
    EXPECT_NEAR(motionSeconds(m, process), 1.0, 1e-9);
    m.type = MotionType::ArcCW;  // the other way round: three quarters
    EXPECT_NEAR(motionSeconds(m, process), 3.0, 1e-9);
    m.feed = 0;
    EXPECT_EQ(motionSeconds(m, process), 0.0);

    SimulatedMachine machine(process);
    m.type = MotionType::Linear;
    m.feed = 600;
    machine.motion(m);
    machine.dwell({}, 2.5);
    machine.dwell({}, -1);  // ignored
    EXPECT_EQ(machine.seconds(), 0.0);
    // The diagonal at 10 mm/s; the path acceleration is the axes' default
    // 2000 mm/s^2 over the largest tangent share (MOT-003).
    const double a = 2000.0 / std::sqrt(0.5);
    const double ramp = 10.0 / a;  // v / a: what a stop and start cost
    EXPECT_NEAR(machine.advance(1.0), 1.0, 1e-12);
    machine.hold();
    EXPECT_EQ(machine.advance(5.0), 5.0) << "held: the time passes, the axes brake and stand";
    EXPECT_NEAR(machine.seconds(), 1.0 + ramp, 1e-9) << "braking is busy time, standing not";
    machine.resume();
    const double busy = std::hypot(10, 10) / 10 + 2 * ramp + 2.5;
    EXPECT_NEAR(machine.advance(100.0), busy - 1.0 - ramp, 1e-9)
        << "returns when the queue is empty";
    EXPECT_TRUE(machine.idle());
    EXPECT_NEAR(machine.seconds(), busy, 1e-9) << "busy time only";
    EXPECT_EQ(machine.position(1), 10) << "reset keeps the position";
}
