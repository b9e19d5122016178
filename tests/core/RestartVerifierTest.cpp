// The restart verifier (issue 15 §3, restart.md R-028): every arrival of
// the built-in demo programs is a target that the computing process
// computes as a normal run has it and ADJUST / REPOS re-establish; a wrong
// ADJUST is found with its targets; the run through the program with
// checkpoints gives what a restart from scratch gives.
#include <gtest/gtest.h>

#include <map>

#include "RestartTestSupport.h"
#include "cnc_core/compiler/Compiler.h"
#include "cnc_core/restart/RestartVerifier.h"
#include "resources/EmbeddedResources.h"

namespace {

using namespace mtc::core;
using namespace mtc::test;

/// The demo programs of `process` (GNE programs compiled, as they run).
ProgramStore demoStore(int process) {
    ProgramStore store;
    for (const auto& name : mtc::resources::list("programs/")) {
        const std::string file = name.substr(name.rfind('/') + 1);
        if (file[4] - '0' != process) continue;
        const int number = std::stoi(file.substr(5, 3));
        std::string source(mtc::resources::find(name));
        if (parse(source, number)->usesCompilerKeywords) {
            CompilerOptions options;
            options.compilerActive = true;
            options.process = demoCell().process(process);
            options.programNumber = number;
            source = Compiler().compile(source, options).objectText;
        }
        store.put(process, number, parse(source, number));
    }
    return store;
}

VerifyReport verify(const ProgramStore& store, int process, int program, bool adjust,
                    std::uint32_t passes = kDefaultVerifyPasses) {
    VerifyOptions options;
    options.adjust = adjust;
    options.maxPasses = passes;
    RestartVerifier verifier(demoCell(), process, store, options);
    DiagnosticList d;
    EXPECT_TRUE(verifier.begin(program, d)) << diagnosticsText(d);
    verifier.advance(~std::uint64_t{0});
    return verifier.report();
}

std::string problems(const VerifyReport& report) {
    std::string text = report.coverageLine() + "\n" + diagnosticsText(report.diagnostics);
    for (const VerifiedTarget& t : report.problems)
        text += t.where.block + ": " + diagnosticsText(t.diagnostics);
    return text;
}

TEST(RestartVerifier, EveryDemoProgramIsReestablishedAtEveryArrival) {
    for (const auto& [process, program] :
         std::vector<std::pair<int, int>>{{0, 1}, {0, 2}, {1, 1}, {1, 2}}) {
        const ProgramStore store = demoStore(process);
        const VerifyReport report = verify(store, process, program, true);
        EXPECT_TRUE(report.complete) << process << "/" << program << "\n" << problems(report);
        EXPECT_GT(report.targets, 10u);
        EXPECT_EQ(report.reestablished, report.targets) << process << "/" << program << "\n"
                                                        << problems(report);
        EXPECT_EQ(report.arrivals, report.targets + report.beyondPasses + report.notSelectable);
    }
}

TEST(RestartVerifier, AnAdjustThatLeavesG0ActiveIsFoundWithItsTargets) {
    RestartCell mill(0);
    // The tool change leaves G0 (like a G53 G0 to the change height); REPOS
    // does not restore the interpolation of the target.
    mill.add(
        "N0000 M30\n"
        "N0001 .ADJUST @150=M(2) @151=G(4)\n"
        "N0002 G53 G0 Z90\n"
        "N0003 G=@151\n"
        "N0004 .REPOS G77 S0 M=@150\n"
        "N0005 G77 X0 Y0 F2000\n"
        "N0006 G77 Z0 F1000 RTS\n",
        99);
    mill.add(
        "N0001 G0 G54 X10 Y10 Z5 S2000 M3\n"
        "N0002 G1 Z-2 F300\n"
        "N0003 X50\n"
        "N0004 Y40\n"
        "N0005 G0 Z5\n"
        "N0006 M30\n",
        1);
    const VerifyReport report = verify(mill.store, 0, 1, true);
    EXPECT_EQ(report.targets, 6u);
    EXPECT_EQ(report.reestablished, 3u) << problems(report);
    ASSERT_EQ(report.problems.size(), 3u);
    for (const VerifiedTarget& t : report.problems) {
        EXPECT_EQ(t.outcome, TargetOutcome::Differs);
        EXPECT_TRUE(t.computed.empty()) << "the computing process is right";
        ASSERT_EQ(t.cutting.size(), 1u) << t.where.block;
        EXPECT_EQ(t.cutting[0].what, "g1");
        EXPECT_EQ(t.cutting[0].expected, 1);
        EXPECT_EQ(t.cutting[0].actual, 0);
    }
    EXPECT_EQ(report.problems[0].where.block, "N0003");
    EXPECT_EQ(report.coverageLine(),
              "3 of 6 targets re-established; 3 leave G0 active: N0003, N0004, N0005");
    // Without --adjust only the computing process is checked: all right.
    const VerifyReport computedOnly = verify(mill.store, 0, 1, false);
    EXPECT_EQ(computedOnly.reestablished, 6u) << problems(computedOnly);
}

TEST(RestartVerifier, PassesCountPerCallChainAndStopAtTheLimit) {
    RestartCell mill(0);
    mill.add(
        "N0001 @1=0 @2=0\n"
        "N0002 .LOOP @1=@1+1\n"
        "N0003 BSR .SUB\n"
        "N0004 @3=@1-5 BMI .LOOP\n"
        "N0005 M30\n"
        "N0006 .SUB @2=@2+@1\n"
        "N0007 RTS\n",
        1);
    const VerifyReport all = verify(mill.store, 0, 1, false);
    EXPECT_EQ(all.arrivals, 1u + 5 * 5 + 1);
    EXPECT_EQ(all.targets, all.arrivals) << "every pass within 16";
    EXPECT_EQ(all.reestablished, all.targets) << problems(all);
    const VerifyReport two = verify(mill.store, 0, 1, false, 2);
    EXPECT_EQ(two.targets, 1u + 5 * 2 + 1);
    EXPECT_EQ(two.beyondPasses, 5u * 3);
    EXPECT_NE(two.coverageLine().find("15 arrivals after the last verified pass"),
              std::string::npos)
        << two.coverageLine();
}

TEST(RestartVerifier, CheckpointsGiveWhatARestartFromScratchGives) {
    // The program run checks every target from a checkpoint of its own
    // computing process; verifySelection runs the whole restart from the
    // start block for the same selection. Both must agree for every target,
    // the planted ADJUST error included.
    for (const int process : {0, 1}) {
        ProgramStore store = demoStore(process);
        VerifyOptions options;
        options.adjust = true;
        options.maxPasses = 3;
        options.keepEveryTarget = true;
        RestartVerifier run(demoCell(), process, store, options);
        DiagnosticList d;
        ASSERT_TRUE(run.begin(1, d));
        run.advance(~std::uint64_t{0});
        const VerifyReport& report = run.report();
        ASSERT_EQ(report.every.size(), report.targets) << problems(report);
        RestartVerifier single(demoCell(), process, store, options);
        for (const VerifiedTarget& t : report.every) {
            const VerifiedTarget again = single.verifySelection(t.selection);
            const std::string name = std::to_string(process) + " " + t.where.block + " pass " +
                                     std::to_string(t.selection.runs);
            EXPECT_EQ(again.outcome, t.outcome) << name << diagnosticsText(again.diagnostics);
            EXPECT_EQ(again.computed.size(), t.computed.size()) << name;
            EXPECT_EQ(again.cutting.size(), t.cutting.size()) << name;
            EXPECT_EQ(again.where.block, t.where.block) << name;
        }
    }
}

TEST(RestartVerifier, StateComparisonListsEachItemOnce) {
    RestartCell mill(0);
    InterpreterState a = mill.live.state();
    InterpreterState b = a;
    b.modal.g[kGroupInterpolation] = 1;
    b.mGroups[5] = 108;
    b.modal.spindleSpeed[1] = 1500;
    b.variables.values[100] = 3;
    b.variables.written.set(100);
    b.modal.machine[2] = -2.5;
    const std::array<int, FunctionBuffer::kLength> empty{};
    std::array<int, FunctionBuffer::kLength> one{};
    one[0] = 62;
    const RestartStateView expected{&a, &empty, &empty, nullptr};
    const RestartStateView actual{&b, &one, &empty, nullptr};
    std::vector<std::string> keys;
    for (const StateDifference& d :
         compareRestartStates(expected, actual, CompareScope::Computed, mill.live.axes()))
        keys.push_back(d.what);
    EXPECT_EQ(keys,
              (std::vector<std::string>{"g1", "m5", "s1", "page61.m16", "@100", "position.Z"}));
    // The cutting scope leaves variables and buffers out; M groups from the machine.
    MachineAuxState machine;
    machine.mGroups = a.mGroups;
    machine.spindleSpeed = a.modal.spindleSpeed;
    const RestartStateView after{&b, nullptr, nullptr, &machine};
    keys.clear();
    for (const StateDifference& d : compareRestartStates({&a, nullptr, nullptr, nullptr}, after,
                                                         CompareScope::Cutting, mill.live.axes()))
        keys.push_back(d.what);
    EXPECT_EQ(keys, (std::vector<std::string>{"g1", "position.Z"}))
        << "M5 and S1 never reached the machine";
    EXPECT_EQ(describeStateItem("g1"), "G group 1 (interpolation)");
    EXPECT_EQ(describeStateItem("tool_spindle2"), "tool in tool spindle 2");
}

}  // namespace
