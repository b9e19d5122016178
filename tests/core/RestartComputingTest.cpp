// The computing process of NC program restart (seed 000, 2.6, 2.7, 3.1, 4,
// 5.2, 5.4): runs with nested loops and subroutines, call chains, primary
// blocks, the page 61 buffers, page 60, aux output per process parameter,
// the special rules for G4/G74/G75, commands and tools, and its failures.
#include <gtest/gtest.h>

#include <thread>

#include "RestartTestSupport.h"

namespace {

using namespace mtc::core;
using namespace mtc::test;

/// Runs a computing process for `selection` to its end; returns it.
std::unique_ptr<ComputingProcess> compute(RestartCell& cell, const RestartSelection& selection,
                                          DiagnosticList* failure = nullptr,
                                          std::uint64_t budget = kDefaultBlockBudget) {
    auto process =
        std::make_unique<ComputingProcess>(cell.config, cell.store, cell.sps, cell.services());
    DiagnosticList d;
    const bool begun = process->begin(selection, cell.live.state(), cell.live.options(), budget, d);
    if (failure) *failure = d;
    if (!begun) return process;
    while (process->runToEnd().status == ComputingStatus::Stopped) {
    }
    return process;
}

double var(const ComputingProcess& c, int n) {
    return c.state().variables.values[static_cast<std::size_t>(n)];
}

const char* kNestedLoops =
    "N0001 @1=0 @2=0\n"
    "N0002 .OUTER @1=@1+1 @3=0\n"
    "N0003 .INNER @3=@3+1\n"
    "N0004 @2=@2+1 ;counts the passes\n"
    "N0005 @4=@3-3 BMI .INNER\n"
    "N0006 @4=@1-4 BMI .OUTER\n"
    "N0007 M30\n";

TEST(RestartComputing, NestedLoopsStopBeforeTheNthArrival) {
    RestartCell mill(0);
    mill.add(kNestedLoops, 1);
    auto c = compute(mill, mill.selection(1, 1, 4, 7));
    ASSERT_EQ(c->progress().status, ComputingStatus::TargetReached)
        << diagnosticsText(c->diagnostics());
    EXPECT_EQ(c->progress().arrivals, 7u);
    EXPECT_EQ(var(*c, 1), 3) << "7th pass = outer loop 3, inner loop 1";
    EXPECT_EQ(var(*c, 3), 1);
    EXPECT_EQ(var(*c, 2), 6) << "the target block itself is not interpreted";
    EXPECT_EQ(c->state().block, mill.block(1, 4));
}

TEST(RestartComputing, MoreRunsThanPassesIsTargetNotFound) {
    RestartCell mill(0);
    mill.add(kNestedLoops, 1);
    auto c = compute(mill, mill.selection(1, 1, 4, 13));
    ASSERT_EQ(c->progress().status, ComputingStatus::Failed);
    EXPECT_EQ(errorCodes(c->diagnostics()), std::vector<std::string>{"RESTART_TARGET_NOT_FOUND"});
    EXPECT_EQ(c->diagnostics().items().back().where.block, "N0004");
    EXPECT_EQ(c->progress().arrivals, 12u);
}

TEST(RestartComputing, ProgramEndsBeforeTheTarget) {
    for (const char* end : {"M30", "M02", "BST", "RET"}) {
        RestartCell mill(0);
        mill.add(std::string("N0001 @1=1\nN0002 ") + end + "\nN0003 @2=1\nN0004 M30\n", 1);
        auto c = compute(mill, mill.selection(1, 1, 3));
        EXPECT_EQ(c->progress().status, ComputingStatus::Failed) << end;
        EXPECT_EQ(errorCodes(c->diagnostics()),
                  std::vector<std::string>{"RESTART_TARGET_NOT_FOUND"})
            << end;
    }
}

const char* kLibrary = "N0000 M30\nN0001 .TAP @11=@10\nN0002 @12=@10*10\nN0003 RTS\n";
const char* kTwoCalls = "N0001 @10=1 BSR .TAP\nN0002 @10=2 BSR .TAP\nN0003 M30\n";

TEST(RestartComputing, TargetInProgram99CountsOnlyTheSelectedCall) {
    RestartCell mill(0);
    mill.add(kLibrary, 99);
    mill.add(kTwoCalls, 1);
    RestartSelection s = mill.selection(1, 99, 2);
    s.path = {mill.ref(1, 2)};  // through the second call
    auto c = compute(mill, s);
    ASSERT_EQ(c->progress().status, ComputingStatus::TargetReached)
        << diagnosticsText(c->diagnostics());
    EXPECT_EQ(var(*c, 11), 2) << "the arrival through N0001 does not count";
    ASSERT_EQ(c->state().callStack.size(), 1u);
    EXPECT_EQ(c->state().callStack[0].callBlock, mill.block(1, 2));
    s.path = {mill.ref(1, 1)};
    auto first = compute(mill, s);
    EXPECT_EQ(var(*first, 11), 1);
}

TEST(RestartComputing, TargetInAnotherProgramNeedsThePath) {
    RestartCell mill(0);
    mill.add(kLibrary, 99);
    mill.add(kTwoCalls, 1);
    DiagnosticList d;
    auto c = compute(mill, mill.selection(1, 99, 2), &d);
    EXPECT_EQ(c->progress().status, ComputingStatus::Idle);
    EXPECT_EQ(errorCodes(d), std::vector<std::string>{"RESTART_PATH_INCONSISTENT"});
}

TEST(RestartComputing, JsrByVariableTakesTheOperatorsValue) {
    RestartCell mill(0);
    mill.add("N0000 @21=5\nN0001 @22=1\nN0002 RTS\n", 5);
    mill.add("N0001 @9=1\nN0002 JSR @20\nN0003 M30\n", 1);
    RestartSelection s = mill.selection(1, 5, 1);
    s.path = {mill.ref(1, 2)};
    DiagnosticList d;
    auto without = compute(mill, s, &d);
    EXPECT_EQ(without->progress().status, ComputingStatus::Failed)
        << "@20 = 0: program 0 does not exist";
    EXPECT_EQ(errorCodes(without->diagnostics()), std::vector<std::string>{"PROGRAM_NOT_FOUND"});
    s.variableChanges[20] = 5;
    auto with = compute(mill, s);
    ASSERT_EQ(with->progress().status, ComputingStatus::TargetReached)
        << diagnosticsText(with->diagnostics());
    EXPECT_EQ(var(*with, 21), 5);
    EXPECT_EQ(var(*with, 20), 5);
    EXPECT_FALSE(with->state().variables.written.test(22));
}

TEST(RestartComputing, EventChangesAreAppliedBeforeTheStart) {
    RestartCell mill(0);
    mill.add("N0001 BEV .SUB 0:7\nN0002 M30\nN0003 .SUB @1=1\nN0004 @2=1\nN0005 RTS\n", 1);
    RestartSelection s = mill.selection(1, 1, 4);
    s.path = {mill.ref(1, 1)};
    auto notSet = compute(mill, s);
    EXPECT_EQ(notSet->progress().status, ComputingStatus::Failed);
    s.eventChanges[{0, 7}] = true;
    auto set = compute(mill, s);
    EXPECT_EQ(set->progress().status, ComputingStatus::TargetReached);
    EXPECT_TRUE(mill.events->get(0, 7)) << "the cell's event table was changed";
}

const char* kPrimary =
    "N0001 @1=1\n"
    "N0002 : @2=1\n"
    "N0003 @3=1\n"
    "N0004 BSR .SUB\n"
    "N0005 M30\n"
    "N0006 .SUB @5=1\n"
    "N0007 : @6=1\n"
    "N0008 @7=1\n"
    "N0009 RTS\n";

TEST(RestartComputing, StartAtTheLastPrimaryBlockInsideTheSubroutine) {
    RestartCell mill(0);
    mill.add(kPrimary, 1);
    RestartSelection s = mill.selection(1, 1, 8);
    s.path = {mill.ref(1, 4)};
    s.fromLastPrimary = true;
    auto c = compute(mill, s);
    ASSERT_EQ(c->progress().status, ComputingStatus::TargetReached);
    EXPECT_TRUE(c->route().primary);
    EXPECT_EQ(c->route().startBlock, mill.block(1, 7));
    EXPECT_EQ(c->progress().blocksInterpreted, 1u);
    for (int n : {1, 2, 3, 5})
        EXPECT_FALSE(c->state().variables.written.test(n)) << n;
    EXPECT_TRUE(c->state().variables.written.test(6));
    ASSERT_EQ(c->state().callStack.size(), 1u) << "the call frame of N0004 was rebuilt";
    EXPECT_EQ(c->state().callStack[0].returnBlock, mill.block(1, 5));
}

TEST(RestartComputing, PrimaryBlockSearchLeavesTheSubroutineThroughItsCall) {
    RestartCell mill(0);
    mill.add(
        "N0001 @1=1\nN0002 : @2=1\nN0003 @3=1\nN0004 BSR .SUB\nN0005 M30\n"
        "N0006 .SUB @5=1\nN0007 @6=1\nN0008 RTS\n",
        1);
    RestartSelection s = mill.selection(1, 1, 7);
    s.path = {mill.ref(1, 4)};
    s.fromLastPrimary = true;
    auto c = compute(mill, s);
    ASSERT_EQ(c->progress().status, ComputingStatus::TargetReached);
    EXPECT_EQ(c->route().startBlock, mill.block(1, 2));
    EXPECT_TRUE(c->route().startFrames.empty());
    EXPECT_FALSE(c->state().variables.written.test(1));
    EXPECT_TRUE(c->state().variables.written.test(5));
}

TEST(RestartComputing, NoPrimaryBlockStartsAtTheProgramStartWithAWarning) {
    RestartCell mill(0);
    mill.add("N0001 @1=1\nN0002 @2=1\nN0003 M30\n", 1);
    RestartSelection s = mill.selection(1, 1, 2);
    s.fromLastPrimary = true;
    DiagnosticList d;
    auto c = compute(mill, s, &d);
    ASSERT_EQ(c->progress().status, ComputingStatus::TargetReached);
    EXPECT_FALSE(c->route().primary);
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d.items()[0].code, "RESTART_NO_PRIMARY_BLOCK");
    EXPECT_TRUE(c->state().variables.written.test(1));
}

TEST(RestartComputing, BuffersKeepTheLast40AndSkipM19) {
    RestartCell mill(0);
    mill.add(
        "N0001 @1=0\n"
        "N0002 .LOOP @1=@1+1\n"
        "N0003 M=500+@1 Q=200+@1 M119\n"
        "N0004 M19 M319\n"
        "N0005 @2=@1-45 BMI .LOOP\n"
        "N0006 @3=1\n"
        "N0007 M30\n",
        1);
    mill.machineData->write({61, 0, 1, 3}, 77, MachineDataWriter::Nc);
    ComputingProcess c(mill.config, mill.store, mill.sps, mill.services());
    DiagnosticList d;
    ASSERT_TRUE(c.begin(mill.selection(1, 1, 6), mill.live.state(), {}, 1000, d));
    EXPECT_EQ(mill.page(61, 1, 3), 0) << "zeroed at the start";
    while (c.advance(1000).status == ComputingStatus::Running) {
    }
    ASSERT_EQ(c.progress().status, ComputingStatus::TargetReached);
    EXPECT_EQ(c.collector().m16().size(), 40);
    for (int element = 1; element <= 40; ++element) {
        EXPECT_EQ(mill.page(61, 1, element), 505 + element) << element;
        EXPECT_EQ(mill.page(61, 2, element), 205 + element) << element;
    }
    EXPECT_EQ(c.state().mGroups[16], 319) << "M(16) reads the last output (M319 has no S3 here)";
    EXPECT_EQ(c.state().mGroups[2], 19);
}

TEST(RestartComputing, SwiftFunctionsAreCollectedLikeTheirPlainForms) {
    RestartCell mill(0);  // MQ / QQ are M / Q output without waiting (decision LA-013)
    mill.add("N0001 MQ108 QQ31\nN0002 MQ512 M19\nN0003 @1=1\nN0004 M30\n", 1);
    auto c = compute(mill, mill.selection(1, 1, 3));
    ASSERT_EQ(c->progress().status, ComputingStatus::TargetReached);
    EXPECT_EQ(c->state().mGroups[5], 108) << "MQ108 sets its M group";
    ASSERT_EQ(c->collector().m16().size(), 1u);
    EXPECT_EQ(mill.page(61, 1, 1), 512) << "MQ512 is kept in the M(16) buffer";
    EXPECT_EQ(mill.page(61, 2, 1), 31) << "QQ31 is kept in the Q buffer";
}

TEST(RestartComputing, AuxOutputFollowsBxx058To061) {
    RestartCell mill(0);  // Bxx.058..061 = No
    mill.add("N0001 T3 S1200 M3 M108 Q7\nN0002 @1=1\nN0003 M30\n", 1);
    auto c = compute(mill, mill.selection(1, 1, 2));
    ASSERT_EQ(c->progress().status, ComputingStatus::TargetReached);
    EXPECT_TRUE(mill.sps.aux.empty());
    EXPECT_EQ(c->state().mGroups[2], 3) << "collected although not output";
    EXPECT_EQ(c->state().mGroups[5], 108);
    EXPECT_EQ(c->state().modal.spindleSpeed[1], 1200);
    EXPECT_EQ(c->state().modal.tool, 3);
    EXPECT_EQ(c->collector().forwarded(), 0u);

    RestartCell lathe(1);  // Bxx.058 = Yes: M functions reach the SPS
    lathe.add("N0001 T3 S1200 M3 M8 Q7\nN0002 @1=1\nN0003 M30\n", 1);
    auto l = compute(lathe, lathe.selection(1, 1, 2));
    ASSERT_EQ(l->progress().status, ComputingStatus::TargetReached);
    ASSERT_EQ(lathe.sps.aux.size(), 2u);
    EXPECT_EQ(lathe.sps.aux[0].type, 'M');
    EXPECT_EQ(lathe.sps.aux[0].value, 3);
    EXPECT_EQ(lathe.sps.aux[1].value, 8);
}

TEST(RestartComputing, DwellHomingHardStopProduceNoMotion) {
    RestartCell mill(0);
    mill.add(
        "N0001 G0 G54 X10 Y10 Z10\nN0002 G4 F30\nN0003 G74 Z0\nN0004 G75 X40 F100\n"
        "N0005 @1=1\nN0006 M30\n",
        1);
    auto c = compute(mill, mill.selection(1, 1, 5));
    ASSERT_EQ(c->progress().status, ComputingStatus::TargetReached);
    EXPECT_TRUE(mill.sps.motions.empty());
    EXPECT_TRUE(mill.sps.dwells.empty());
    EXPECT_EQ(c->state().modal.machine[2], 0.0) << "the commanded position follows G74";
    EXPECT_EQ(c->state().modal.machine[0], -110.0) << "and G75 (X40 + G54 X-150)";
}

TEST(RestartComputing, ToolStorageAndPositionCommandsAreNotPerformed) {
    RestartCell mill(0);
    mill.add(
        "N0001 T5 MTP MRY\nN0002 TCH(1, 2) PMP NMP\nN0003 T7 TMS(1, 3) TSE TPE\n"
        "N0004 MFP MHP MMP MOP\nN0005 MRF TSM(1, 2)\n"
        "N0006 GAX(X1) FAX(X1) AXD (X:S-0-0104)=7000\nN0007 DP 1 WES 1:5 POK\n"
        "N0008 @1=1\nN0009 M30\n",
        1);
    auto c = compute(mill, mill.selection(1, 1, 8));
    ASSERT_EQ(c->progress().status, ComputingStatus::TargetReached)
        << diagnosticsText(c->diagnostics());
    std::vector<std::string> passed;
    for (const auto& command : mill.sps.commands)
        passed.emplace_back(keywordName(command.keyword));
    EXPECT_EQ(passed, (std::vector<std::string>{"GAX", "FAX", "AXD", "DP", "WES", "POK"}));
    EXPECT_EQ(c->filter().suppressedCount(), 14u);
    const auto& spindles = c->state().modal.toolSpindle;
    EXPECT_EQ(spindles[1], 0) << "TSM emptied spindle 2 again";
    EXPECT_EQ(spindles[2], 7) << "TMS remembered T7 for spindle 3";
    EXPECT_EQ(mill.page(60, 0, 7), 7) << "page 60 element 7 = tool spindle 3";
}

TEST(RestartComputing, UnknownToolIsAnError) {
    RestartCell mill(0);
    mill.add("N0001 T99\nN0002 @1=1\nN0003 M30\n", 1);
    auto c = compute(mill, mill.selection(1, 1, 2));
    EXPECT_EQ(c->progress().status, ComputingStatus::Failed);
    EXPECT_EQ(errorCodes(c->diagnostics()), std::vector<std::string>{"TOOL_UNKNOWN"});
}

TEST(RestartComputing, Page60AtTheTarget) {
    RestartCell lathe(1);
    lathe.add(
        "N0001 T9 MTP\nN0002 G0 C0\nN0003 G20 Z0 C0 X0\nN0004 G32 RI 36.5\n"
        "N0005 G1 Y1 10 F200\nN0006 G30\nN0007 M30\n",
        1);
    auto c = compute(lathe, lathe.selection(1, 1, 6));
    ASSERT_EQ(c->progress().status, ComputingStatus::TargetReached)
        << diagnosticsText(c->diagnostics());
    EXPECT_EQ(lathe.page(60, 0, 1), 1) << "S1 in rotary axis mode";
    EXPECT_EQ(lathe.page(60, 0, 4), 32);
    EXPECT_EQ(lathe.page(60, 0, 5), 9) << "turret: MTP puts T9 into tool spindle 1";
    EXPECT_TRUE(lathe.sps.commands.empty()) << "MTP is not performed";
}

TEST(RestartComputing, ProgrammedStopHoldsAndPublishesTheRotaryAxisModes) {
    RestartCell lathe(1);
    lathe.add("N0001 G0 C10\nN0002 M0\nN0003 @1=1\nN0004 M30\n", 1);
    ComputingProcess c(lathe.config, lathe.store, lathe.sps, lathe.services());
    DiagnosticList d;
    ASSERT_TRUE(c.begin(lathe.selection(1, 1, 3), lathe.live.state(), {}, 100, d));
    EXPECT_EQ(c.advance(100).status, ComputingStatus::Stopped);
    EXPECT_EQ(lathe.page(60, 0, 1), 1) << "updated at a program stop";
    EXPECT_EQ(lathe.page(60, 0, 4), 30) << "transformation only at the target";
    EXPECT_EQ(c.advance(100).status, ComputingStatus::TargetReached);
}

TEST(RestartComputing, SlicesReportProgressAndTheBudgetEndsAnEndlessLoop) {
    RestartCell mill(0);
    mill.add("N0001 .L @1=@1+1\nN0002 BRA .L\nN0003 @2=1\n", 1);
    ComputingProcess c(mill.config, mill.store, mill.sps, mill.services());
    DiagnosticList d;
    ASSERT_TRUE(c.begin(mill.selection(1, 1, 3), mill.live.state(), {}, 10'000, d));
    EXPECT_EQ(c.advance(1000).status, ComputingStatus::Running);
    EXPECT_EQ(c.progress().blocksInterpreted, 1000u);
    EXPECT_EQ(c.blocksSoFar(), 1000u);
    EXPECT_EQ(c.advance(1'000'000).status, ComputingStatus::Failed);
    EXPECT_EQ(c.progress().blocksInterpreted, 10'000u);
    EXPECT_EQ(errorCodes(c.diagnostics()), std::vector<std::string>{"BLOCK_BUDGET"});
}

TEST(RestartComputing, AbortFromAnotherThread) {
    RestartCell mill(0);
    mill.add("N0001 .L @1=@1+1\nN0002 BRA .L\nN0003 @2=1\n", 1);
    ComputingProcess c(mill.config, mill.store, mill.sps, mill.services());
    DiagnosticList d;
    ASSERT_TRUE(c.begin(mill.selection(1, 1, 3), mill.live.state(), {}, ~0ull, d));
    std::thread stopper([&] {
        while (c.blocksSoFar() < 200'000)
            std::this_thread::yield();
        c.requestAbort();
    });
    const ComputingProgress p = c.advance(~0ull);
    stopper.join();
    EXPECT_EQ(p.status, ComputingStatus::Aborted);
    EXPECT_GE(p.blocksInterpreted, 200'000u);
    EXPECT_EQ(c.advance(10).status, ComputingStatus::Aborted) << "stays aborted";
}

TEST(RestartComputing, BadSelectionsAreRefused) {
    RestartCell mill(0);
    mill.add("N0001 @1=1\nN0002 BSR .S\nN0003 M30\nN0004 .S RTS\n", 1);
    auto refused = [&](RestartSelection s) {
        ComputingProcess c(mill.config, mill.store, mill.sps, mill.services());
        DiagnosticList d;
        EXPECT_FALSE(c.begin(s, mill.live.state(), {}, 100, d));
        EXPECT_EQ(c.progress().status, ComputingStatus::Idle);
        return errorCodes(d);
    };
    RestartSelection s = mill.selection(1, 1, 2);
    s.runs = 0;
    EXPECT_EQ(refused(s), std::vector<std::string>{"RESTART_RUNS_RANGE"});
    s.runs = 65537;
    EXPECT_EQ(refused(s), std::vector<std::string>{"RESTART_RUNS_RANGE"});
    s = mill.selection(1, 1, 2);
    s.mainProgram = 4;
    EXPECT_EQ(refused(s), std::vector<std::string>{"RESTART_PROGRAM_NOT_FOUND"});
    s = mill.selection(1, 1, 2);
    s.target.block = 40;
    EXPECT_EQ(refused(s), std::vector<std::string>{"RESTART_BLOCK_RANGE"});
    s = mill.selection(1, 1, 4);
    s.path = {mill.ref(1, 1)};
    EXPECT_EQ(refused(s), std::vector<std::string>{"RESTART_PATH_NOT_A_CALL"});
    s.path = {mill.ref(1, 4)};
    EXPECT_EQ(refused(s), std::vector<std::string>{"RESTART_PATH_NOT_A_CALL"}) << "RTS";
    s = mill.selection(1, 1, 2);
    s.variableChanges[1000] = 1;
    EXPECT_EQ(refused(s), std::vector<std::string>{"RESTART_VARIABLE_RANGE"});
    s = mill.selection(1, 1, 2);
    s.eventChanges[{9, 1}] = true;
    EXPECT_EQ(refused(s), std::vector<std::string>{"RESTART_EVENT_INVALID"});
}

TEST(RestartComputing, TargetInACycleIsRefused) {
    RestartCell mill(0);
    mill.add("N0001 BSR .*CYC\nN0002 M30\n", 1);
    auto cycle = parse("%MAC\nN0000 .*CYC @1=1\nN0001 RTS\n", 0);
    auto mutableCycle = std::make_shared<Program>(*cycle);
    mutableCycle->isCycle = true;
    mutableCycle->number = 7;
    mill.store.put(0, 7, mutableCycle);
    RestartSelection s = mill.selection(1, 1, 1);
    s.target = {7, 1};
    s.path = {mill.ref(1, 1)};
    ComputingProcess c(mill.config, mill.store, mill.sps, mill.services());
    DiagnosticList d;
    EXPECT_FALSE(c.begin(s, mill.live.state(), {}, 100, d));
    EXPECT_EQ(errorCodes(d), std::vector<std::string>{"RESTART_IN_CYCLE"});
}

TEST(RestartComputing, DeepestLevelIsTheTenth) {
    RestartCell mill(0);
    std::string text = "N0000 BSR .L1\nN0001 M30\n";
    for (int level = 1; level <= 10; ++level)
        text += "N" + std::to_string(100 + level) + " .L" + std::to_string(level) +
                (level < 10 ? " BSR .L" + std::to_string(level + 1) : " @1=1") + "\n";
    mill.add(text + "N0200 RTS\n", 1);
    RestartSelection s = mill.selection(1, 1, 110);
    for (int n : {0, 101, 102, 103, 104, 105, 106, 107, 108, 109})
        s.path.push_back(mill.ref(1, n));
    ComputingProcess c(mill.config, mill.store, mill.sps, mill.services());
    DiagnosticList d;
    EXPECT_FALSE(c.begin(s, mill.live.state(), {}, 100, d));
    EXPECT_EQ(errorCodes(d), std::vector<std::string>{"RESTART_PATH_DEPTH"});
    s.path.pop_back();
    s.target = mill.ref(1, 109);
    DiagnosticList ok;
    EXPECT_TRUE(c.begin(s, mill.live.state(), {}, 100, ok)) << diagnosticsText(ok);
}

TEST(RestartComputing, FunctionBufferDropsTheOldest) {
    FunctionBuffer buffer;
    for (int i = 1; i <= 41; ++i)
        buffer.push(i);
    const auto e = buffer.elements();
    EXPECT_EQ(e.front(), 2);
    EXPECT_EQ(e.back(), 41);
    buffer.clear();
    buffer.push(9);
    EXPECT_EQ(buffer.elements()[0], 9);
    EXPECT_EQ(buffer.elements()[1], 0);
    for (int i = 1; i <= 130; ++i)  // round the ring more than three times
        buffer.push(i);
    const auto wrapped = buffer.elements();
    for (int i = 0; i < FunctionBuffer::kLength; ++i)
        EXPECT_EQ(wrapped[static_cast<std::size_t>(i)], 91 + i) << i;
}

TEST(RestartComputing, CollectorKeepsWhatTheGroupRuleStores) {
    for (int process : {0, 1}) {  // the collector's table against the rule, every M and beyond
        const ProcessConfig& config = *demoCell().process(process);
        const AuxFunctionGroups groups(config);
        const RestartAuxCollector collector(config);
        for (int m = -120; m <= 1120; ++m)
            EXPECT_EQ(collector.storesInM16(m), groups.storedInBuffer(m)) << process << " M" << m;
    }
}

}  // namespace
