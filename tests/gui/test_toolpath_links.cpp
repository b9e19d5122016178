// The toolpath view linked to the restart screen and to the program editor
// (docs/decisions/toolpath.md TP-006, TP-007, TP-012), on the 2D view the
// offscreen platform gives: the editor's cursor highlights its block, a pick
// moves the editor's cursor, a pick made outside the restart screen is its
// cursor at the next entry, and the REPOS path has the corners of the demo
// REPOS program.
#include <QLabel>
#include <QPlainTextEdit>

#include "PanelFixture.h"
#include "screens/editor/EditorScreen.h"
#include "screens/editor/NcCodeEdit.h"
#include "screens/restart/RestartController.h"
#include "screens/restart/RestartRun.h"
#include "screens/restart/RestartScreen.h"
#include "screens/toolpath/ToolpathCanvas.h"
#include "screens/toolpath/ToolpathModel.h"
#include "screens/toolpath/ToolpathScreen.h"

using mtc::screens::ToolpathModel;
using mtc::screens::ToolpathScreen;

namespace {

ToolpathScreen* toolpath(PanelFixture& panel) {
    return static_cast<ToolpathScreen*>(panel.window->screen(0, "toolpath"));
}

mtc::screens::NcCodeEdit* editor(PanelFixture& panel) {
    return panel.window->screen(0, "editor")->findChild<mtc::screens::NcCodeEdit*>("programEditor");
}

QString restartStatus(PanelFixture& panel) {
    return panel.window->screen(0, "restart")->findChild<QLabel*>("restartStatus")->text();
}

/// The block of the highlighted moves (all of one block).
std::uint32_t highlightedBlock(ToolpathModel* model) {
    return model->geometry()->moves[model->highlighted().front()].block;
}

/// "N0012" of block `block` of program `number` on station 0.
QString blockId(PanelFixture& panel, int number, std::uint32_t block) {
    return QString::fromStdString(panel.session->program(0, number)->blockId(block));
}

/// Clicks the first segment of a move of a block other than `other` whose
/// block has a source line of its own; returns that move (-1 when none).
long clickAMoveOfAnotherBlock(PanelFixture& panel, std::uint32_t other) {
    ToolpathModel* model = toolpath(panel)->model();
    const auto& g = *model->geometry();
    for (long m = static_cast<long>(g.moves.size()) - 1; m >= 0; --m) {
        const auto& move = g.moves[static_cast<std::size_t>(m)];
        if (move.program != 1 || move.block == other) continue;
        const auto at = toolpath(panel)->canvas()->positionOfMove(m);
        if (!at) continue;
        QTest::mouseClick(toolpath(panel)->canvas(), Qt::LeftButton, {}, *at);
        if (!model->highlighted().empty() && highlightedBlock(model) == move.block) return m;
    }
    return -1;
}

}  // namespace

class ToolpathLinksTest : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { useTestSettings(); }

    void editorCursorHighlightsItsBlockAndAPickMovesTheEditor() {
        PanelFixture panel;
        panel.session->selectProgram(0, 1);
        QVERIFY(panel.window->showScreen("editor"));
        QTRY_VERIFY(!editor(panel)->loading());
        editor(panel)->setFocus();
        for (int i = 0; i < 20; ++i)
            panel.press(Qt::Key_Down);
        const int line = editor(panel)->cursorLine();
        QCOMPARE(line, 21);
        QVERIFY(panel.window->showScreen("toolpath"));
        ToolpathModel* model = toolpath(panel)->model();
        QCOMPARE(model->partnerName(), QString("editor"));
        QVERIFY(toolpath(panel)
                    ->findChild<QLabel*>("toolpathMessage")
                    ->text()
                    .contains("Linked to the editor"));
        // The highlighted block is the one the cursor line belongs to.
        const auto program = panel.session->program(0, 1);
        std::uint32_t expected = 0;
        for (std::uint32_t b = 0; b < program->blocks.size(); ++b)
            if (static_cast<int>(program->blocks[b].line) <= line) expected = b;
        QVERIFY(model->highlightText().startsWith("P1 " + blockId(panel, 1, expected)));
        if (!model->geometry()->movesOfBlock(1, expected).empty())
            QCOMPARE(highlightedBlock(model), expected);

        // A pick in the view: the editor shows that block's line when it is shown again.
        const long picked = clickAMoveOfAnotherBlock(panel, expected);
        QVERIFY(picked >= 0);
        const auto block = model->geometry()->moves[static_cast<std::size_t>(picked)].block;
        QVERIFY(panel.window->showScreen("editor"));
        const int blockLine = static_cast<int>(program->blocks[block].line);
        QTRY_COMPARE(editor(panel)->cursorLine(), blockLine);
        QCOMPARE(editor(panel)->cursorBlockId(), blockId(panel, 1, block));
        // Moving the editor's cursor moves the highlight again (the view is not shown).
        panel.press(Qt::Key_Down);
        const int below = editor(panel)->cursorLine();
        std::uint32_t now = 0;
        for (std::uint32_t b = 0; b < program->blocks.size(); ++b)
            if (static_cast<int>(program->blocks[b].line) <= below) now = b;
        QVERIFY(model->highlightText().startsWith("P1 " + blockId(panel, 1, now)));
    }

    void theLastOfRestartAndEditorShownIsThePartner() {
        PanelFixture panel;
        panel.session->selectProgram(0, 1);
        QVERIFY(panel.window->showScreen("toolpath"));
        ToolpathModel* model = toolpath(panel)->model();
        QCOMPARE(model->partnerName(), QString("restart"));  // before either was shown
        QVERIFY(panel.window->showScreen("editor"));
        QCOMPARE(model->partnerName(), QString("editor"));
        panel.press(Qt::Key_F1, Qt::ShiftModifier);  // M key: NC program restart
        QCOMPARE(panel.window->currentScreenName(), QString("restart"));
        QCOMPARE(model->partnerName(), QString("restart"));
        QVERIFY(panel.window->showScreen("menu"));
        QCOMPARE(model->partnerName(), QString("restart"));  // other screens change nothing
    }

    void aPickOutsideTheRestartScreenIsItsCursorAtTheNextEntryOnly() {
        PanelFixture panel;
        panel.session->selectProgram(0, 1);
        panel.press(Qt::Key_F1, Qt::ShiftModifier);
        QVERIFY(restartStatus(panel).startsWith("Target P1 N0000"));
        QVERIFY(panel.window->showScreen("toolpath"));
        ToolpathModel* model = toolpath(panel)->model();
        for (int i = 0; i < 5; ++i)
            panel.press(Qt::Key_PageDown);
        const std::uint32_t picked = highlightedBlock(model);
        QVERIFY(picked > 0);
        const QString target = "Target P1 " + blockId(panel, 1, picked);
        // Re-entry: a new selection (runs 1, seed 000 2.6) on the picked block.
        panel.press(Qt::Key_F1, Qt::ShiftModifier);
        QCOMPARE(panel.window->currentScreenName(), QString("restart"));
        QVERIFY2(restartStatus(panel).startsWith(target), qPrintable(restartStatus(panel)));
        QVERIFY(restartStatus(panel).endsWith("runs 1"));
        QCOMPARE(highlightedBlock(model), picked);
        // The pick was used by that entry: the next one starts on N0000.
        panel.press(Qt::Key_Escape);
        panel.press(Qt::Key_F1, Qt::ShiftModifier);
        QVERIFY(restartStatus(panel).startsWith("Target P1 N0000"));
        // A pick before the restart screen was ever entered works the same.
        PanelFixture fresh;
        fresh.session->selectProgram(0, 1);
        QVERIFY(fresh.window->showScreen("toolpath"));
        fresh.press(Qt::Key_PageDown);
        fresh.press(Qt::Key_PageDown);
        const std::uint32_t early = highlightedBlock(toolpath(fresh)->model());
        fresh.press(Qt::Key_F1, Qt::ShiftModifier);
        QVERIFY(restartStatus(fresh).startsWith("Target P1 " + blockId(fresh, 1, early)));
    }

    void reposPathHasTheCornersOfTheDemoReposProgram() {
        PanelFixture panel;
        panel.session->selectProgram(0, 1);
        panel.press(Qt::Key_F1, Qt::ShiftModifier);
        for (int i = 0; i < 6; ++i)
            panel.press(Qt::Key_Down);
        auto* controller =
            static_cast<mtc::screens::RestartScreen*>(panel.window->screen(0, "restart"))
                ->controller();
        panel.press(Qt::Key_Return);
        QVERIFY2(controller->run()->started(), qPrintable(controller->message().text));
        QTRY_COMPARE(controller->run()->phase(), mtc::core::RestartPhase::TargetReached);
        QVERIFY(panel.window->showScreen("toolpath"));
        const auto marks = toolpath(panel)->model()->marks();
        QVERIFY(marks.hasReentry);
        QVERIFY(marks.hasRepos);
        // Where the axes stand, ADJUST's tool change height (G53 G0 Z90 in
        // .M6), then REPOS of the G17 plane: X and Y first, Z last.
        const auto& path = marks.repos;
        QVERIFY2(path.size() >= 3, qPrintable(QString::number(path.size())));
        const auto& last = path[path.size() - 1];
        const auto& planeFirst = path[path.size() - 2];
        for (int a = 0; a < 3; ++a)
            QVERIFY(qAbs(last[a] - marks.reentry[a]) < 1e-9);
        QVERIFY(qAbs(planeFirst[0] - marks.reentry[0]) < 1e-9);
        QVERIFY(qAbs(planeFirst[1] - marks.reentry[1]) < 1e-9);
        QVERIFY(qAbs(planeFirst[2] - 90.0) < 1e-9);
        const auto& cleared = path[path.size() - 3];
        QVERIFY(qAbs(cleared[2] - 90.0) < 1e-9);
        for (int a = 0; a < 3; ++a)
            QVERIFY(qAbs(path.front()[a] - marks.actual[a]) < 1e-9);
        // The 2D view draws it (cyan polyline).
        const QImage picture = toolpath(panel)->canvas()->picture();
        const QColor cyan = toolpath(panel)->model()->palette().repos;
        int n = 0;
        const QImage rgb = picture.convertToFormat(QImage::Format_RGB32);
        for (int y = 0; y < rgb.height(); ++y)
            for (int x = 0; x < rgb.width(); ++x)
                n += QColor(rgb.pixel(x, y)).rgb() == cyan.rgb();
        QVERIFY(n > 10);
    }
};

QTEST_MAIN(ToolpathLinksTest)
#include "test_toolpath_links.moc"
