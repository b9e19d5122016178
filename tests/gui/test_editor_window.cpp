// The program editor's window over a large program (decision ED-009): a
// 200,000-block program is opened, driven with real keys across the window
// borders, edited at both ends, saved and compared with the file; the error
// window's Enter and the scroll bar reach lines far outside the window.
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QRandomGenerator>
#include <QScrollBar>
#include <QTemporaryDir>
#include <QTextBlock>
#include <QWheelEvent>
#include <memory>

#include "PanelFixture.h"
#include "screens/editor/EditorScreen.h"
#include "screens/editor/LineStore.h"
#include "screens/editor/NcCodeEdit.h"
#include "screens/editor/NcHighlighter.h"
#include "screens/runtime/RuntimeScreen.h"

namespace {

using mtc::screens::NcCodeEdit;

constexpr int kBlocks = 200000;
constexpr int kHeaderLines = 10;
/// 1-based line of the faulty macro definition (far from the window at line 1).
constexpr int kFaultyLine = kHeaderLines + 150001;

/// Program 9: kBlocks moves, a macro definition at the start and a faulty one far
/// below.
QString largeProgram() {
    QString body;
    body.reserve(26 * kBlocks);
    for (int i = 0; i < kBlocks; ++i) {
        const QString number = QString("N%1 ").arg(i % 10000, 4, 10, QChar('0'));
        if (i == 1)
            body += number + "DEFINE SAFE AS G0 Z50\n";  // a compiler keyword
        else if (i == kFaultyLine - kHeaderLines - 1)
            body += number + "DEFINE 9BAD AS G1 X0\n";
        else
            body += number + QString("G1 X%1 Y%2 F1000\n").arg(i % 97).arg(i % 89);
    }
    return programHeader(9, "Large") + body;
}

/// Program 10: moves after a good macro definition (compiles).
QString compilableProgram() {
    QString body = "N0000 DEFINE SAFE AS G0 Z50\n";
    body.reserve(26 * kBlocks);
    for (int i = 1; i < kBlocks; ++i)
        body += QString("N%1 G1 X%2 Y%3 F1000\n")
                    .arg(i % 10000, 4, 10, QChar('0'))
                    .arg(i % 97)
                    .arg(i % 89);
    return body + "N9999 SAFE\n";
}

/// The 1-based line `line` of `text`.
QString lineOf(const QString& text, int line) {
    int start = 0;
    for (int i = 1; i < line; ++i)
        start = text.indexOf('\n', start) + 1;
    const int end = text.indexOf('\n', start);
    return text.mid(start, end < 0 ? -1 : end - start);
}

}  // namespace

class EditorWindowTest : public QObject {
    Q_OBJECT
  private:
    QTemporaryDir dir_;
    QString original_;

    NcCodeEdit* openLarge(PanelFixture& panel) {
        panel.session->selectProgram(0, 9);
        if (!panel.window->showScreen("editor")) return nullptr;
        auto* edit = child<NcCodeEdit>(panel, "editor", "programEditor");
        edit->setFocus();
        return edit;
    }

    mtc::hmi::PanelOptions options() {
        // Every case starts with the compiler off (F6 toggles the cell's
        // NC options, which a compile case leaves in the directory).
        QFile::remove(QDir(dir_.path()).filePath("NC_OPTIONS.CFG"));
        mtc::hmi::PanelOptions o;
        o.programsDir = dir_.path();
        return o;
    }

    QString statusText(PanelFixture& panel) {
        return child<QLabel>(panel, "editor", "editorStatus")->text();
    }

  private slots:
    void initTestCase() {
        useTestSettings();
        original_ = largeProgram();
        writeProgram(emptiedDirectory(dir_.path()), 9, original_);
    }

    void lineStoreSplicesLikeAList() {
        // Random replacements against a QStringList (the reference).
        QStringList reference;
        for (int i = 0; i < 300; ++i)
            reference << QString("line %1 \u00e4").arg(i);
        reference << "";
        mtc::screens::LineStore store(reference.join('\n').toStdString());
        QCOMPARE(store.count(), reference.size());
        QRandomGenerator random(7);
        for (int round = 0; round < 200; ++round) {
            const int first = random.bounded(reference.size());
            const int lines = 1 + random.bounded(std::min(20, reference.size() - first));
            QStringList fresh;
            for (int k = random.bounded(4); k >= 0; --k)
                fresh << (random.bounded(3) == 0 ? QString()
                                                 : QString("new %1.%2").arg(round).arg(k));
            QCOMPARE(store.text(first, lines), reference.mid(first, lines).join('\n'));
            store.replace(first, lines, fresh.join('\n'));
            for (int k = 0; k < lines; ++k)
                reference.removeAt(first);
            for (int k = 0; k < fresh.size(); ++k)
                reference.insert(first + k, fresh[k]);
            QCOMPARE(store.count(), reference.size());
        }
        QCOMPARE(QString::fromStdString(store.whole()), reference.join('\n'));
        QCOMPARE(store.text(store.count() - 1, 5), reference.last());
        QCOMPARE(mtc::screens::LineStore("").count(), 1);
    }

    void smallProgramsAreNotWindowed() {
        PanelFixture panel(options());
        NcCodeEdit* edit = openLarge(panel);  // a large one first: the editor goes back
        QVERIFY(edit && edit->windowed());
        panel.session->addProgram(0, 31, "small.nc", "N0000 G1 X1 F100\nN0001 M30\n");
        pickProgram(panel, 31);
        panel.press(Qt::Key_F2);  // Edit
        QCOMPARE(panel.window->currentScreenName(), QString("editor"));
        QVERIFY(!edit->windowed());
        QCOMPARE(edit->windowStart(), 0);
        QCOMPARE(edit->toPlainText(), QString("N0000 G1 X1 F100\nN0001 M30\n"));
        QVERIFY(edit->verticalScrollBarPolicy() == Qt::ScrollBarAsNeeded);
        QVERIFY(!edit->wholeScrollBar());
        QCOMPARE(edit->lineCount(), 3);
        QCOMPARE(edit->blockCount(), 3);
    }

    void keysCrossTheWindowBorders() {
        PanelFixture panel(options());
        QElapsedTimer clock;
        clock.start();
        NcCodeEdit* edit = openLarge(panel);
        QVERIFY(edit);
        const qint64 openMs = clock.elapsed();
        const int lines = kHeaderLines + kBlocks + 1;
        QVERIFY(edit->windowed());
        QVERIFY(edit->blockCount() <= NcCodeEdit::kWindowLines);
        QCOMPARE(edit->lineCount(), lines);
        QCOMPARE(edit->cursorLine(), 1);
        QVERIFY(edit->textCursor().block().userState() == mtc::screens::kHighlighted);

        clock.restart();
        panel.press(Qt::Key_End, Qt::ControlModifier);
        const qint64 endMs = clock.elapsed();
        QCOMPARE(edit->cursorLine(), lines);
        QVERIFY(edit->windowStart() > 0);
        QVERIFY2(statusText(panel).startsWith(QString("Line %1 of %1").arg(lines)),
                 qPrintable(statusText(panel)));
        QCOMPARE(edit->wholeScrollBar()->value(), edit->wholeScrollBar()->maximum());
        panel.press(Qt::Key_Up);
        QCOMPARE(edit->textCursor().block().text(), lineOf(original_, lines - 1));
        QTRY_VERIFY(edit->textCursor().block().userState() == mtc::screens::kHighlighted);
        QCOMPARE(edit->cursorBlockId(), QString("N9999"));

        // PgUp until the window has moved twice: every stop shows its line.
        const int firstWindow = edit->windowStart();
        int moves = 0;
        qint64 slowestPageMs = 0;
        for (int presses = 0; moves < 2 && presses < 400; ++presses) {
            const int before = edit->windowStart();
            clock.restart();
            panel.press(Qt::Key_PageUp);
            slowestPageMs = std::max(slowestPageMs, clock.elapsed());
            if (edit->windowStart() != before) ++moves;
            QCOMPARE(edit->textCursor().block().text(), lineOf(original_, edit->cursorLine()));
            const QTextBlock visible = edit->cursorForPosition(QPoint(1, 1)).block();
            QVERIFY(visible.blockNumber() <= edit->textCursor().blockNumber());
        }
        QCOMPARE(moves, 2);
        QVERIFY(edit->windowStart() < firstWindow);
        QCOMPARE(edit->wholeScrollBar()->value(),
                 edit->windowStart() + edit->verticalScrollBar()->value());
        // And PgDn back to the end.
        for (int presses = 0; edit->cursorLine() < lines && presses < 400; ++presses)
            panel.press(Qt::Key_PageDown);
        QCOMPARE(edit->cursorLine(), lines);
        // A selection across a window move keeps its anchor (while the anchor
        // is in the window: it starts about 700 lines above the window's end).
        while (edit->textCursor().blockNumber() > edit->document()->blockCount() - 700)
            panel.press(Qt::Key_PageUp);
        const int from = edit->cursorLine();
        const int window = edit->windowStart();
        for (int presses = 0; edit->windowStart() == window && presses < 400; ++presses)
            panel.press(Qt::Key_PageUp, Qt::ShiftModifier);
        QVERIFY(edit->windowStart() < window);
        QCOMPARE(edit->textCursor().selectedText().count(QChar::ParagraphSeparator),
                 from - edit->cursorLine());
        qInfo("200,000 blocks: open %lld ms, Ctrl+End %lld ms, slowest PgUp %lld ms", openMs, endMs,
              slowestPageMs);
    }

    void editsAtBothEndsAreSavedWhole() {
        PanelFixture panel(options());
        NcCodeEdit* edit = openLarge(panel);
        QVERIFY(edit);
        auto* heading = child<QLabel>(panel, "editor", "editorHeading");
        // Near the end: text appended to the last block.
        panel.press(Qt::Key_End, Qt::ControlModifier);
        panel.press(Qt::Key_Up);
        panel.press(Qt::Key_End);
        QElapsedTimer clock;
        clock.start();
        QTest::keyClicks(edit, " ;done");
        const qint64 typingMs = clock.elapsed();
        QVERIFY(heading->text().contains("modified"));
        // Far away (the window moves, the edit is kept): a new block after the header.
        panel.press(Qt::Key_Home, Qt::ControlModifier);
        QVERIFY(heading->text().contains("modified"));
        for (int i = 0; i < kHeaderLines; ++i)
            panel.press(Qt::Key_Down);
        QTest::keyClicks(edit, "N0000 M0");
        panel.press(Qt::Key_Return);
        panel.press(Qt::Key_Backspace);  // the Return, undone by hand
        panel.press(Qt::Key_Return);
        const int lines = kHeaderLines + kBlocks + 2;
        QCOMPARE(edit->lineCount(), lines);
        panel.press(Qt::Key_End, Qt::ControlModifier);
        QCOMPARE(edit->cursorLine(), lines);
        panel.press(Qt::Key_Up);
        QVERIFY(edit->textCursor().block().text().endsWith(" ;done"));

        clock.restart();
        panel.press(Qt::Key_S, Qt::ControlModifier);
        const qint64 saveMs = clock.elapsed();
        QVERIFY2(!heading->text().contains("modified"), qPrintable(heading->text()));
        QString expected = original_;
        expected.insert(expected.size() - 1, " ;done");
        const int afterHeader = expected.indexOf("N0000 G1");
        expected.insert(afterHeader, "N0000 M0\n");
        QFile saved(QDir(dir_.path()).filePath("N1010009.DAT"));
        QVERIFY(saved.open(QIODevice::ReadOnly));
        QVERIFY(saved.readAll() == expected.toUtf8());  // complete, byte for byte
        QVERIFY(panel.session->program(0, 9)->source == expected.toStdString());
        qInfo("6 typed characters %lld ms, Save %lld ms", typingMs, saveMs);
        writeProgram(QDir(dir_.path()), 9, original_);  // for the next test cases
    }

    void aLargeDeleteInTheWindowLeavesTheRestReachable() {
        PanelFixture panel(options());
        NcCodeEdit* edit = openLarge(panel);
        QVERIFY(edit);
        panel.press(Qt::Key_A, Qt::ControlModifier);  // Select all: not offered while windowed
        QVERIFY(!edit->textCursor().hasSelection());
        std::unique_ptr<QMenu> menu(edit->contextMenu(QPoint(5, 5)));
        int selectAll = 0;
        for (QAction* action : menu->actions())
            if (action->objectName() == "select-all") selectAll += action->isEnabled() ? 10 : 1;
        QCOMPARE(selectAll, 1);                // there, and disabled
        QTextCursor all = edit->textCursor();  // the whole window, as a long selection would
        all.select(QTextCursor::Document);
        edit->setTextCursor(all);
        panel.press(Qt::Key_Delete);
        const int lines = kHeaderLines + kBlocks + 1 - NcCodeEdit::kWindowLines + 1;
        QCOMPARE(edit->lineCount(), lines);
        panel.press(Qt::Key_Down);
        QCOMPARE(edit->cursorLine(), 2);
        QCOMPARE(edit->textCursor().block().text(),
                 lineOf(original_, NcCodeEdit::kWindowLines + 1));
        panel.press(Qt::Key_End, Qt::ControlModifier);
        QCOMPARE(edit->cursorLine(), lines);
    }

    void errorWindowEnterAndScrollBarReachFarLines() {
        PanelFixture panel(options());
        pickProgram(panel, 9);
        auto* listing = child<NcCodeEdit>(panel, "programs", "programListing");
        QVERIFY(listing->windowed());  // the directory's listing shows it at once too
        QCOMPARE(listing->lineCount(), kHeaderLines + kBlocks + 1);
        panel.press(Qt::Key_F6);  // Compiler active = Yes
        panel.press(Qt::Key_F3);  // Compile: the faulty definition at kFaultyLine
        QVERIFY2(directoryRow(panel, 9).contains("[E]"),
                 qPrintable(child<QLabel>(panel, "programs", "programsMessage")->text()));
        panel.window->showScreen("errors");
        auto* list = child<QListWidget>(panel, "errors", "errorList");
        QVERIFY(list->count() >= 1);
        list->setCurrentRow(0);
        QVERIFY2(list->currentItem()->text().contains("N0000"),
                 qPrintable(list->currentItem()->text()));
        panel.press(Qt::Key_Return);
        QCOMPARE(panel.window->currentScreenName(), QString("editor"));
        auto* edit = child<NcCodeEdit>(panel, "editor", "programEditor");
        QCOMPARE(edit->cursorLine(), kFaultyLine);
        QVERIFY(edit->textCursor().block().text().contains("DEFINE 9BAD"));
        QVERIFY(edit->windowStart() > 0);
        QVERIFY(statusText(panel).startsWith(QString("Line %1 ").arg(kFaultyLine)));

        // The scroll bar over the whole program: to line 20,001 and back to the top.
        QScrollBar* bar = edit->wholeScrollBar();
        QVERIFY(bar && bar->isVisible());
        QCOMPARE(bar->maximum() + bar->pageStep() >= edit->lineCount() - 1, true);
        bar->setValue(20000);
        QTRY_COMPARE(edit->windowStart() + edit->cursorForPosition(QPoint(1, 1)).blockNumber(),
                     20000);
        QVERIFY(qAbs(edit->cursorLine() - 20001) < NcCodeEdit::kWindowLines);
        QCOMPARE(edit->cursorForPosition(QPoint(1, 1)).block().text(), lineOf(original_, 20001));
        // The mouse wheel through two windows (15 lines a turn, 150 turns).
        auto topLine = [edit] {
            return edit->windowStart() + edit->cursorForPosition(QPoint(1, 1)).blockNumber() + 1;
        };
        const int before = topLine();
        for (int turn = 0; turn < 150; ++turn) {
            const QPoint at(20, 20);
            QWheelEvent wheel(at, edit->viewport()->mapToGlobal(at), QPoint(), QPoint(0, -120 * 5),
                              Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
            QApplication::sendEvent(edit->viewport(), &wheel);
            QApplication::processEvents();
        }
        QTRY_COMPARE(topLine(), before + 150 * 15);
        QVERIFY(edit->windowStart() > 20000);
        QCOMPARE(edit->cursorForPosition(QPoint(1, 1)).block().text(),
                 lineOf(original_, topLine()));
        QCOMPARE(bar->value(), topLine() - 1);
        bar->setValue(0);
        QTRY_COMPARE(edit->windowStart(), 0);
        QCOMPARE(edit->cursorForPosition(QPoint(1, 1)).blockNumber(), 0);
    }

    void runtimeViewFollowsAcrossWindows() {
        PanelFixture panel(options());
        // Not a .DAT file: no 10,000-line limit of the object file (seed 001 ch. 11).
        panel.session->addProgram(0, 10, "large.nc", compilableProgram().toStdString());
        pickProgram(panel, 10);
        panel.press(Qt::Key_F6);  // Compiler active = Yes
        panel.press(Qt::Key_F3);  // Compile
        if (!directoryRow(panel, 10).contains("[C]")) {
            panel.window->showScreen("errors");
            QFAIL(qPrintable(child<QListWidget>(panel, "errors", "errorList")->item(0)->text()));
        }
        panel.session->selectProgram(0, 10);
        QVERIFY(panel.window->showScreen("runtime"));
        auto* source = child<NcCodeEdit>(panel, "runtime", "runtimeSource");
        auto* compiled = child<NcCodeEdit>(panel, "runtime", "runtimeCompiled");
        QVERIFY(source->windowed() && compiled->windowed());
        compiled->setFocus();
        const auto* screen =
            qobject_cast<mtc::screens::RuntimeScreen*>(panel.window->currentScreen());
        // Far down the compiled program: the source's window follows its line.
        panel.press(Qt::Key_End, Qt::ControlModifier);
        for (int i = 0; i < 40; ++i)
            panel.press(Qt::Key_PageUp);
        const int row = compiled->cursorLine() - 1;
        const int line = screen->listing().sourceLine[row];
        QVERIFY(line > 150000);
        QCOMPARE(source->cursorLine(), line);
        QVERIFY(source->windowStart() > 0);
        const QString block = source->textCursor().block().text().section(' ', 0, 0);
        QVERIFY2(compiled->textCursor().block().text().contains(block + ":"),
                 qPrintable(compiled->textCursor().block().text() + " / " + block));
        QCOMPARE(source->extraSelections().size(), 1);
    }
};

QTEST_MAIN(EditorWindowTest)
#include "test_editor_window.moc"
