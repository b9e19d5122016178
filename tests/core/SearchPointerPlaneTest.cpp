// Search pointer of the restart screen: cursor keys and <Plane+>/<Plane->
// through every jump and call kind of seed 000, 2.5.
#include <gtest/gtest.h>

#include "SearchPointerTestSupport.h"

using namespace mtc::core;
using namespace mtc::core::testing;

namespace {

struct SearchPointerTest : ::testing::Test {
    SearchStore cell;
    SearchPointer pointer{cell.store, 0, cell.sources()};

    void SetUp() override { ASSERT_TRUE(pointer.begin(5).ok); }
    /// Cursor on block number `n` of the displayed program.
    void cursorOn(int n) {
        pointer.moveTo(blockOf(pointer, n));
        ASSERT_EQ(pointer.current().program->blocks[pointer.current().cursor].number, n);
    }
    std::string code(const SearchReply& reply) { return reply.note ? reply.note->code : ""; }
};

}  // namespace

TEST_F(SearchPointerTest, BeginPutsTheCursorOnN0000OfTheSelectedProgram) {
    EXPECT_EQ(pointer.levels().size(), 1u);
    EXPECT_EQ(cursorText(pointer), "P5 N0000");
    EXPECT_EQ(pointer.runs(), 1u);
    EXPECT_FALSE(pointer.fromLastPrimary());
}

TEST_F(SearchPointerTest, BeginRefusesMissingEmptyAndUnselectedPrograms) {
    SearchPointer other(cell.store, 0, cell.sources());
    EXPECT_EQ(code(other.begin(0)), "RESTART_NO_PROGRAM");
    EXPECT_EQ(code(other.begin(42)), "RESTART_NO_PROGRAM");
    EXPECT_FALSE(other.active());
    cell.store.put(0, 9, parsed("N0000 PROGRAMMENDE\n", 9));
    EXPECT_EQ(code(other.begin(9)), "RESTART_EMPTY_PROGRAM");
    EXPECT_FALSE(other.active());
}

TEST_F(SearchPointerTest, UpDownStopAtTheEnds) {
    pointer.up();
    EXPECT_EQ(cursorText(pointer), "P5 N0000");
    pointer.down();
    pointer.down();
    EXPECT_EQ(cursorText(pointer), "P5 N0002");
    pointer.up();
    EXPECT_EQ(cursorText(pointer), "P5 N0001");
    pointer.end();
    pointer.down();
    EXPECT_EQ(cursorText(pointer), "P5 N0021") << "never onto PROGRAMMENDE";
}

TEST_F(SearchPointerTest, HomeIsN0000AndEndTheBlockBeforeTheEndOfProgram) {
    pointer.end();
    EXPECT_EQ(cursorText(pointer), "P5 N0021");
    pointer.home();
    EXPECT_EQ(cursorText(pointer), "P5 N0000");
    // Without PROGRAMMENDE <End> goes to the last block.
    SearchPointer loose(cell.store, 0, cell.sources());
    ASSERT_TRUE(loose.begin(8).ok);
    loose.end();
    EXPECT_EQ(cursorText(loose), "P8 N0005");
}

TEST_F(SearchPointerTest, PageKeysMoveByThePageAndClamp) {
    pointer.pageDown(8);
    EXPECT_EQ(cursorText(pointer), "P5 N0008");
    pointer.pageDown(100);
    EXPECT_EQ(cursorText(pointer), "P5 N0021");
    pointer.pageUp(5);
    EXPECT_EQ(cursorText(pointer), "P5 N0016");
    pointer.pageUp(100);
    EXPECT_EQ(cursorText(pointer), "P5 N0000");
}

TEST_F(SearchPointerTest, PlanePlusOnALabelJumpFindsTheLabelInTheSameProgram) {
    cursorOn(6);  // BNE .LOOP
    ASSERT_TRUE(pointer.planePlus().ok);
    EXPECT_EQ(pointer.levels().size(), 2u);
    EXPECT_EQ(cursorText(pointer), "P5 N0004");
    EXPECT_FALSE(pointer.current().call);
    EXPECT_EQ(pointer.levelCommand(1), "BNE .LOOP");
}

TEST_F(SearchPointerTest, PlanePlusOnBsrGoesToTheLocalLabelAndPlaneMinusBack) {
    cursorOn(5);  // BSR .SIDE
    ASSERT_TRUE(pointer.planePlus().ok);
    EXPECT_EQ(cursorText(pointer), "P5 N0020");
    EXPECT_TRUE(pointer.current().call);
    pointer.down();
    ASSERT_TRUE(pointer.planeMinus().ok);
    EXPECT_EQ(cursorText(pointer), "P5 N0005") << "back at the calling point";
    EXPECT_EQ(code(pointer.planeMinus()), "RESTART_TOP_LEVEL");
}

TEST_F(SearchPointerTest, BsrFindsTheLabelInProgram99) {
    cursorOn(2);  // T1 BSR .TOOL
    ASSERT_TRUE(pointer.planePlus().ok);
    EXPECT_EQ(cursorText(pointer), "P99 N0002");
    EXPECT_EQ(pointer.levelCommand(1), "BSR .TOOL");
}

TEST_F(SearchPointerTest, JsrShowsTheOtherProgramAtN0000) {
    cursorOn(8);  // JSR 6
    ASSERT_TRUE(pointer.planePlus().ok);
    EXPECT_EQ(cursorText(pointer), "P6 N0000");
    EXPECT_EQ(pointer.levelCommand(1), "JSR 6");
}

TEST_F(SearchPointerTest, JmpContinuesTheSearchInTheOtherProgram) {
    cursorOn(15);  // JMP 7
    ASSERT_TRUE(pointer.planePlus().ok);
    EXPECT_EQ(cursorText(pointer), "P7 N0000");
    EXPECT_FALSE(pointer.current().call);
    // JMP ends program 5: program 7 is the only program level, but the
    // computing process starts at the beginning of the NC program, N0000 of
    // program 5 (seed 000, 2.4; restart.md R-024).
    ASSERT_EQ(pointer.programLevels().size(), 1u);
    EXPECT_EQ(pointer.programLevels()[0].program->number, 7);
    EXPECT_EQ(pointer.startBlock()->block, (BlockRef{5, 0}));
    ASSERT_EQ(pointer.programSegments().size(), 2u);
    EXPECT_EQ(pointer.programSegments()[0].jumpProgram->number, 5);
    EXPECT_EQ(pointer.programSegments()[0]
                  .jumpProgram->blocks[pointer.programSegments()[0].jumpBlock]
                  .number,
              15);
}

TEST_F(SearchPointerTest, JsrByVariableShowsTheValueAndJumpsWithIt) {
    cursorOn(9);  // JSR @30, @30 = 6
    ASSERT_TRUE(pointer.planePlus().ok);
    const PlaneWindow& w = pointer.window();
    ASSERT_EQ(w.kind, PlaneWindow::Kind::Variable);
    EXPECT_EQ(w.variable, 30);
    EXPECT_TRUE(w.valueKnown);
    EXPECT_EQ(w.value, 6.0);
    EXPECT_EQ(pointer.levels().size(), 1u) << "no jump before the window is confirmed";
    ASSERT_TRUE(pointer.confirmVariable(6.0).ok);
    EXPECT_EQ(cursorText(pointer), "P6 N0000");
    EXPECT_TRUE(pointer.variableChanges().empty()) << "value unchanged: nothing to record";
    EXPECT_EQ(pointer.levelCommand(1), "JSR @30");
}

TEST_F(SearchPointerTest, VariableWindowChangesTheValueOrAborts) {
    cursorOn(16);  // JMP @31: not written, value unknown
    ASSERT_TRUE(pointer.planePlus().ok);
    ASSERT_EQ(pointer.window().kind, PlaneWindow::Kind::Variable);
    EXPECT_FALSE(pointer.window().valueKnown);
    // A program that does not exist: refused, the window stays open.
    auto reply = pointer.confirmVariable(12);
    EXPECT_FALSE(reply.ok);
    EXPECT_EQ(code(reply), "RESTART_PROGRAM_MISSING");
    EXPECT_NE(reply.note->message.find("program 12 does not exist"), std::string::npos);
    EXPECT_EQ(pointer.window().kind, PlaneWindow::Kind::Variable);
    EXPECT_EQ(code(pointer.confirmVariable(2.5)), "RESTART_VARIABLE_VALUE");
    EXPECT_EQ(code(pointer.confirmVariable(-1)), "RESTART_VARIABLE_VALUE");
    // Abort: nothing changes.
    pointer.cancelWindow();
    EXPECT_EQ(pointer.window().kind, PlaneWindow::Kind::None);
    EXPECT_EQ(pointer.levels().size(), 1u);
    // Change to 7 and jump: recorded for the computing process.
    ASSERT_TRUE(pointer.planePlus().ok);
    ASSERT_TRUE(pointer.confirmVariable(7).ok);
    EXPECT_EQ(cursorText(pointer), "P7 N0000");
    ASSERT_EQ(pointer.variableChanges().count(31), 1u);
    EXPECT_EQ(pointer.variableChanges().at(31), 7.0);
    EXPECT_EQ(pointer.accept().selection.variableChanges.at(31), 7.0);
}

TEST_F(SearchPointerTest, VariableOfAnotherProcessIsShownButNotChanged) {
    cursorOn(17);  // JSR @1:40, @1:40 = 6
    ASSERT_TRUE(pointer.planePlus().ok);
    EXPECT_FALSE(pointer.window().writable);
    EXPECT_EQ(pointer.window().variableProcess, 1);
    EXPECT_EQ(code(pointer.confirmVariable(7)), "RESTART_VARIABLE_READONLY");
    ASSERT_TRUE(pointer.confirmVariable(6).ok);
    EXPECT_EQ(cursorText(pointer), "P6 N0000");
    EXPECT_EQ(pointer.levelCommand(1), "JSR @1:40");
}

TEST_F(SearchPointerTest, BesJumpsWhateverTheEventAndRecordsAChangedEvent) {
    cursorOn(10);  // BES .SKIP 0:5, event not set
    ASSERT_TRUE(pointer.planePlus().ok);
    ASSERT_EQ(pointer.window().kind, PlaneWindow::Kind::Event);
    EXPECT_EQ(pointer.window().event.process, 0);
    EXPECT_EQ(pointer.window().event.event, 5);
    EXPECT_FALSE(pointer.window().eventSet);
    ASSERT_TRUE(pointer.confirmEvent(true).ok);
    EXPECT_EQ(cursorText(pointer), "P5 N0012");
    ASSERT_EQ(pointer.eventChanges().size(), 1u);
    EXPECT_TRUE(pointer.eventChanges().at(EventRef{0, 5}));
    // Back and again: the window shows the changed state.
    ASSERT_TRUE(pointer.planeMinus().ok);
    ASSERT_TRUE(pointer.planePlus().ok);
    EXPECT_TRUE(pointer.window().eventSet);
    ASSERT_TRUE(pointer.confirmEvent(false).ok);
    EXPECT_TRUE(pointer.eventChanges().empty()) << "back to the cell's state: no change";
}

TEST_F(SearchPointerTest, BevCallsTheLabelInProgram99AfterTheEventWindow) {
    cursorOn(12);  // BEV .TOOL 0:8, event set
    ASSERT_TRUE(pointer.planePlus().ok);
    EXPECT_TRUE(pointer.window().eventSet);
    ASSERT_TRUE(pointer.confirmEvent(true).ok);
    EXPECT_EQ(cursorText(pointer), "P99 N0002");
    EXPECT_TRUE(pointer.current().call);
    EXPECT_TRUE(pointer.eventChanges().empty());
}

TEST_F(SearchPointerTest, JevOpensTheOtherProgramAtN0000) {
    cursorOn(11);  // JEV 6 0:7
    ASSERT_TRUE(pointer.planePlus().ok);
    ASSERT_EQ(pointer.window().kind, PlaneWindow::Kind::Event);
    pointer.cancelWindow();
    EXPECT_EQ(pointer.levels().size(), 1u) << "abort leaves the level";
    ASSERT_TRUE(pointer.planePlus().ok);
    ASSERT_TRUE(pointer.confirmEvent(false).ok);
    EXPECT_EQ(cursorText(pointer), "P6 N0000");
    EXPECT_EQ(pointer.levelCommand(1), "JEV 6 0:7");
}

TEST_F(SearchPointerTest, CursorKeysCloseAnOpenWindow) {
    cursorOn(10);
    ASSERT_TRUE(pointer.planePlus().ok);
    pointer.down();
    EXPECT_EQ(pointer.window().kind, PlaneWindow::Kind::None);
    EXPECT_EQ(code(pointer.confirmEvent(true)), "RESTART_NO_WINDOW");
}

TEST_F(SearchPointerTest, RefusesBlocksWithoutJumpEndOfProgramAndMissingLabels) {
    cursorOn(3);
    EXPECT_EQ(code(pointer.planePlus()), "RESTART_NO_JUMP");
    cursorOn(18);  // BST
    EXPECT_EQ(code(pointer.planePlus()), "RESTART_PROGRAM_END");
    cursorOn(14);  // BRA .NOWHERE
    auto reply = pointer.planePlus();
    EXPECT_EQ(code(reply), "RESTART_LABEL_NOT_FOUND");
    EXPECT_EQ(reply.note->where.program, 5);
    EXPECT_EQ(reply.note->where.block, "N0014");
    EXPECT_EQ(reply.note->where.line, 15);
    EXPECT_EQ(pointer.levels().size(), 1u);
    cursorOn(21);  // RTS
    EXPECT_EQ(code(pointer.planePlus()), "RESTART_NO_JUMP");
}

TEST_F(SearchPointerTest, SelectionIsRefusedInsideACycle) {
    cursorOn(13);  // BSR .*PECK
    auto reply = pointer.planePlus();
    EXPECT_FALSE(reply.ok);
    EXPECT_EQ(code(reply), "RESTART_CYCLE");
    EXPECT_EQ(pointer.levels().size(), 1u);
    EXPECT_EQ(cursorText(pointer), "P5 N0013");
}

TEST_F(SearchPointerTest, JsrToAMissingProgramIsRefused) {
    cell.store.put(0, 10, parsed("N0000 JSR 77\nN0001 M30\n", 10));
    ASSERT_TRUE(pointer.begin(10).ok);
    auto reply = pointer.planePlus();
    EXPECT_EQ(code(reply), "RESTART_PROGRAM_MISSING");
    EXPECT_NE(reply.note->message.find("program 77"), std::string::npos);
}

TEST_F(SearchPointerTest, TenLevelsAtMost) {
    cursorOn(2);
    ASSERT_TRUE(pointer.planePlus().ok);  // level 2: P99 .TOOL
    pointer.down();                       // N0003 .DEEP ... BSR .DEEP
    for (int level = 3; level <= kMaxSearchLevels; ++level) {
        ASSERT_TRUE(pointer.planePlus().ok) << "level " << level;
        EXPECT_EQ(pointer.levels().size(), static_cast<std::size_t>(level));
    }
    auto reply = pointer.planePlus();
    EXPECT_EQ(code(reply), "RESTART_LEVEL_LIMIT");
    EXPECT_EQ(pointer.levels().size(), 10u);
    const AcceptResult accepted = pointer.accept();
    ASSERT_TRUE(accepted.ok);
    EXPECT_EQ(accepted.selection.path.size(), 9u) << "target on the 10th level";
    for (int i = 0; i < 9; ++i)
        ASSERT_TRUE(pointer.planeMinus().ok);
    EXPECT_EQ(cursorText(pointer), "P5 N0002");
}

TEST_F(SearchPointerTest, EachStationHasItsOwnPointer) {
    SearchPointer lathe(cell.store, 1, cell.sources());
    EXPECT_EQ(code(lathe.begin(5)), "RESTART_NO_PROGRAM") << "program 5 is process 0's";
    ASSERT_TRUE(lathe.begin(6).ok);
    lathe.end();
    EXPECT_EQ(cursorText(lathe), "P6 N0002");
    EXPECT_EQ(cursorText(pointer), "P5 N0000");
}

TEST(SearchPointerPrograms, TestProgramsParseWithoutErrors) {
    SearchStore cell;
    for (const auto& [key, program] : cell.store.programs()) {
        EXPECT_FALSE(program->diagnostics.hasErrors())
            << "program " << key.second << ": "
            << (program->diagnostics.empty() ? "" : program->diagnostics.items().front().message);
    }
    EXPECT_EQ(cell.store.cycles().at("PECK")->findLabel("*PECK"), 0);
}
