// Target paths of `mtc200-cli restart --target` (CLI-CONTRACT.md): syntax,
// N and L references, P prefixes, following branches, calls into program 99,
// JSR / JMP by constant and by variable, events, and every refusal.
#include <gtest/gtest.h>

#include "RestartTestSupport.h"
#include "cnc_core/restart/TargetPath.h"

namespace {

using namespace mtc::core;
using namespace mtc::test;

const char* kMain =
    "N0001 @20=5 ;line 1\n"
    "N0002 BSR .SUB\n"
    "N0003 JSR 7\n"
    "N0004 JSR @20\n"
    "N0005 BES .SKIP 0:9\n"
    "N0006 @1=1\n"
    "N0007 .SKIP BEV .SUB 3:4\n"
    "N0008 JMP 7\n"
    "N0009 .SUB @2=2\n"
    "N0010 RTS\n";

struct PathCell : RestartCell {
    PathCell() : RestartCell(0) {
        add(kMain, 1);
        add("N0000 M30\nN0001 .LIB @3=3\nN0002 BSR .SUB\nN0003 RTS\n"
            "N0004 .SUB @4=4\nN0005 RTS\n",
            99);
        add("N0000 @5=5\nN0001 BSR .LIB\nN0002 RTS\n", 7);
        add("N0000 @6=6\nN0001 RTS\n", 5);
    }
    TargetPathResult resolve(const std::string& text, const InterpreterState* state = nullptr) {
        return resolveTargetPath(text, store, 0, 1, state);
    }
};

std::vector<std::string> codes(const TargetPathResult& r) {
    return errorCodes(r.diagnostics);
}

TEST(RestartTargetPath, SyntaxErrorsAreUsageErrors) {
    PathCell cell;
    for (const char* bad :
         {"", "N", "X12", "N12>", ">N1", "P1N2", "P:N2", "N-1", "L1.5", "N1>>N2"}) {
        const TargetPathResult r = cell.resolve(bad);
        EXPECT_FALSE(r.ok) << bad;
        EXPECT_TRUE(r.syntaxError) << bad;
        EXPECT_EQ(codes(r), std::vector<std::string>{"RESTART_PATH_SYNTAX"}) << bad;
    }
}

TEST(RestartTargetPath, BlockAndLineReferences) {
    PathCell cell;
    TargetPathResult r = cell.resolve("N0006");
    ASSERT_TRUE(r.ok) << diagnosticsText(r.diagnostics);
    EXPECT_EQ(r.selection.target, cell.ref(1, 6));
    EXPECT_TRUE(r.selection.path.empty());
    EXPECT_EQ(r.selection.mainProgram, 1);
    r = cell.resolve("L6");
    ASSERT_TRUE(r.ok);
    EXPECT_EQ(r.selection.target, cell.ref(1, 6));
    r = cell.resolve("P1:n6");
    EXPECT_TRUE(r.ok) << "lower case and P prefix of the program the path is in";
    EXPECT_EQ(codes(cell.resolve("N0042")),
              std::vector<std::string>{"RESTART_PATH_BLOCK_NOT_FOUND"});
    EXPECT_EQ(codes(cell.resolve("P7:N0006")), std::vector<std::string>{"RESTART_PATH_PROGRAM"});
}

TEST(RestartTargetPath, SubroutineCallsSearchTheProgramThenProgram99) {
    PathCell cell;
    TargetPathResult r = cell.resolve("N0002>N0010");
    ASSERT_TRUE(r.ok) << diagnosticsText(r.diagnostics);
    EXPECT_EQ(r.selection.path, std::vector<BlockRef>{cell.ref(1, 2)});
    EXPECT_EQ(r.selection.target, cell.ref(1, 10)) << ".SUB is in the program itself";
    r = cell.resolve("N0003>N0001>P99:N0002>N0005");
    ASSERT_TRUE(r.ok) << diagnosticsText(r.diagnostics);
    EXPECT_EQ(r.selection.target, cell.ref(99, 5)) << "program 7 calls .LIB, .LIB calls .SUB of 99";
    EXPECT_EQ(r.selection.path.size(), 3u);
}

TEST(RestartTargetPath, JsrByVariableTakesTheNextProgramAsTheOperatorsEntry) {
    PathCell cell;
    TargetPathResult r = cell.resolve("N0004>P5:N0001");
    ASSERT_TRUE(r.ok) << diagnosticsText(r.diagnostics);
    EXPECT_EQ(r.selection.variableChanges.at(20), 5.0);
    EXPECT_EQ(r.selection.target, cell.ref(5, 1));
    const TargetPathResult missing = cell.resolve("N0004>N0001");
    EXPECT_EQ(codes(missing), std::vector<std::string>{"RESTART_PATH_PROGRAM_NOT_FOUND"})
        << "@20 is 0 in a fresh control";
    EXPECT_NE(missing.diagnostics.items()[0].message.find("program 0"), std::string::npos);
    InterpreterState state;
    state.variables.values[20] = 7;
    r = cell.resolve("N0004>N0001", &state);
    ASSERT_TRUE(r.ok) << "the variable's current value";
    EXPECT_EQ(r.selection.target, cell.ref(7, 1));
    EXPECT_TRUE(r.selection.variableChanges.empty());
    EXPECT_EQ(codes(cell.resolve("N0004>P6:N0001")),
              std::vector<std::string>{"RESTART_PATH_PROGRAM_NOT_FOUND"})
        << "a variable program number that does not exist";
}

TEST(RestartTargetPath, EventsAreSetSoThatTheFollowedJumpIsTaken) {
    PathCell cell;
    TargetPathResult r = cell.resolve("N0005>N0007>N0009");
    ASSERT_TRUE(r.ok) << diagnosticsText(r.diagnostics);
    EXPECT_TRUE((r.selection.eventChanges.at({0, 9})));
    EXPECT_TRUE((r.selection.eventChanges.at({3, 4})));
}

TEST(RestartTargetPath, JmpContinuesInTheOtherProgram) {
    PathCell cell;
    const TargetPathResult r = cell.resolve("N0008>N0001");
    ASSERT_TRUE(r.ok) << diagnosticsText(r.diagnostics);
    EXPECT_EQ(r.selection.target, cell.ref(7, 1));
}

TEST(RestartTargetPath, Refusals) {
    PathCell cell;
    EXPECT_EQ(codes(cell.resolve("N0001>N0002")),
              std::vector<std::string>{"RESTART_PATH_NOT_A_CALL"});
    EXPECT_EQ(codes(cell.resolve("N0010>N0002")),
              std::vector<std::string>{"RESTART_PATH_NOT_A_CALL"})
        << "RTS cannot be followed";
    cell.add("N0001 JSR 42\nN0002 BSR .NOWHERE\nN0003 M30\n", 2);
    EXPECT_EQ(codes(resolveTargetPath("N0001>N0000", cell.store, 0, 2)),
              std::vector<std::string>{"RESTART_PATH_PROGRAM_NOT_FOUND"});
    EXPECT_EQ(codes(resolveTargetPath("N0002>N0000", cell.store, 0, 2)),
              std::vector<std::string>{"RESTART_PATH_LABEL_NOT_FOUND"});
    EXPECT_EQ(codes(resolveTargetPath("N0001", cell.store, 0, 3)),
              std::vector<std::string>{"RESTART_PROGRAM_NOT_FOUND"});
}

TEST(RestartTargetPath, CyclesAreRefused) {
    PathCell cell;
    auto cycle = std::make_shared<Program>(*parse("N0000 .*CYC @1=1\nN0001 RTS\n", 0));
    cycle->isCycle = true;
    cell.store.putCycle("CYC", cycle);
    cell.add("N0001 BSR .*CYC\nN0002 M30\n", 2);
    EXPECT_EQ(codes(resolveTargetPath("N0001>N0000", cell.store, 0, 2)),
              std::vector<std::string>{"RESTART_IN_CYCLE"});
}

TEST(RestartTargetPath, TheTenthLevelIsTheDeepest) {
    RestartCell mill(0);
    std::string text = "N0000 BSR .L1\nN0001 M30\n";
    for (int level = 1; level <= 10; ++level)
        text += "N" + std::to_string(100 + level) + " .L" + std::to_string(level) +
                (level < 10 ? " BSR .L" + std::to_string(level + 1) : " @1=1") + "\n";
    mill.add(text + "N0200 RTS\n", 1);
    std::string path = "N0000";
    for (int n = 101; n <= 108; ++n)
        path += ">N" + std::to_string(n);
    EXPECT_TRUE(resolveTargetPath(path + ">N0109", mill.store, 0, 1).ok);
    EXPECT_EQ(codes(resolveTargetPath(path + ">N0109>N0110", mill.store, 0, 1)),
              std::vector<std::string>{"RESTART_PATH_DEPTH"});
}

}  // namespace
