// Interpreter API: validate-then-commit, stepping, restart hooks (start
// block, stop before the n-th arrival at a block, output suppression per
// aux type, observer, call stack), state snapshots, control reset, the
// services of the cell (events, machine data, other processes' variables).
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "InterpTestSupport.h"
#include "cnc_core/machine/MachineConfigReader.h"
#include "cnc_core/machine/InMemoryMachineData.h"

namespace {

using namespace mtc::core;
using namespace mtc::test;

struct RecordingObserver : AuxObserver {
    void auxiliary(const AuxOutput& output, bool forwarded) override {
        seen.push_back(std::string(1, output.type) +
                       std::to_string(static_cast<int>(output.value)) +
                       (forwarded ? "" : "(suppressed)"));
    }
    std::vector<std::string> seen;
};

double variable(const Station& s, int index) {
    return s.interpreter->state().variables.values[static_cast<size_t>(index)];
}

TEST(InterpCommit, RejectedBlockChangesNothing) {
    Station mill(demoCell(), 0);
    RunResult r = mill.run("N1 G0 X5 M3 @1=1\nN2 @1=7 @2=8 M4 M108 Q5 G1 G91 X9 A10\nN3 M30\n");
    ASSERT_EQ(r.status, RunStatus::Error);
    EXPECT_EQ(errorCodes(r.diagnostics), std::vector<std::string>{"AXIS_UNKNOWN"});
    const InterpreterState& s = mill.interpreter->state();
    EXPECT_EQ(variable(mill, 1), 1) << "assignment of the rejected block not committed";
    EXPECT_FALSE(s.variables.written.test(2));
    EXPECT_EQ(s.mGroups[2], 3);
    EXPECT_EQ(s.mGroups[5], -1);
    EXPECT_EQ(s.lastQ, -1);
    EXPECT_EQ(s.modal.g[kGroupInterpolation], 0);
    EXPECT_EQ(s.modal.g[kGroupDimension], 90);
    EXPECT_EQ(s.modal.machine[0], 5.0);
    EXPECT_EQ(s.block, 1u) << "the program pointer stays on the rejected block";
    EXPECT_EQ(mill.sink->text, "aux P1 N0001 L1 M3\nmotion P1 N0001 L1 rapid X=5.0000\n")
        << "aux functions leave before the move of their block";
}

TEST(InterpCommit, SwiftFunctionsLeaveLikeMAndQ) {
    Station mill(demoCell(), 0);
    const RunResult r = mill.run("N1 MQ3 QQ17 G0 X5\nN2 M0\n");
    ASSERT_EQ(r.status, RunStatus::Stopped) << r.diagnostics.size();
    EXPECT_EQ(mill.sink->text.substr(0, mill.sink->text.find("motion")),
              "aux P1 N0001 L1 M3\naux P1 N0001 L1 Q17\n");
    EXPECT_EQ(mill.interpreter->state().mGroups[2], 3);
    EXPECT_EQ(mill.interpreter->state().lastQ, 17);
}

TEST(InterpCommit, RejectedJumpChangesNothing) {
    Station mill(demoCell(), 0);
    RunResult r = mill.run("N1 @1=1\nN2 @1=2 M3 BSR .MISSING\n");
    EXPECT_EQ(errorCodes(r.diagnostics), std::vector<std::string>{"LABEL_NOT_FOUND"});
    EXPECT_EQ(variable(mill, 1), 1);
    EXPECT_EQ(mill.interpreter->state().mGroups[2], 5);
    EXPECT_TRUE(mill.interpreter->state().callStack.empty());
}

TEST(InterpStep, OneBlockAtATime) {
    Station mill(demoCell(), 0);
    mill.add("N1 @1=1\nN2 @1=2\nN3 M30\n", 1);
    ASSERT_TRUE(mill.interpreter->select(1));
    EXPECT_EQ(mill.interpreter->step().status, RunStatus::Running);
    EXPECT_EQ(variable(mill, 1), 1);
    EXPECT_EQ(mill.interpreter->step().status, RunStatus::Running);
    EXPECT_EQ(variable(mill, 1), 2);
    EXPECT_EQ(mill.interpreter->step().status, RunStatus::Ended);
}

TEST(InterpRestart, StartAtABlock) {
    Station mill(demoCell(), 0);
    mill.add("N1 @1=1\nN2 @2=1\nN3 @3=1\nN4 M30\n", 1);
    ASSERT_TRUE(mill.interpreter->select(1, 2));
    EXPECT_EQ(mill.interpreter->run().status, RunStatus::Ended);
    EXPECT_FALSE(mill.interpreter->state().variables.written.test(1));
    EXPECT_FALSE(mill.interpreter->state().variables.written.test(2));
    EXPECT_TRUE(mill.interpreter->state().variables.written.test(3));
    DiagnosticList d;
    EXPECT_FALSE(mill.interpreter->select(1, 99, &d));
    EXPECT_EQ(errorCodes(d), std::vector<std::string>{"BLOCK_RANGE"});
    EXPECT_FALSE(mill.interpreter->select(42, 0, &d));
    EXPECT_EQ(errorCodes(d).back(), "PROGRAM_NOT_FOUND");
}

TEST(InterpRestart, StopsBeforeTheTargetOnItsNthArrival) {
    Station mill(demoCell(), 0);
    mill.add("N1 @1=0\nN2 .LOOP @1=@1+1\nN3 @2=@1\nN4 @3=@1-5 BMI .LOOP\nN5 M30\n", 1);
    ASSERT_TRUE(mill.interpreter->select(1));
    mill.interpreter->setStopTarget(StopTarget{1, 2, 3});  // block N3, third time
    RunResult r = mill.interpreter->run();
    EXPECT_EQ(r.status, RunStatus::TargetReached);
    EXPECT_EQ(variable(mill, 1), 3);
    EXPECT_EQ(variable(mill, 2), 2) << "the target block itself is not interpreted";
    EXPECT_EQ(mill.interpreter->targetArrivals(), 3u);
    const auto stack = mill.interpreter->callStack();
    ASSERT_EQ(stack.size(), 1u);
    EXPECT_EQ(stack[0].block, "N0003");
    EXPECT_EQ(stack[0].line, 3);
    EXPECT_EQ(mill.interpreter->run().status, RunStatus::Ended) << "the target is used up";
}

TEST(InterpRestart, TargetInsideASubroutineShowsTheCallStack) {
    Station mill(demoCell(), 0);
    mill.add(".LIB @5=1\n@6=1\nRTS\n", 99);
    mill.add("N1 BSR .SUB\nN2 M30\nN3 .SUB @4=1\nN4 BSR .LIB\nN5 RTS\n", 1);
    ASSERT_TRUE(mill.interpreter->select(1));
    mill.interpreter->setStopTarget(StopTarget{99, 1, 1});
    EXPECT_EQ(mill.interpreter->run().status, RunStatus::TargetReached);
    const auto stack = mill.interpreter->callStack();
    ASSERT_EQ(stack.size(), 3u);
    EXPECT_EQ(stack[0].program, 1);
    EXPECT_EQ(stack[0].block, "N0001");
    EXPECT_EQ(stack[1].block, "N0004");
    EXPECT_EQ(stack[2].program, 99);
    EXPECT_EQ(stack[2].line, 2);
}

TEST(InterpRestart, OutputSuppressedPerTypeButCollected) {
    Station lathe(demoCell(), 1);
    RecordingObserver observer;
    lathe.interpreter->setObserver(&observer);
    OutputOptions& out = lathe.interpreter->options().output;
    out.m = false;
    out.s = false;
    out.motion = false;
    out.dwell = false;
    RunResult r = lathe.run("N1 T3 E2 S1500 M3 M8 M69 Q7\nN2 G1 X20 Z5 F100\nN3 G4 F1\nN4 M0\n");
    ASSERT_EQ(r.status, RunStatus::Stopped);
    EXPECT_EQ(lathe.sink->text, "aux P1 N0001 L1 T3\naux P1 N0001 L1 E2\naux P1 N0001 L1 Q7\n")
        << "only T, E and Q reach the sink";
    EXPECT_EQ(observer.seen, (std::vector<std::string>{"S1500(suppressed)", "T3", "E2",
                                                       "M3(suppressed)", "M8(suppressed)",
                                                       "M69(suppressed)", "Q7", "M0(suppressed)"}));
    const InterpreterState& s = lathe.interpreter->state();
    EXPECT_EQ(s.mGroups[2], 3);
    EXPECT_EQ(s.mGroups[5], 8);
    EXPECT_EQ(s.mGroups[16], 69);
    EXPECT_EQ(s.mGroups[1], 0);
    EXPECT_EQ(s.lastQ, 7);
    EXPECT_EQ(s.modal.machine[0], 20.0) << "positions are computed without motion output";
    EXPECT_DOUBLE_EQ(s.modal.time, 60.0 * std::sqrt(425.0) / 100.0 + 1.0);
}

TEST(InterpRestart, PublishesPage60) {
    Station lathe(demoCell(), 1);
    lathe.run("N1 T5 MTP\nN2 G0 C10\nN3 G20 Z0 C0 X0\nN4 G32 RI 20\nN5 M0\n");
    lathe.interpreter->publishPage60();
    double v = -1;
    MachineDataProvider& md = lathe.interpreter->machineData();
    ASSERT_EQ(md.read({60, 1, 0, 1}, v), MachineDataStatus::Ok);
    EXPECT_EQ(v, 1) << "S1 in rotary axis mode";
    ASSERT_EQ(md.read({60, 1, 0, 4}, v), MachineDataStatus::Ok);
    EXPECT_EQ(v, 32);
    ASSERT_EQ(md.read({60, 1, 0, 5}, v), MachineDataStatus::Ok);
    EXPECT_EQ(v, 5) << "turret: MTP activates the tool in tool spindle 1";
}

TEST(InterpState, SnapshotAndRestoreRepeatTheRun) {
    Station mill(demoCell(), 0);
    mill.add("N1 G0 X1\nN2 M0\nN3 G1 X10 Y5 F200 M8\nN4 @1=@1+1 M30\n", 1);
    ASSERT_TRUE(mill.interpreter->select(1));
    ASSERT_EQ(mill.interpreter->run().status, RunStatus::Stopped);
    const InterpreterState snapshot = mill.interpreter->state();
    mill.sink->text.clear();
    mill.interpreter->run();
    const std::string first = mill.sink->text;
    mill.interpreter->restoreState(snapshot);
    mill.sink->text.clear();
    mill.interpreter->run();
    EXPECT_EQ(mill.sink->text, first);
    EXPECT_EQ(variable(mill, 1), 1) << "the variables came back with the snapshot";
}

TEST(InterpState, ControlResetEndsEverything) {
    Station mill(demoCell(), 0);
    mill.add("N1 BSR .S\nN2 M30\nN3 .S M3 M108 Q4 G91 G19\nN4 M0\nN5 RTS\n", 1);
    ASSERT_TRUE(mill.interpreter->select(1));
    ASSERT_EQ(mill.interpreter->run().status, RunStatus::Stopped);
    EXPECT_EQ(mill.interpreter->state().callStack.size(), 1u);
    mill.interpreter->controlReset();
    const InterpreterState& s = mill.interpreter->state();
    EXPECT_TRUE(s.callStack.empty());
    EXPECT_EQ(s.block, 0u);
    EXPECT_EQ(s.mGroups[2], 5) << "spindle group back to its reset value";
    EXPECT_EQ(s.mGroups[5], -1);
    EXPECT_EQ(s.lastQ, -1);
    EXPECT_EQ(s.modal.g[kGroupDimension], 90);
    EXPECT_EQ(s.modal.g[kGroupPlane], 17);
}

TEST(InterpEnd, ProgramWithoutEndAndSubroutineWithoutRts) {
    Station mill(demoCell(), 0);
    RunResult r = mill.run("N1 @1=1\n");
    EXPECT_EQ(r.status, RunStatus::Ended);
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics.items()[0].code, "PROGRAM_END_MISSING");
    r = mill.run("N1 JSR 3\nN2 M30\n", 2);
    mill.add("N1 @1=2\n", 3);
    r = mill.run("N1 JSR 3\nN2 M30\n", 2);
    EXPECT_EQ(errorCodes(r.diagnostics), std::vector<std::string>{"SUBROUTINE_WITHOUT_RTS"});
}

TEST(InterpEnd, OptionalStop) {
    Station mill(demoCell(), 0);
    EXPECT_EQ(mill.run("N1 M1\nN2 M30\n").status, RunStatus::Ended);
    mill.interpreter->options().optionalStop = true;
    EXPECT_EQ(mill.run("N1 M1\nN2 M30\n").status, RunStatus::Stopped);
}

TEST(InterpServices, EventsAreSharedByTheProcessesOfACell) {
    auto events = std::make_shared<EventTable>();
    const MachineConfig& cell = demoCell();
    ProgramStore store;
    NullSink sink;
    store.put(0, 1, parse("N1 .WAIT BER .WAIT 1:15\nN2 @1=1 M30\n", 1));
    InterpreterServices services;
    services.events = events;
    Interpreter mill(*cell.process(0), store, sink, services);
    ASSERT_TRUE(mill.select(1));
    EXPECT_EQ(mill.run(50).status, RunStatus::BudgetExceeded) << "waits for the event";
    Interpreter lathe(*cell.process(1), store, sink, services);
    lathe.events().set(1, 15, true);  // e.g. the lathe's SPS sets it
    EXPECT_EQ(mill.run(50).status, RunStatus::Ended);
    EXPECT_EQ(mill.state().variables.values[1], 1);
}

struct CellVariables : VariableAccess {
    bool read(int process, int index, double& value) const override {
        if (process != 1) return false;
        auto it = values.find(index);
        value = it == values.end() ? 0.0 : it->second;
        return true;
    }
    bool write(int process, int index, double value) override {
        if (process != 1) return false;
        values[index] = value;
        return true;
    }
    std::map<int, double> values;
};

TEST(InterpServices, VariablesOfOtherProcesses) {
    CellVariables cellVariables;
    cellVariables.values[20] = 4;
    ProgramStore store;
    NullSink sink;
    InterpreterServices services;
    services.otherProcesses = &cellVariables;
    Interpreter mill(*demoCell().process(0), store, sink, services);
    store.put(0, 1, parse("N1 @1=@1:20*2 @1:21=@1+1 @0:2=5\nN2 @3=@2:1\nN3 M30\n", 1));
    ASSERT_TRUE(mill.select(1));
    RunResult r = mill.run();
    EXPECT_EQ(errorCodes(r.diagnostics), std::vector<std::string>{"VARIABLE_PROCESS"});
    EXPECT_EQ(mill.state().variables.values[1], 8);
    EXPECT_EQ(mill.state().variables.values[2], 5) << "@0:2 is the own process";
    EXPECT_EQ(cellVariables.values[21], 9);
}

TEST(InterpServices, SharedMachineDataBetweenInterpreters) {
    auto data = std::make_shared<InMemoryMachineData>(demoCell());
    ProgramStore store;
    NullSink sink;
    InterpreterServices services;
    services.machineData = data;
    Interpreter lathe(*demoCell().process(1), store, sink, services);
    Interpreter mill(*demoCell().process(0), store, sink, services);
    store.put(1, 1, parse("N1 MTD(180,,,2)=123.5\nN2 M30\n", 1));
    store.put(0, 1, parse("N1 @1=MTD(180,1,0,2)\nN2 M30\n", 1));
    ASSERT_TRUE(lathe.select(1));
    ASSERT_TRUE(mill.select(1));
    lathe.run();
    mill.run();
    EXPECT_EQ(mill.state().variables.values[1], 123.5);
}

TEST(InterpConfig, BadConfigurationIsReportedAndNothingRuns) {
    const MachineConfigReadResult read = readMachineConfig(R"([cell]
name = bad
[process 0]
name = bad
B004 = 17
[process 0 axis X]
definition = X
[process 0 axis Q]
definition = X
[process 0 zero-offsets]
G54 = R5
)");
    // The reader refuses the file with the lines (issue 22 §2) ...
    EXPECT_EQ(errorCodes(read.diagnostics),
              (std::vector<std::string>{"CFG_ZERO_OFFSET", "CFG_AXIS_NAME", "CFG_AXIS_DUPLICATE"}));
    std::vector<int> lines;
    for (const Diagnostic& d : read.diagnostics.items())
        lines.push_back(d.where.line);
    EXPECT_EQ(lines, (std::vector<int>{11, 8, 8}));
    // ... and the interpreter still refuses such a cell built in code.
    ProcessConfig process = *read.config.process(0);
    ZeroOffset bad;
    bad.code = "G54";
    bad.values["R"] = 5;
    process.zeroOffsets.push_back(bad);
    ProgramStore store;
    NullSink sink;
    Interpreter interp(process, store, sink);
    EXPECT_EQ(errorCodes(interp.configurationDiagnostics()),
              (std::vector<std::string>{"CFG_AXIS_NAME", "CFG_AXIS_DUPLICATE", "CFG_ZERO_OFFSET"}));
    store.put(0, 1, parse("N1 M30\n", 1));
    ASSERT_TRUE(interp.select(1));
    RunResult r = interp.run();
    EXPECT_EQ(r.status, RunStatus::Error);
    EXPECT_FALSE(r.diagnostics.empty());
}

TEST(InterpZeroOffsets, TableColumnsFollowTheAxisDefinition) {
    Station lathe(demoCell(), 1);
    // Demo lathe: G54 = X0 Z255.5. After G20 Z0 C0 X0 the X axis has
    // definition Z and uses the Z column; the Z axis uses the X column.
    lathe.run("N1 G54 G0 X10 Z10\nN2 G20 Z0 C0 X0\nN3 G0 X-240 Z10\nN4 M0\n");
    const ModalState& m = lathe.interpreter->state().modal;
    EXPECT_DOUBLE_EQ(m.machine[0], 15.5);
    EXPECT_DOUBLE_EQ(m.machine[1], 10.0);
}

}  // namespace
