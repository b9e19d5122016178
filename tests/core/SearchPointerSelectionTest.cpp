// Search pointer of the restart screen: search string, start block (last
// primary block), number of runs, warnings and the selection <Enter> builds
// (seed 000, 2.3-2.6 and 5.1).
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "SearchPointerTestSupport.h"
#include "cnc_core/restart/RestartRoute.h"

using namespace mtc::core;
using namespace mtc::core::testing;

namespace {

struct SearchSelectionTest : ::testing::Test {
    SearchStore cell;
    SearchPointer pointer{cell.store, 0, cell.sources()};

    void SetUp() override { ASSERT_TRUE(pointer.begin(5).ok); }
    void cursorOn(int n) { pointer.moveTo(blockOf(pointer, n)); }
    std::string code(const SearchReply& reply) { return reply.note ? reply.note->code : ""; }
    std::vector<std::string> codes(const AcceptResult& result) {
        std::vector<std::string> list;
        for (const auto& d : result.diagnostics.items())
            list.push_back(d.code);
        return list;
    }
    /// What the NC answers to the accepted selection (the CLI and the screen
    /// both get it from ComputingProcess::begin): refusals of the route and
    /// the start warnings of RS-011.
    DiagnosticList nc(const AcceptResult& result) {
        RestartRoute route;
        DiagnosticList d;
        if (planRestartRoute(result.selection, cell.store, route, d)) addStartWarnings(route, d);
        return d;
    }
    std::vector<std::string> ncCodes(const AcceptResult& result) {
        std::vector<std::string> list;
        const DiagnosticList answer = nc(result);
        for (const auto& d : answer.items())
            list.push_back(d.code);
        return list;
    }
};

}  // namespace

TEST_F(SearchSelectionTest, SearchFindsWordsForwardFromTheCursor) {
    ASSERT_TRUE(pointer.search("BSR").ok);
    EXPECT_EQ(cursorText(pointer), "P5 N0002");
    ASSERT_TRUE(pointer.search("BSR").ok) << "the next occurrence, not the cursor block";
    EXPECT_EQ(cursorText(pointer), "P5 N0005");
}

TEST_F(SearchSelectionTest, SearchIncludesCommentsAndIgnoresCase) {
    ASSERT_TRUE(pointer.search("second primary").ok);
    EXPECT_EQ(cursorText(pointer), "P5 N0007");
    ASSERT_TRUE(pointer.search("side WALL").ok);
    EXPECT_EQ(cursorText(pointer), "P5 N0020");
}

TEST_F(SearchSelectionTest, AHitOnACommentLineGoesToTheNextBlock) {
    ASSERT_TRUE(pointer.search("hidden-gem").ok);
    EXPECT_EQ(cursorText(pointer), "P5 N0020");
}

TEST_F(SearchSelectionTest, SearchDoesNotWrapAndKeepsTheCursor) {
    cursorOn(20);
    auto reply = pointer.search("BSR .TOOL");
    EXPECT_FALSE(reply.ok);
    EXPECT_EQ(code(reply), "RESTART_TEXT_NOT_FOUND");
    EXPECT_NE(reply.note->message.find("not found after N0020"), std::string::npos);
    EXPECT_EQ(cursorText(pointer), "P5 N0020");
    EXPECT_EQ(code(pointer.search("")), "RESTART_SEARCH_EMPTY");
    EXPECT_EQ(code(pointer.search("PROGRAMMENDE")), "RESTART_TEXT_NOT_FOUND")
        << "the end of the program is not a target";
}

TEST_F(SearchSelectionTest, SearchWorksInTheDisplayedLevel) {
    cursorOn(2);
    ASSERT_TRUE(pointer.planePlus().ok);  // P99 .TOOL
    ASSERT_TRUE(pointer.search("deep").ok);
    EXPECT_EQ(cursorText(pointer), "P99 N0003");
}

// A large text is searched in two halves at once: the first hit is the same
// as the one-piece search's wherever it lies (first half, second half, across
// the middle, none), from every start.
TEST_F(SearchSelectionTest, TheSplitSearchFindsWhatTheOnePieceSearchFinds) {
    std::string text;
    for (int i = 0; i < 5000; ++i)
        text += "N" + std::to_string(1000 + i % 9000) + " G1 X" + std::to_string(i % 97) + "\n";
    const std::size_t middle = text.size() / 2;
    text.replace(middle - 2, 5, "EDGE!");  // across the middle of a search from 0
    text.replace(100, 4, "edge");
    text.replace(text.size() - 10, 4, "Edge");
    const std::size_t split = 64;  // split every search longer than 64 bytes
    int compared = 0;
    for (const char* needle : {"edge", "EDGE!", "X96\n", "g1 x5", "zzz", "N1000 G1 X0"}) {
        for (std::size_t from = 0; from < text.size(); from += 997) {
            const std::size_t expected = ProgramScan::findFolded(text, needle, from);
            EXPECT_EQ(ProgramScan::findFoldedSplit(text, needle, from, split), expected)
                << needle << " from " << from;
            ++compared;
        }
        EXPECT_EQ(ProgramScan::findFoldedSplit(text, needle, 0, split),
                  ProgramScan::findFolded(text, needle, 0));
    }
    EXPECT_EQ(ProgramScan::findFoldedSplit(text, "edge!", 0, split), middle - 2);
    EXPECT_EQ(ProgramScan::findFoldedSplit(text, "edge", 101, split), middle - 2);
    EXPECT_EQ(ProgramScan::findFoldedSplit(text, "edge", middle, split), text.size() - 10);
    EXPECT_EQ(ProgramScan::findFoldedSplit(text, "zzz", 0, split), std::string::npos);
    EXPECT_GT(compared, 100);
}

TEST_F(SearchSelectionTest, FindFoldedMatchesEveryPositionOfTheText) {
    // Lengths around the 16-byte SSE2 step, hits at the start, inside and at the end.
    std::string text(100, 'x');
    text.replace(0, 3, "AbC");
    text.replace(40, 3, "abc");
    text.replace(97, 3, "ABC");
    EXPECT_EQ(ProgramScan::findFolded(text, "abc"), 0u);
    EXPECT_EQ(ProgramScan::findFolded(text, "ABC", 1), 40u);
    EXPECT_EQ(ProgramScan::findFolded(text, "abc", 41), 97u);
    EXPECT_EQ(ProgramScan::findFolded(text, "abc", 98), std::string::npos);
    EXPECT_EQ(ProgramScan::findFolded(text, "x"), 3u);
    EXPECT_EQ(ProgramScan::findFolded("short", "longer than the text"), std::string::npos);
    EXPECT_EQ(ProgramScan::findFolded("@[`{", "@[`{"), 0u) << "no folding outside A-Z";
    EXPECT_EQ(ProgramScan::findFolded("`{", "@["), std::string::npos);
    // The anchor filter also lets through the byte that differs in bit 5 from
    // a non-letter ('@' for '`', 0x10 for '0'): the full comparison rejects it.
    EXPECT_EQ(ProgramScan::findFolded(std::string(40, '@') + "`", "`"), 40u);
    EXPECT_EQ(ProgramScan::findFolded(std::string(40, '\x10') + "0", "0"), 40u);
}

TEST_F(SearchSelectionTest, FindFoldedAgreesWithAPlainSearchOnRandomTexts) {
    // Every start and length around the 32- and 16-byte steps and the tail,
    // needles of NC characters in both cases, many candidates per step.
    auto lower = [](std::string s) {
        for (char& c : s)
            if (c >= 'A' && c <= 'Z') c = static_cast<char>(c | 0x20);
        return s;
    };
    const std::string alphabet = "GgXx01 .@`;\n";
    std::uint32_t seed = 12345;
    auto next = [&seed] { return seed = seed * 1664525u + 1013904223u; };
    for (int round = 0; round < 2000; ++round) {
        std::string text(next() % 150, ' ');
        for (char& c : text)
            c = alphabet[next() % alphabet.size()];
        std::string needle(1 + next() % 4, ' ');
        for (char& c : needle)
            c = alphabet[next() % alphabet.size()];
        const std::size_t from = text.empty() ? 0 : next() % (text.size() + 1);
        const std::size_t expected = lower(text).find(lower(needle), from);
        ASSERT_EQ(ProgramScan::findFolded(text, needle, from), expected)
            << "text '" << text << "' needle '" << needle << "' from " << from;
    }
}

TEST_F(SearchSelectionTest, StartBlockIsN0000UnlessTheLastPrimaryBlockIsChosen) {
    cursorOn(12);
    auto start = pointer.startBlock();
    ASSERT_TRUE(start);
    EXPECT_FALSE(start->primary);
    EXPECT_EQ(start->block.block, 0u);
    ASSERT_TRUE(pointer.setFromLastPrimary(true).ok);
    start = pointer.startBlock();
    ASSERT_TRUE(start);
    EXPECT_TRUE(start->primary);
    EXPECT_EQ(start->block.block, blockOf(pointer, 7));
    cursorOn(7);  // the target itself is not "before the target"
    EXPECT_EQ(pointer.startBlock()->block.block, blockOf(pointer, 1));
    cursorOn(8);
    EXPECT_EQ(pointer.startBlock()->block.block, blockOf(pointer, 7));
}

TEST_F(SearchSelectionTest, NoPrimaryBlockBeforeTheTargetIsRefusedAndWarned) {
    cursorOn(1);  // N0001 is the first primary block: nothing before it
    auto reply = pointer.setFromLastPrimary(true);
    EXPECT_FALSE(reply.ok);
    EXPECT_EQ(code(reply), "RESTART_NO_PRIMARY");
    EXPECT_FALSE(pointer.fromLastPrimary());
    // Switched on further down, then the cursor moves up: Enter refuses.
    cursorOn(3);
    ASSERT_TRUE(pointer.setFromLastPrimary(true).ok);
    cursorOn(0);
    EXPECT_FALSE(pointer.startBlock());
    const AcceptResult result = pointer.accept();
    EXPECT_FALSE(result.ok);
    EXPECT_EQ(codes(result), std::vector<std::string>{"RESTART_NO_PRIMARY"});
}

TEST_F(SearchSelectionTest, PrimaryBlockInASubroutineOrOnTheWayThere) {
    // Program 6 has a primary block N0001; JSR 6 in N0008 of program 5.
    cursorOn(8);
    ASSERT_TRUE(pointer.planePlus().ok);
    pointer.end();  // P6 N0002 RTS
    ASSERT_TRUE(pointer.setFromLastPrimary(true).ok);
    auto start = pointer.startBlock();
    EXPECT_EQ(start->level, 1);
    EXPECT_EQ(start->block.program, 6);
    EXPECT_EQ(start->block.block, 1u);
    // On N0000 of program 6 the last primary block is N0007 of program 5.
    pointer.home();
    start = pointer.startBlock();
    EXPECT_EQ(start->level, 0);
    EXPECT_EQ(start->block.program, 5);
    EXPECT_EQ(start->block.block, 7u);
    // In .SIDE (entered from N0005) the blocks between N0005 and the label are skipped.
    ASSERT_TRUE(pointer.planeMinus().ok);
    cursorOn(5);
    ASSERT_TRUE(pointer.planePlus().ok);
    EXPECT_EQ(pointer.startBlock()->block.block, 1u) << "N0001, not N0007 after the call";
}

TEST_F(SearchSelectionTest, NumberOfRunsIsValidatedAndOldValueKept) {
    ASSERT_TRUE(pointer.setRuns("3").ok);
    EXPECT_EQ(pointer.runs(), 3u);
    auto reply = pointer.setRuns("0");
    EXPECT_EQ(code(reply), "RESTART_RUNS_RANGE");
    EXPECT_NE(reply.note->message.find("1 ... 65536"), std::string::npos);
    EXPECT_EQ(code(pointer.setRuns("65537")), "RESTART_RUNS_RANGE");
    EXPECT_EQ(code(pointer.setRuns("99999999999999999999999")), "RESTART_RUNS_RANGE");
    EXPECT_EQ(code(pointer.setRuns("abc")), "RESTART_RUNS_TEXT");
    EXPECT_EQ(code(pointer.setRuns("2.5")), "RESTART_RUNS_TEXT");
    EXPECT_EQ(code(pointer.setRuns("-4")), "RESTART_RUNS_TEXT");
    EXPECT_EQ(code(pointer.setRuns("")), "RESTART_RUNS_TEXT");
    EXPECT_EQ(pointer.runs(), 3u);
    ASSERT_TRUE(pointer.setRuns(" 65536 ").ok);
    EXPECT_EQ(pointer.runs(), 65536u);
    ASSERT_TRUE(pointer.setRuns("1").ok);
    EXPECT_EQ(pointer.runs(), 1u);
}

TEST_F(SearchSelectionTest, RunsGoBackToOneOnEntryAndAfterTheComputingProcess) {
    ASSERT_TRUE(pointer.setRuns("12").ok);
    pointer.computingProcessDone();
    EXPECT_EQ(pointer.runs(), 1u);
    ASSERT_TRUE(pointer.setRuns("12").ok);
    ASSERT_TRUE(pointer.begin(5).ok);
    EXPECT_EQ(pointer.runs(), 1u);
}

TEST_F(SearchSelectionTest, AcceptBuildsTheSelectionWithPathAndTarget) {
    cursorOn(5);
    ASSERT_TRUE(pointer.planePlus().ok);  // .SIDE
    pointer.down();                       // N0021
    ASSERT_TRUE(pointer.setRuns("3").ok);
    const AcceptResult result = pointer.accept();
    ASSERT_TRUE(result.ok);
    const RestartSelection& s = result.selection;
    EXPECT_EQ(s.process, 0);
    EXPECT_EQ(s.mainProgram, 5);
    ASSERT_EQ(s.path.size(), 1u);
    EXPECT_EQ(s.path[0], (BlockRef{5, 5}));
    EXPECT_EQ(s.target, (BlockRef{5, 21}));
    EXPECT_EQ(s.runs, 3u);
    EXPECT_FALSE(s.fromLastPrimary);
    EXPECT_TRUE(result.diagnostics.empty());
}

TEST_F(SearchSelectionTest, AcceptIsRefusedWhileAWindowIsOpen) {
    cursorOn(10);
    ASSERT_TRUE(pointer.planePlus().ok);
    const AcceptResult result = pointer.accept();
    EXPECT_FALSE(result.ok);
    EXPECT_EQ(codes(result), std::vector<std::string>{"RESTART_WINDOW_OPEN"});
}

TEST_F(SearchSelectionTest, SubroutineAtTheProgramStartNeedsTheStartBlock) {
    ASSERT_TRUE(pointer.begin(8).ok);
    pointer.moveTo(4);  // N0004 after the subroutine and its call
    AcceptResult result = pointer.accept();
    ASSERT_TRUE(result.ok) << "the screen accepts it; the NC refuses it";
    EXPECT_TRUE(result.diagnostics.empty());
    ASSERT_EQ(ncCodes(result), std::vector<std::string>{"RESTART_START_BLOCK_NEEDED"});
    const Diagnostic refusal = nc(result).items()[0];
    EXPECT_EQ(refusal.severity, Severity::Error) << "seed 000, 2.4: the start block is mandatory";
    EXPECT_EQ(refusal.where.block, "N0001");
    // With the start block chosen it is accepted without a warning.
    ASSERT_TRUE(pointer.setFromLastPrimary(true).ok);
    result = pointer.accept();
    ASSERT_TRUE(result.ok);
    EXPECT_TRUE(nc(result).empty());
    EXPECT_EQ(result.start.block.block, 2u);
    // A target inside the subroutine itself is reached before its RTS.
    ASSERT_TRUE(pointer.setFromLastPrimary(false).ok);
    pointer.moveTo(1);
    EXPECT_TRUE(nc(pointer.accept()).empty());
    // Program 5 has its subroutine after M30: no warning.
    ASSERT_TRUE(pointer.begin(5).ok);
    cursorOn(12);
    EXPECT_TRUE(nc(pointer.accept()).empty());
}

TEST_F(SearchSelectionTest, WarnsWhenTheStartBlockLiesAfterG91OrG51) {
    ASSERT_TRUE(pointer.begin(7).ok);
    ASSERT_TRUE(pointer.setFromLastPrimary(false).ok);
    pointer.moveTo(2);  // start N0001: G91 only in its comment and later
    ASSERT_TRUE(pointer.setFromLastPrimary(true).ok);
    EXPECT_TRUE(nc(pointer.accept()).empty());
    pointer.moveTo(4);  // start N0003 after G91 in N0002
    AcceptResult result = pointer.accept();
    ASSERT_TRUE(result.ok);
    EXPECT_TRUE(result.diagnostics.empty()) << "the NC warns (ComputingProcess::begin)";
    EXPECT_EQ(ncCodes(result), std::vector<std::string>{"RESTART_START_AFTER_G91"});
    EXPECT_EQ(nc(result).items()[0].where.block, "N0003");
    pointer.moveTo(6);  // start N0005: G90 in N0004 ends G91
    EXPECT_TRUE(nc(pointer.accept()).empty());
    pointer.moveTo(8);  // start N0007 after G51 in N0006
    EXPECT_EQ(ncCodes(pointer.accept()), std::vector<std::string>{"RESTART_START_AFTER_G51"});
}

TEST_F(SearchSelectionTest, StartBlockAndSelectionAgreeWithTheComputingProcessRoute) {
    // What the screen shows as start block is where the computing process
    // starts (RestartRoute, docs/decisions/restart.md R-002), for every target
    // of program 5 and of the subroutines reached with Plane+.
    auto check = [&](const std::string& where) {
        const AcceptResult accepted = pointer.accept();
        if (!accepted.ok) {
            EXPECT_EQ(accepted.diagnostics.items().front().code, "RESTART_NO_PRIMARY") << where;
            return;
        }
        RestartRoute route;
        DiagnosticList diagnostics;
        if (!planRestartRoute(accepted.selection, cell.store, route, diagnostics)) {
            // A block the level never runs through (a subroutine body after
            // M30, blocks after the BRA to a missing label): refused.
            EXPECT_EQ(diagnostics.items().front().code, "RESTART_TARGET_IN_SUBROUTINE") << where;
            return;
        }
        EXPECT_EQ(accepted.start.block.program, route.startProgram->number) << where;
        EXPECT_EQ(accepted.start.block.block, route.startBlock) << where;
        EXPECT_EQ(accepted.start.primary, route.primary) << where;
        EXPECT_EQ(static_cast<std::size_t>(accepted.start.level), route.startFrames.size())
            << where;
    };
    for (bool primary : {false, true}) {
        for (int calling : {-1, 2, 5, 6, 8}) {
            ASSERT_TRUE(pointer.begin(5).ok);
            if (calling >= 0) {
                cursorOn(calling);
                ASSERT_TRUE(pointer.planePlus().ok) << calling;
            }
            pointer.home();
            if (calling >= 0) pointer.moveTo(pointer.current().entry);
            const std::uint32_t last = pointer.currentScan().lastSelectableBlock();
            for (std::uint32_t block = pointer.current().cursor; block <= last; ++block) {
                pointer.moveTo(block);
                pointer.setFromLastPrimary(primary);
                check("via " + std::to_string(calling) + " target " + cursorText(pointer) +
                      (primary ? " primary" : ""));
            }
        }
    }
}
