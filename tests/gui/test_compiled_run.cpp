// A station runs the runtime program (seed 001 ch. 1, 10, 11; decision
// C-013): a program with compiler keywords is compiled on demand when it is
// selected, runs as the compiled object (N0053:0001 blocks), is refused with
// status E, and its runtime errors lead back to the source line. Warnings
// never give status E (C-014); with the compiler off a keyword refuses the
// program at selection (C-016).
#include <QDir>
#include <QLabel>
#include <QListView>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTextBlock>
#include <cmath>
#include <utility>
#include <vector>

#include "PanelFixture.h"
#include "cnc_core/machine/SimulatedMachine.h"
#include "screens/programs/ProgramDirectoryModel.h"

namespace {

/// A corner X30 Y0 rounded with radius 5 through a macro: the compiled path
/// touches (25, 0) and (30, 5), the source path only the corner (30, 0).
const char* kRoundedCorner =
    "N0000 G0 G17 G90 X0 Y0 Z0\n"
    "N0001 DEFINE ROUND AS RD5\n"
    "N0002 G1 X30 Y0 F2000 ROUND\n"
    "N0003 G1 X30 Y30\n"
    "N0004 M30\n"
    "N0005 PROGRAMMENDE\n";

/// A rounding without a following motion: compiler error, status E.
const char* kBrokenRounding =
    "N0000 G0 G17 G90 X0 Y0 Z0\n"
    "N0001 G1 X10 Y0 F1000 RD3\n"
    "N0002 M30\n"
    "N0003 PROGRAMMENDE\n";

/// Compiles (a chamfer inserts a block), then fails at run time on T999:
/// source line 14, a later line in the object program.
const char* kRuntimeFault =
    "N0000 G0 G17 G90 X0 Y0 Z0\n"
    "N0001 G1 X10 Y0 F1000 CF2\n"
    "N0002 G1 X10 Y10\n"
    "N0003 T999\n"
    "N0004 M30\n"
    "N0005 PROGRAMMENDE\n";

/// The corner of kRoundedCorner rounded by the global macro ROUND5 of the
/// program directory's GLOBAL_MACROS.MAC (GM-005): no DEFINE in the program.
const char* kGlobalMacroUse =
    "N0000 G0 G17 G90 X0 Y0 Z0\n"
    "N0001 G1 X30 Y0 F2000 ROUND5\n"
    "N0002 G1 X30 Y30\n"
    "N0003 M30\n"
    "N0004 PROGRAMMENDE\n";

/// RD 6 does not fit the 4 mm line: reduced to 4 with a warning, no error.
const char* kReducedRounding =
    "N0000 G0 G17 G90 X0 Y0 Z0\n"
    "N0001 G1 X4 Y0 F2000 RD6\n"
    "N0002 G1 X4 Y10\n"
    "N0003 M30\n"
    "N0004 PROGRAMMENDE\n";

/// A rounding in the third block: with the compiler off, the program is
/// refused at selection (seed 001 ch. 7), not after the first blocks moved.
const char* kKeywordLate =
    "N0000 G0 G17 G90 X0 Y0 Z0\n"
    "N0001 G1 X10 Y0 F2000\n"
    "N0002 G1 X10 Y10 RD2\n"
    "N0003 G1 X0 Y10\n"
    "N0004 M30\n"
    "N0005 PROGRAMMENDE\n";

}  // namespace

class CompiledRunTest : public QObject {
    Q_OBJECT
  private:
    QTemporaryDir dir_;

    mtc::hmi::PanelOptions options(const QString& language = "en") {
        const QDir dir = emptiedDirectory(dir_.path());
        writeProgram(dir, 5, programHeader(5, "Rounded corner") + kRoundedCorner);
        writeProgram(dir, 6, programHeader(6, "Broken rounding") + kBrokenRounding);
        writeProgram(dir, 7, programHeader(7, "Runtime fault") + kRuntimeFault);
        writeProgram(dir, 8, programHeader(8, "Global macro") + kGlobalMacroUse);
        writeProgram(dir, 9, programHeader(9, "Reduced rounding") + kReducedRounding);
        writeProgram(dir, 10, programHeader(10, "Keyword late") + kKeywordLate);
        writeGlobalMacros(dir,
                          "; NC options of the test cell\nDEFINE ROUND5 AS RD5\nDEFINE 9X AS X9\n");
        mtc::hmi::PanelOptions o;
        o.programsDir = dir_.path();
        o.language = language;
        return o;
    }

    /// Compiler active = Yes, then Enter selects `number` in the directory.
    static void selectCompiled(PanelFixture& panel, int number) {
        pickProgram(panel, number);
        panel.press(Qt::Key_F6);  // NC options: Compiler active = Yes
        pickProgram(panel, number);
        panel.press(Qt::Key_Return);
        QCOMPARE(panel.session->control(0).selectedProgram(), number);
    }

  private slots:
    void initTestCase() { useTestSettings(); }

    void aGlobalMacroOfTheProgramDirectoryIsExpanded() {
        PanelFixture panel(options());
        selectCompiled(panel, 8);
        QVERIFY2(directoryRow(panel, 8).contains("[C]"), qPrintable(directoryRow(panel, 8)));
        QFile object(QDir(dir_.path()).filePath("N1010008.NCO"));
        QVERIFY(object.open(QIODevice::ReadOnly));
        const QString text = QString::fromLatin1(object.readAll());
        QVERIFY2(text.contains("N0001:0000 G1 X25 Y0 F2000"), qPrintable(text));
        QVERIFY2(text.contains("N0001:0001 G3 X30 Y5 I25 J5"), qPrintable(text));
        QVERIFY(!text.contains("ROUND5"));
    }

    void aCompiledProgramRunsItsTangentPoints() {
        PanelFixture panel(options());
        selectCompiled(panel, 5);
        QVERIFY2(directoryRow(panel, 5).contains("[C]"), qPrintable(directoryRow(panel, 5)));
        QVERIFY(QFile::exists(QDir(dir_.path()).filePath("N1010005.NCO")));

        panel.session->setSpeed(1000);
        panel.press(Qt::Key_F8, Qt::ShiftModifier);  // single block on
        auto* block = panel.window->findChild<QLabel*>("headerProgram");
        const auto& machine = panel.session->machine(0);
        std::vector<std::pair<double, double>> reached;
        bool enhancedShown = false;
        const QRegularExpression enhanced("Block: N\\d{4}:\\d{4}");
        for (int step = 0; step < 20 && (step == 0 || panel.session->control(0).programActive());
             ++step) {
            panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start (next block)
            QTRY_VERIFY(panel.session->control(0).programHeld() ||
                        !panel.session->control(0).programActive());
            reached.emplace_back(machine.position(0), machine.position(1));
            enhancedShown = enhancedShown || enhanced.match(block->text()).hasMatch();
        }
        QVERIFY(!panel.session->control(0).programActive());
        auto touched = [&](double x, double y) {
            for (const auto& [px, py] : reached)
                if (std::abs(px - x) < 1e-6 && std::abs(py - y) < 1e-6) return true;
            return false;
        };
        QVERIFY2(touched(25, 0), "the line ends at the rounding's first tangent point");
        QVERIFY2(touched(30, 5), "the arc ends at the second tangent point");
        QVERIFY2(!touched(30, 0), "the sharp source corner is never reached");
        QVERIFY(touched(30, 30));
        QVERIFY2(enhancedShown, "the inserted arc block shows as N....:0001");
    }

    void theRestartSearchesTheCompiledProgram() {
        PanelFixture panel(options());
        selectCompiled(panel, 5);
        panel.press(Qt::Key_F1, Qt::ShiftModifier);  // M key NC program restart
        QCOMPARE(panel.window->currentScreenName(), QString("restart"));
        auto* listing = child<QListView>(panel, "restart", "restartListing");
        QVERIFY(listing && listing->model());
        QString text;
        for (int row = 0; row < listing->model()->rowCount(); ++row)
            text += listing->model()->index(row, 0).data().toString() + "\n";
        QVERIFY2(text.contains(QRegularExpression("N0002:0001")), qPrintable(text));
        QVERIFY2(!text.contains("ROUND"), qPrintable(text));  // no macro left in the object
    }

    // The refusal in the panel's language (docs/DECISIONS.md D-026).
    void startIsRefusedWithCompilerErrors_data() {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QString>("alarm");
        QTest::addColumn<QString>("restart");
        QTest::newRow("en")
            << "en"
            << "Start refused: program 6 has compiler errors \u2014 see error window"
            << "compiler errors";
        QTest::newRow("de") << "de"
                            << "Start abgelehnt: Programm 6 hat Compilerfehler \u2014 siehe "
                               "Fehlerfenster"
                            << "Compilerfehler";
    }

    void startIsRefusedWithCompilerErrors() {
        QFETCH(QString, language);
        QFETCH(QString, alarm);
        QFETCH(QString, restart);
        PanelFixture panel(options(language));
        selectCompiled(panel, 6);
        QVERIFY2(directoryRow(panel, 6).contains("[E]"), qPrintable(directoryRow(panel, 6)));
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start
        const auto& control = panel.session->control(0);
        QVERIFY(!control.programActive());
        QCOMPARE(control.selectedProgram(), 6);
        QCOMPARE(panel.session->machine(0).position(0), 0.0);
        auto* header = panel.window->findChild<QLabel*>("headerAlarm");
        QTRY_VERIFY2(header->text().endsWith(alarm), qPrintable(header->text()));
        // No runtime program: the restart refuses as well.
        QVERIFY(!panel.session->store().findRuntime(control.process(), 6));
        panel.press(Qt::Key_F1, Qt::ShiftModifier);  // M key NC program restart
        QCOMPARE(panel.window->currentScreenName(), QString("restart"));
        auto* message = child<QLabel>(panel, "restart", "restartMessage");
        QTRY_VERIFY2(message->text().contains(restart), qPrintable(message->text()));
    }

    void warningsOnlyCompileStaysRunnableAfterRestart() {
        const mtc::hmi::PanelOptions opened = options();
        {
            PanelFixture panel(opened);
            selectCompiled(panel, 9);
            QVERIFY2(directoryRow(panel, 9).contains("[C]"), qPrintable(directoryRow(panel, 9)));
        }
        const QDir dir(dir_.path());
        QVERIFY(QFile::exists(dir.filePath("N1010009.NCO")));
        QVERIFY2(!QFile::exists(dir.filePath("N1010009.ERR")), "C-014: no error file for warnings");
        // an error file with notices only, as older versions wrote it
        QFile notices(dir.filePath("N1010009.ERR"));
        QVERIFY(notices.open(QIODevice::WriteOnly));
        notices.write("\nN0001:$I:0000\nRD reduced to 4.\n");
        notices.close();

        PanelFixture panel(opened);  // the panel starts again on the same directory
        QVERIFY2(directoryRow(panel, 9).contains("[C]"), qPrintable(directoryRow(panel, 9)));
        pickProgram(panel, 9);
        panel.press(Qt::Key_Return);
        QCOMPARE(panel.session->control(0).selectedProgram(), 9);
        panel.session->setSpeed(1000);
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start is not refused
        QTRY_VERIFY(!panel.session->control(0).programActive());
        QVERIFY2(panel.session->control(0).alarm().empty(),
                 panel.session->control(0).alarm().c_str());
        QCOMPARE(panel.session->machine(0).position(1), 10.0);
        panel.window->showScreen("errors");  // the warning is back in the error window
        auto* list = child<QListWidget>(panel, "errors", "errorList");
        QString all;
        for (int row = 0; row < list->count(); ++row)
            all += list->item(row)->text() + "\n";
        QVERIFY2(all.contains("RD reduced to 4"), qPrintable(all));
    }

    void keywordWithTheCompilerOffIsRefusedAtSelection() {
        PanelFixture panel(options());  // compiler active = No (preset)
        pickProgram(panel, 10);
        panel.press(Qt::Key_Return);
        QCOMPARE(panel.session->control(0).selectedProgram(), 10);
        auto* alarm = panel.window->findChild<QLabel*>("headerAlarm");
        QTRY_VERIFY2(alarm->text().contains("NEEDS_COMPILER") && alarm->text().contains("N0002"),
                     qPrintable(alarm->text()));
        panel.session->setSpeed(1000);
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start: refused at once
        QVERIFY(!panel.session->control(0).programActive());
        QCOMPARE(panel.session->machine(0).position(0), 0.0);  // N0001 did not move
        panel.window->showScreen("errors");
        auto* list = child<QListWidget>(panel, "errors", "errorList");
        QTRY_VERIFY(list->count() >= 1);
        list->setCurrentRow(list->count() - 1);
        panel.press(Qt::Key_Return);  // Enter leads to the keyword's line
        QCOMPARE(panel.window->currentScreenName(), QString("editor"));
        auto* edit = child<QPlainTextEdit>(panel, "editor", "programEditor");
        QCOMPARE(edit->textCursor().block().text(), QString("N0002 G1 X10 Y10 RD2"));
    }

    void aRuntimeErrorLeadsToTheSourceLine() {
        PanelFixture panel(options());
        selectCompiled(panel, 7);
        QVERIFY(directoryRow(panel, 7).contains("[C]"));
        panel.session->setSpeed(1000);
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start
        QTRY_VERIFY(!panel.session->control(0).programActive());
        panel.window->showScreen("errors");
        auto* list = child<QListWidget>(panel, "errors", "errorList");
        QTRY_VERIFY(list->count() >= 1);
        const QString text = list->item(list->count() - 1)->text();
        QVERIFY2(text.contains("runtime") && text.contains("P007") && text.contains("N0003"),
                 qPrintable(text));
        list->setCurrentRow(list->count() - 1);
        panel.press(Qt::Key_Return);
        QCOMPARE(panel.window->currentScreenName(), QString("editor"));
        auto* edit = child<QPlainTextEdit>(panel, "editor", "programEditor");
        QCOMPARE(edit->textCursor().block().text(), QString("N0003 T999"));
        QCOMPARE(edit->textCursor().blockNumber() + 1, 14);
        // The run was the compiled program, whose T999 sits on another line.
        QVERIFY(panel.session->store().findRuntime(panel.session->control(0).process(), 7));
        QFile object(QDir(dir_.path()).filePath("N1010007.NCO"));
        QVERIFY(object.open(QIODevice::ReadOnly));
        const QStringList objectLines = QString::fromUtf8(object.readAll()).split('\n');
        int objectLine = 0;
        for (int i = 0; i < objectLines.size() && objectLine == 0; ++i)
            if (objectLines[i].startsWith("N0003") && objectLines[i].contains("T999"))
                objectLine = i + 1;
        QVERIFY2(objectLine > 14, qPrintable(objectLines.join(" | ")));
    }
};

QTEST_MAIN(CompiledRunTest)
#include "test_compiled_run.moc"
