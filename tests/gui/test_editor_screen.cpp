// Program directory with N/C/E, program editor, error window and runtime
// view (seed 001 ch. 1, 7, 9-11), driven with real keys.
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QLabel>
#include <QListView>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QTemporaryDir>
#include <QTextBlock>
#include <cmath>

#include "PanelFixture.h"
#include "hmi/ErrorLog.h"
#include "hmi/ProgramWorkspace.h"
#include "screens/editor/EditorScreen.h"
#include "screens/editor/NcCodeEdit.h"
#include "screens/editor/NcHighlighter.h"
#include "screens/errors/ErrorsScreen.h"
#include "screens/programs/ProgramDirectoryModel.h"
#include "screens/runtime/RuntimeScreen.h"
#include "screens/runtime/VelocityPlot.h"

namespace {

/// Source lines 11.. after the 10 header lines.
const char* kMacroProgram =
    "N0000 G0 G17 G90 X0 Y0 Z5\n"
    "N0001 DEFINE SAFE AS G0 Z50\n"
    "N0002 G1 X10 F500\n"
    "N0003 DEFINE 9BAD AS G1 X0 ;line 14\n"
    "N0004 SAFE\n"
    "N0005 M30\n"
    "N0006 PROGRAMMENDE\n";

const char* kPlainProgram = "N0000 G0 X0 Y0 Z5\nN0001 M30\nN0002 PROGRAMMENDE\n";

const char* kChamferProgram =
    "N0000 G0 G17 G90 X0 Y0 Z5\n"
    "N0001 G1 Z-1 F400\n"
    "N0002 G1 X20 Y0 CF3\n"
    "N0003 G1 X20 Y20 RD4\n"
    "N0004 G1 X0 Y20\n"
    "N0005 M30\n"
    "N0006 PROGRAMMENDE\n";

/// A closed polygon with a look-ahead segment (I/J: absolute centre).
const char* kLookAheadProgram =
    "N0000 G0 G17 G90 X0 Y0 Z0\n"
    "N0001 G1 F6000\n"
    "N0002 LA_ON\n"
    "N0003 G1 X40 Y0\n"
    "N0004 G1 X40 Y20\n"
    "N0005 G3 X20 Y40 I20 J20\n"
    "N0006 G1 X0 Y40\n"
    "N0007 G1 X0 Y0\n"
    "N0008 LA_OFF\n"
    "N0009 M30\n"
    "N0010 PROGRAMMENDE\n";

/// A chamfer (compiler) in a contour milled with G42 (tool T1, radius 3.5):
/// the seed 001 ch. 1 example in our own numbers.
const char* kCompensatedProgram =
    "N0000 T1 G0 G17 G90 X-10 Y-10 Z5\n"
    "N0001 G1 Z-1 F400\n"
    "N0002 G42 X0 Y0\n"
    "N0003 X20 CF3\n"
    "N0004 Y20\n"
    "N0005 G40 X30 Y30\n"
    "N0006 M30\n"
    "N0007 PROGRAMMENDE\n";

}  // namespace

class EditorScreenTest : public QObject {
    Q_OBJECT
  private:
    QTemporaryDir dir_;

    mtc::hmi::PanelOptions options() {
        const QDir dir = emptiedDirectory(dir_.path());
        writeProgram(dir, 5, programHeader(5, "Macro test") + kMacroProgram);
        writeProgram(dir, 6, programHeader(6, "No keyword") + kPlainProgram);
        writeProgram(dir, 7, programHeader(7, "Chamfer test") + kChamferProgram);
        writeProgram(dir, 8, programHeader(8, "Look-ahead test") + kLookAheadProgram);
        writeProgram(dir, 10, programHeader(10, "Compensated chamfer") + kCompensatedProgram);
        mtc::hmi::PanelOptions o;
        o.programsDir = dir_.path();
        return o;
    }

  private slots:
    void initTestCase() { useTestSettings(); }

    void compileFromTheEditorAndEnterLandsOnTheFaultyLine() {
        PanelFixture panel(options());
        pickProgram(panel, 5);
        QVERIFY(directoryRow(panel, 5).contains("[N]"));
        panel.press(Qt::Key_F6);  // NC options: Compiler active = Yes
        panel.press(Qt::Key_F2);  // Edit
        QCOMPARE(panel.window->currentScreenName(), QString("editor"));
        auto* edit = child<QPlainTextEdit>(panel, "editor", "programEditor");
        QVERIFY(edit->toPlainText().startsWith("iMTc/"));
        QCOMPARE(QApplication::focusWidget(), edit);

        panel.press(Qt::Key_F2);  // Compile
        auto* heading = child<QLabel>(panel, "editor", "editorHeading");
        QTRY_VERIFY2(heading->text().contains("[E]"), qPrintable(heading->text()));
        QVERIFY(QFile::exists(QDir(dir_.path()).filePath("N1010005.ERR")));
        QVERIFY(!QFile::exists(QDir(dir_.path()).filePath("N1010005.NCO")));

        panel.press(Qt::Key_E, Qt::ControlModifier);  // error display
        QCOMPARE(panel.window->currentScreenName(), QString("errors"));
        auto* list = child<QListWidget>(panel, "errors", "errorList");
        QVERIFY(list->count() >= 1);
        QCOMPARE(list->currentRow(), 0);
        const QString brief = list->currentItem()->text();
        QVERIFY2(brief.contains("compiler") && brief.contains("N0003"), qPrintable(brief));
        QVERIFY(!brief.contains('\n'));
        panel.press(Qt::Key_F2);  // <Additional text>
        QVERIFY(list->currentItem()->text().contains("\n"));
        QVERIFY(list->currentItem()->text().contains("letter"));
        panel.press(Qt::Key_F2);  // and off again
        QVERIFY(!list->currentItem()->text().contains('\n'));

        panel.press(Qt::Key_Return);  // to the faulty block
        QCOMPARE(panel.window->currentScreenName(), QString("editor"));
        QCOMPARE(edit->textCursor().blockNumber() + 1, 14);
        QVERIFY(edit->textCursor().block().text().startsWith("N0003 DEFINE 9BAD"));
        auto* status = child<QLabel>(panel, "editor", "editorStatus");
        QVERIFY2(status->text().contains("Line 14") && status->text().contains("N0003"),
                 qPrintable(status->text()));

        // Fix it with keys: delete the '9' of the macro name, compile again.
        for (int i = 0; i < 13; ++i)
            panel.press(Qt::Key_Right);
        panel.press(Qt::Key_Delete);
        QVERIFY(heading->text().contains("modified"));
        panel.press(Qt::Key_F2);  // Compile saves first
        QTRY_VERIFY2(heading->text().contains("[C]"), qPrintable(heading->text()));
        QVERIFY(!heading->text().contains("modified"));
        QFile saved(QDir(dir_.path()).filePath("N1010005.DAT"));
        QVERIFY(saved.open(QIODevice::ReadOnly));
        QVERIFY(saved.readAll().contains("N0003 DEFINE BAD AS G1 X0"));
        QVERIFY(QFile::exists(QDir(dir_.path()).filePath("N1010005.NCO")));
        QVERIFY(!QFile::exists(QDir(dir_.path()).filePath("N1010005.ERR")));
        const auto program = panel.session->program(0, 5);
        QVERIFY(program->source.view().find("DEFINE BAD AS") != std::string::npos);
        QCOMPARE(list->count(), 0);  // the compiler's messages of program 5 are gone
    }

    void directoryShowsTheStatusBits() {
        PanelFixture panel(options());
        pickProgram(panel, 7);
        QVERIFY(directoryRow(panel, 6).contains("[ ]"));  // no keyword
        QVERIFY(directoryRow(panel, 7).contains("[N]"));
        panel.press(Qt::Key_F3);  // Compile: not offered while the compiler is off
        QVERIFY(directoryRow(panel, 7).contains("[N]"));
        panel.press(Qt::Key_F6);  // Compiler active = Yes
        panel.press(Qt::Key_F3);  // Compile
        QTRY_VERIFY2(directoryRow(panel, 7).contains("[C]"), qPrintable(directoryRow(panel, 7)));
        pickProgram(panel, 5);
        panel.press(Qt::Key_F3);
        QTRY_VERIFY2(directoryRow(panel, 5).contains("[E]"), qPrintable(directoryRow(panel, 5)));
        QVERIFY(directoryRow(panel, 6).contains("[ ]"));
        // Changing the compiler setting clears every object (seed 001 ch. 11).
        panel.press(Qt::Key_F6);
        QVERIFY(directoryRow(panel, 7).contains("[N]"));
        QVERIFY(!QFile::exists(QDir(dir_.path()).filePath("N1010007.NCO")));
    }

    void runtimeViewNumbersTheCompilersBlocks() {
        PanelFixture panel(options());
        pickProgram(panel, 7);
        panel.press(Qt::Key_F6);
        panel.press(Qt::Key_F3);
        QTRY_VERIFY(directoryRow(panel, 7).contains("[C]"));
        panel.press(Qt::Key_F4);  // Runtime program
        QCOMPARE(panel.window->currentScreenName(), QString("runtime"));
        auto* screen = qobject_cast<mtc::screens::RuntimeScreen*>(panel.window->currentScreen());
        auto* compiled = child<QPlainTextEdit>(panel, "runtime", "runtimeCompiled");
        auto* source = child<QPlainTextEdit>(panel, "runtime", "runtimeSource");
        QVERIFY(source->toPlainText().contains("CF3"));
        const QStringList lines = compiled->toPlainText().split('\n');
        QVERIFY(screen->listing().intermediateBlocks >= 2);  // chamfer and rounding
        // Seed 001 ch. 1: the compiler's intermediate blocks keep their
        // enhanced numbers; the arrow belongs to the blocks the control
        // inserts while it runs (tool compensation), none here.
        int numbered = 0;
        for (const QString& line : lines) {
            if (line.startsWith("  N0002:0001") || line.startsWith("  N0003:0001")) ++numbered;
            QVERIFY2(!line.startsWith(mtc::screens::kIntermediateArrow), qPrintable(line));
        }
        QCOMPARE(numbered, 2);
        QCOMPARE(screen->listing().insertedBlocks, 0);
        QVERIFY(lines.contains("  N0000:0000 G0 G17 G90 X0 Y0 Z5"));
        // Down through the compiled program: the source line follows.
        const int arrowRow = lines.indexOf(QRegularExpression("^  N0002:0001.*"));
        QVERIFY(arrowRow > 0);
        for (int i = 0; i < arrowRow; ++i)
            panel.press(Qt::Key_Down);
        QCOMPARE(compiled->textCursor().blockNumber(), arrowRow);
        QVERIFY2(source->textCursor().block().text().startsWith("N0002"),
                 qPrintable(source->textCursor().block().text()));
    }

    void runtimeViewMarksTheBlocksCompensationInsertsWithArrows() {
        PanelFixture panel(options());
        pickProgram(panel, 10);
        panel.press(Qt::Key_F6);
        panel.press(Qt::Key_F3);
        QTRY_VERIFY2(directoryRow(panel, 10).contains("[C]"), qPrintable(directoryRow(panel, 10)));
        panel.press(Qt::Key_F4);  // Runtime program
        auto* screen = qobject_cast<mtc::screens::RuntimeScreen*>(panel.window->currentScreen());
        QVERIFY(screen);
        const QStringList lines =
            child<QPlainTextEdit>(panel, "runtime", "runtimeCompiled")->toPlainText().split('\n');
        // Seed 001 ch. 1: "N0053:0000 ... / -> G2 ... / N0053:0001 ... / -> G2 ...":
        // the outside corners before and after the chamfer get an arc each.
        const QString arrow = mtc::screens::kIntermediateArrow + QString(10, ' ');
        const int first = lines.indexOf(QRegularExpression("^  N0003:0000 .*"));
        const int second = lines.indexOf(QRegularExpression("^  N0003:0001 .*"));
        QVERIFY2(first > 0 && second == first + 2, qPrintable(lines.join('\n')));
        QCOMPARE(lines[first + 1], arrow + "G3 X19.4749 Y-2.4749 I17 J0");
        QCOMPARE(lines[second + 1], arrow + "G3 X23.5 Y3 I20 J3");
        QCOMPARE(screen->listing().insertedBlocks, 2);
        QVERIFY(screen->listing().inserted[first + 1]);
        QVERIFY(!screen->listing().inserted[first]);
        QVERIFY2(
            child<QLabel>(panel, "runtime", "runtimeNote")->text().contains("tool compensation"),
            qPrintable(child<QLabel>(panel, "runtime", "runtimeNote")->text()));
    }

    void runtimeViewOfAProgramWithoutCompilerKeywordsShowsTheArrowsToo() {
        PanelFixture panel(options());
        panel.session->addProgram(0, 22, "comp.nc",
                                  "N0000 T1 G0 G17 G90 X-10 Y0 Z5\nN0001 G41 G1 X0 Y0 F300\n"
                                  "N0002 Y20\nN0003 X20\nN0004 G40 X30 Y30\nN0005 M30\n");
        QVERIFY(panel.session->selectProgram(0, 22));
        panel.window->showScreen("runtime");
        const QStringList lines =
            child<QPlainTextEdit>(panel, "runtime", "runtimeCompiled")->toPlainText().split('\n');
        // G41 (tool left, 3.5): at (0, 20) the contour turns right, an outside corner.
        const int row = lines.indexOf("  N0002 Y20");
        QVERIFY2(row >= 0, qPrintable(lines.join('\n')));
        QCOMPARE(lines[row + 1],
                 mtc::screens::kIntermediateArrow + QString(10, ' ') + "G2 X0 Y23.5 I0 J20");
        QCOMPARE(lines[row + 2], QString("  N0003 X20"));
    }

    void runtimeViewPlotsTheLookAheadProfile() {
        PanelFixture panel(options());
        pickProgram(panel, 8);
        panel.press(Qt::Key_F6);
        panel.press(Qt::Key_F3);
        QTRY_VERIFY2(directoryRow(panel, 8).contains("[C]"), qPrintable(directoryRow(panel, 8)));
        panel.press(Qt::Key_F4);
        auto* screen = qobject_cast<mtc::screens::RuntimeScreen*>(panel.window->currentScreen());
        QVERIFY(screen);
        const auto& segment = screen->plot()->segment();
        QVERIFY(!segment.curve.empty());
        QCOMPARE(segment.sourceLine, 14);  // N0003, the first motion of the segment
        QCOMPARE(int(segment.blockStarts.size()), segment.blocks);
        QVERIFY(segment.blocks > 5);             // ramps split the five motions into sub-blocks
        QCOMPARE(segment.curve.front().v, 0.0);  // from rest ...
        QVERIFY(std::abs(segment.curve.back().v) < 1e-6);  // ... to rest
        for (const auto& p : segment.curve)
            QVERIFY(p.v <= 6000.0 + 1e-6);  // never above the programmed F
        QVERIFY(segment.length > 2 * 40 + 2 * 20);
        QVERIFY(screen->listing().intermediateBlocks > 0);
        QVERIFY(!screen->plot()->grab().isNull());
    }

    void aRuntimeErrorAppearsInTheErrorWindow() {
        PanelFixture panel(options());
        panel.session->addProgram(0, 51, "bad.nc", "N0001 G1 X10 F100\nN0002 T999\nN0003 M30\n");
        QVERIFY(panel.session->selectProgram(0, 51));
        panel.session->setSpeed(1000);
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start
        QTRY_VERIFY(!panel.session->control(0).programActive());
        panel.window->showScreen("errors");
        auto* list = child<QListWidget>(panel, "errors", "errorList");
        QTRY_COMPARE(list->count(), 1);
        const QString text = list->item(0)->text();
        QVERIFY2(text.contains("runtime") && text.contains("P051") && text.contains("N0002"),
                 qPrintable(text));
        panel.press(Qt::Key_Return);
        QCOMPARE(panel.window->currentScreenName(), QString("editor"));
        auto* edit = child<QPlainTextEdit>(panel, "editor", "programEditor");
        QCOMPARE(edit->textCursor().block().text(), QString("N0002 T999"));
    }

    void aRestartErrorAppearsInTheErrorWindow() {
        PanelFixture panel(options());
        panel.session->addProgram(0, 21, "plain.nc", "N0000 G1 X1 F100\nN0001 M30\n");
        panel.session->selectProgram(0, 21);
        panel.press(Qt::Key_F1, Qt::ShiftModifier);  // M key NC program restart
        QCOMPARE(panel.window->currentScreenName(), QString("restart"));
        panel.press(Qt::Key_F1);  // Plane+ on a block without jump or call: refused
        panel.window->showScreen("errors");
        auto* list = child<QListWidget>(panel, "errors", "errorList");
        QTRY_VERIFY(list->count() >= 1);
        const QString text = list->item(list->count() - 1)->text();
        QVERIFY2(text.contains("restart") && text.contains("P021"), qPrintable(text));
        panel.press(Qt::Key_F6);  // Clear runtime
        QCOMPARE(list->count(), 0);
    }

    void errorFilesOnDiskFillTheWindowAtStart() {
        mtc::hmi::PanelOptions o = options();
        {
            PanelFixture panel(o);
            pickProgram(panel, 5);
            panel.press(Qt::Key_F6);
            panel.press(Qt::Key_F3);  // compile: E, .ERR written
            QTRY_VERIFY(directoryRow(panel, 5).contains("[E]"));
        }
        PanelFixture again(o);  // nothing rewritten: the files are as they were
        QVERIFY(directoryRow(again, 5).contains("[E]"));
        again.window->showScreen("errors");
        auto* list = child<QListWidget>(again, "errors", "errorList");
        QVERIFY(list->count() >= 1);
        QVERIFY(list->item(0)->text().contains("N0003"));
        again.press(Qt::Key_Return);
        QCOMPARE(again.window->currentScreenName(), QString("editor"));
        auto* edit = child<QPlainTextEdit>(again, "editor", "programEditor");
        QCOMPARE(edit->textCursor().blockNumber() + 1, 14);
    }

    void gneKeyOpensTheGneScreenOrExplainsItsAbsence() {
        PanelFixture panel(options());
        pickProgram(panel, 6);
        panel.press(Qt::Key_F2);
        QCOMPARE(panel.window->currentScreenName(), QString("editor"));
        const bool hasGne = panel.window->screen(0, "gne") != nullptr;
        panel.press(Qt::Key_F4);  // GNE
        if (hasGne) {
            QCOMPARE(panel.window->currentScreenName(), QString("gne"));
        } else {
            QCOMPARE(panel.window->currentScreenName(), QString("editor"));
            QVERIFY(child<QLabel>(panel, "editor", "editorMessage")->text().contains("GNE"));
        }
    }

    void aLargeProgramIsUsableAtOnce() {
        // ED-007: 1,000,000 blocks are the target; 200,000 keep the test fast.
        constexpr int kBlocks = 200000;
        QString body;
        body.reserve(26 * kBlocks);
        for (int i = 0; i < kBlocks; ++i)
            body += QString("N%1 G1 X%2 Y%3 F1000\n")
                        .arg(i % 10000, 4, 10, QChar('0'))
                        .arg(i % 97)
                        .arg(i % 89);
        const QString original = programHeader(9, "Large") + body;
        mtc::hmi::PanelOptions o = options();
        QDir dir(dir_.path());
        writeProgram(dir, 9, original);
        PanelFixture panel(o);
        pickProgram(panel, 9);
        panel.press(Qt::Key_F2);
        auto* editor = qobject_cast<mtc::screens::EditorScreen*>(panel.window->currentScreen());
        QVERIFY(editor);
        auto* edit = child<mtc::screens::NcCodeEdit>(panel, "editor", "programEditor");
        QCOMPARE(edit->lineCount(), 10 + kBlocks + 1);  // all there when the screen shows
        qInfo("%d-block program opened in %lld ms", kBlocks, editor->lastOpenMs());
        QVERIFY(edit->textCursor().block().userState() == mtc::screens::kHighlighted);

        QElapsedTimer keys;  // figures for ED-007 (not asserted: bench/ and timing do that)
        keys.start();
        panel.press(Qt::Key_End, Qt::ControlModifier);
        QCOMPARE(edit->cursorLine(), 10 + kBlocks + 1);  // ED-009: the window's line
        const qint64 endMs = keys.restart();
        panel.press(Qt::Key_PageUp);
        const qint64 pageMs = keys.restart();
        panel.press(Qt::Key_End, Qt::ControlModifier);
        panel.press(Qt::Key_Up);
        panel.press(Qt::Key_End);
        QTRY_VERIFY(edit->textCursor().block().userState() == mtc::screens::kHighlighted);
        keys.restart();
        QTest::keyClicks(edit, " ;done");
        qInfo("keys: Ctrl+End %lld ms, PgUp %lld ms, 6 typed characters %lld ms", endMs, pageMs,
              keys.elapsed());
        auto* heading = child<QLabel>(panel, "editor", "editorHeading");
        QVERIFY(heading->text().contains("modified"));
        panel.press(Qt::Key_S, Qt::ControlModifier);
        QVERIFY2(!heading->text().contains("modified"), qPrintable(heading->text()));

        QString expected = original;
        expected.insert(expected.size() - 1, " ;done");
        QFile saved(dir.filePath("N1010009.DAT"));
        QVERIFY(saved.open(QIODevice::ReadOnly));
        QVERIFY(saved.readAll() == expected.toUtf8());  // complete, byte for byte
        const QStringList leftovers = dir.entryList({"*.tmp*", "*~"}, QDir::Files | QDir::Hidden);
        QVERIFY2(leftovers.isEmpty(), qPrintable(leftovers.join(',')));
        QVERIFY(panel.session->program(0, 9)->source == expected.toStdString());
    }

    void editorAndDirectoryShowTheSameStatusLetter() {
        PanelFixture panel(options());
        pickProgram(panel, 7);
        panel.press(Qt::Key_F6);  // Compiler active = Yes
        panel.press(Qt::Key_F2);  // Edit
        auto* heading = child<QLabel>(panel, "editor", "editorHeading");
        auto agree = [&](const char* letter) {
            const QString tag = QString("[%1]").arg(letter);
            return heading->text().contains(tag) && directoryRow(panel, 7).contains(tag);
        };
        QVERIFY2(agree("N"), qPrintable(heading->text() + " / " + directoryRow(panel, 7)));
        panel.press(Qt::Key_F2);  // Compile
        QTRY_VERIFY2(agree("C"), qPrintable(heading->text() + " / " + directoryRow(panel, 7)));
        // An edit: a faulty macro definition before the last block, saved.
        panel.press(Qt::Key_End, Qt::ControlModifier);
        panel.press(Qt::Key_Up);
        QTest::keyClicks(child<QPlainTextEdit>(panel, "editor", "programEditor"),
                         "N0007 DEFINE 9BAD AS G1 X0");
        panel.press(Qt::Key_Return);
        panel.press(Qt::Key_S, Qt::ControlModifier);
        QTRY_VERIFY2(agree("N"), qPrintable(heading->text() + " / " + directoryRow(panel, 7)));
        panel.press(Qt::Key_F2);  // Compile: error
        QTRY_VERIFY2(agree("E"), qPrintable(heading->text() + " / " + directoryRow(panel, 7)));
    }
};

QTEST_MAIN(EditorScreenTest)
#include "test_editor_screen.moc"
