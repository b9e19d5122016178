// The NC options screen (seed 001 ch. 4, 7, 8, 9, 11; decisions NO-001..):
// one set of options for both stations, global macros added, changed and
// deleted by keys, refused entries leave everything as it was, a changed
// macro sets the programs that depend on it back to N on every station.
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QListView>
#include <QListWidget>
#include <QRegularExpression>
#include <QTemporaryDir>

#include "PanelFixture.h"
#include "cnc_core/compiler/NcOptions.h"
#include "hmi/NcOptionsHolder.h"

namespace {

/// Uses the global macro FAST (no keyword of its own).
const char* kUsesMacro =
    "N0000 G0 G17 G90 X0 Y0 Z0\n"
    "N0001 FAST X40 Y0\n"
    "N0002 M30\n"
    "N0003 PROGRAMMENDE\n";

/// Uses FAST and a rounding without a following motion: status E.
const char* kBrokenWithMacro =
    "N0000 FAST X0 Y0 Z0\n"
    "N0001 G1 X10 Y0 F1000 RD3\n"
    "N0002 M30\n"
    "N0003 PROGRAMMENDE\n";

/// Neither a keyword nor a macro: never compiled.
const char* kPlain =
    "N0000 G0 G90 X0 Y0 Z0\n"
    "N0001 G1 X10 F500\n"
    "N0002 M30\n"
    "N0003 PROGRAMMENDE\n";

QString readAll(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
}

}  // namespace

class NcOptionsTest : public QObject {
    Q_OBJECT
  private:
    QTemporaryDir dir_;

    QString path(const QString& name) const { return QDir(dir_.path()).filePath(name); }

    mtc::hmi::PanelOptions options() {
        const QDir dir = emptiedDirectory(dir_.path());
        writeProgram(dir, 8, programHeader(8, "Global macro") + kUsesMacro);
        writeProgram(dir, 7, programHeader(7, "Broken") + kBrokenWithMacro);
        writeProgram(dir, 9, programHeader(9, "Plain") + kPlain);
        // station 2 (process 1) uses the macro as well
        QFile second(dir.filePath("N1011008.DAT"));
        if (second.open(QIODevice::WriteOnly))
            second.write(QString(programHeader(8, "Second station") + kUsesMacro)
                             .replace("N1010008", "N1011008")
                             .replace("%NPG:1:01:0:", "%NPG:1:01:1:")
                             .toUtf8());
        writeGlobalMacros(dir, "DEFINE FAST AS G0\n");
        mtc::hmi::PanelOptions o;
        o.programsDir = dir_.path();
        return o;
    }

    static QListView* optionList(PanelFixture& panel) {
        return child<QListView>(panel, "nc-options", "ncoList");
    }
    static QString message(PanelFixture& panel) {
        return child<QLabel>(panel, "nc-options", "ncoMessage")->text();
    }
    static QStringList rows(PanelFixture& panel) {
        QStringList texts;
        const auto* model = optionList(panel)->model();
        for (int row = 0; row < model->rowCount(); ++row)
            texts << model->index(row, 0).data().toString();
        return texts;
    }
    static void typeEntry(PanelFixture& panel, const QString& text) {
        auto* editor = child<QLineEdit>(panel, "nc-options", "ncoEditor");
        QTRY_VERIFY(editor->hasFocus());
        editor->selectAll();
        QTest::keyClick(editor, Qt::Key_Backspace);
        QTest::keyClicks(editor, text);
        QTest::keyClick(editor, Qt::Key_Return);
    }
    static QString softKeyLabel(PanelFixture& panel, int slot, const char* screen, int key) {
        return panel.window->screen(slot, screen)->softKeys().value(key).label;
    }
    /// Station `slot`'s program directory row of `number` (with its N/C/E).
    static QString rowOf(PanelFixture& panel, int slot, int number) {
        auto* list = panel.window->screen(slot, "programs")->findChild<QListView*>("programList");
        const auto* model = qobject_cast<const mtc::screens::ProgramDirectoryModel*>(list->model());
        return model->index(model->rowOf(number)).data().toString();
    }

  private slots:
    void initTestCase() { useTestSettings(); }

    void theScreenOpensFromTheProgramDirectoryAndTheMenu() {
        PanelFixture panel(options());
        panel.window->showScreen("programs");
        QCOMPARE(softKeyLabel(panel, 0, "programs", 4), QString("NC\noptions"));
        panel.press(Qt::Key_F5);
        QTRY_VERIFY(optionList(panel)->isVisible());
        QVERIFY(rows(panel).first().contains("Compiler active:"));
        QVERIFY(rows(panel).join('\n').contains("INDRAMAT compiler"));
        QVERIFY(rows(panel).join('\n').contains("DEFINE FAST AS G0"));
        panel.press(Qt::Key_F8);
        QTRY_VERIFY(panel.window->screen(0, "programs")->isVisible());
        panel.window->showScreen("menu");
        auto* menu = child<QListWidget>(panel, "menu", "menuList");
        QVERIFY(!menu->findItems("(nc-options)", Qt::MatchContains).isEmpty());
    }

    void compilerActiveIsOneSettingForBothStations() {
        PanelFixture panel(options());
        panel.window->showScreen("nc-options");
        QVERIFY(!panel.session->ncOptions().compilerActive());
        panel.press(Qt::Key_Return);  // cursor on "Compiler active"
        QTRY_VERIFY(panel.session->ncOptions().compilerActive());
        QVERIFY(rows(panel).first().contains("Yes"));
        QCOMPARE(softKeyLabel(panel, 0, "programs", 5), QString("Compiler\nactive: Yes"));
        QCOMPARE(softKeyLabel(panel, 1, "programs", 5), QString("Compiler\nactive: Yes"));
        QVERIFY(readAll(path("NC_OPTIONS.CFG")).contains("COMPILER_ACTIVE = YES"));
        QCOMPARE(optionList(panel)->currentIndex().row(), 0);  // the cursor stays
        panel.press(Qt::Key_F4);
        QTRY_VERIFY(!panel.session->ncOptions().compilerActive());
        QCOMPARE(softKeyLabel(panel, 1, "programs", 5), QString("Compiler\nactive: No"));
        QVERIFY(readAll(path("NC_OPTIONS.CFG")).contains("COMPILER_ACTIVE = NO"));
        // the other station's program directory switches it back for both
        panel.window->showStation(1);
        panel.window->showScreen("programs");
        panel.press(Qt::Key_F6);
        QTRY_VERIFY(panel.session->ncOptions().compilerActive());
        QCOMPARE(softKeyLabel(panel, 0, "programs", 5), QString("Compiler\nactive: Yes"));
    }

    void aMacroIsAddedByKeysAndWrittenToTheFile() {
        PanelFixture panel(options());
        panel.window->showScreen("nc-options");
        const int before = rows(panel).size();
        panel.press(Qt::Key_F2);
        typeEntry(panel, "DEFINE SLOW_FEED AS G1 F100");
        QTRY_COMPARE(rows(panel).size(), before + 1);
        QVERIFY(rows(panel).join('\n').contains("DEFINE SLOW_FEED AS G1 F100"));
        QVERIFY2(message(panel).startsWith("Taken"), qPrintable(message(panel)));
        const QString file = readAll(path("GLOBAL_MACROS.MAC"));
        QVERIFY(file.contains("DEFINE FAST AS G0\n"));
        QVERIFY(file.contains("DEFINE SLOW_FEED AS G1 F100\n"));
        QCOMPARE(panel.session->ncOptions().globalMacros().size(), std::size_t(2));
        QVERIFY(!child<QLineEdit>(panel, "nc-options", "ncoEditor")->isVisible());
    }

    void refusedMacrosSayWhyAndLeaveEverythingAsItWas() {
        PanelFixture panel(options());
        panel.window->showScreen("nc-options");
        const QStringList before = rows(panel);
        const QString fileBefore = readAll(path("GLOBAL_MACROS.MAC"));
        const struct {
            QString entry;
            QString reason;
        } refused[] = {
            {"DEFINE LA_ON AS G1", "keyword"},
            {"DEFINE TWICE AS FAST X1", "nested"},
            {"DEFINE FAST AS G1", "already defined"},
            {"DEFINE LONG AS X" + QString(156, '1'), "156"},
            {"SLOW = G1 F100", "DEFINE <name> AS"},
        };
        for (const auto& entry : refused) {
            panel.press(Qt::Key_F2);
            typeEntry(panel, entry.entry);
            QTRY_VERIFY2(message(panel).contains(entry.reason), qPrintable(message(panel)));
            QVERIFY(message(panel).startsWith("Macro refused"));
            auto* editor = child<QLineEdit>(panel, "nc-options", "ncoEditor");
            QCOMPARE(editor->text(), entry.entry);  // kept for a correction
            QTest::keyClick(editor, Qt::Key_Escape);
            QTRY_VERIFY(!editor->isVisible());
            QCOMPARE(rows(panel), before);
            QCOMPARE(readAll(path("GLOBAL_MACROS.MAC")), fileBefore);
        }
        QCOMPARE(panel.session->ncOptions().globalMacros().size(), std::size_t(1));
    }

    void aMacroIsChangedAndDeleted() {
        PanelFixture panel(options());
        panel.window->showScreen("nc-options");
        auto* list = optionList(panel);
        const int macroRow = rows(panel).indexOf(QRegularExpression(".*DEFINE FAST.*"));
        QVERIFY(macroRow > 0);
        for (int i = 0; i < macroRow; ++i)
            panel.press(Qt::Key_Down);
        QCOMPARE(list->currentIndex().row(), macroRow);
        panel.press(Qt::Key_Return);
        auto* editor = child<QLineEdit>(panel, "nc-options", "ncoEditor");
        QTRY_COMPARE(editor->text(), QString("DEFINE FAST AS G0"));
        typeEntry(panel, "DEFINE FAST AS G0 F20000");
        QTRY_VERIFY(rows(panel).join('\n').contains("DEFINE FAST AS G0 F20000"));
        QVERIFY(readAll(path("GLOBAL_MACROS.MAC")).contains("DEFINE FAST AS G0 F20000\n"));
        QCOMPARE(list->currentIndex().row(), macroRow);
        panel.press(Qt::Key_Delete);
        QTRY_VERIFY(!rows(panel).join('\n').contains("DEFINE FAST"));
        QVERIFY(panel.session->ncOptions().globalMacros().empty());
        QVERIFY(!readAll(path("GLOBAL_MACROS.MAC")).contains("FAST"));
        QVERIFY2(message(panel).startsWith("Deleted"), qPrintable(message(panel)));
    }

    void aChangedMacroSetsTheProgramsOfBothStationsBackToN() {
        // a stale object of station 2's program (newer than its source): C
        {
            options();
            QFile object(path("N1011008.NCO"));
            QVERIFY(object.open(QIODevice::WriteOnly));
            object.write("stale\n");
        }
        mtc::hmi::PanelOptions o;
        o.programsDir = dir_.path();
        PanelFixture panel(o);
        QVERIFY(panel.session->program(1, 8));
        panel.window->showScreen("nc-options");
        panel.press(Qt::Key_F4);  // Compiler active = Yes
        QTRY_VERIFY(panel.session->ncOptions().compilerActive());
        pickProgram(panel, 8);
        panel.press(Qt::Key_F3);  // Compile
        QTRY_VERIFY2(directoryRow(panel, 8).contains("[C]"), qPrintable(directoryRow(panel, 8)));
        QVERIFY(QFile::exists(path("N1010008.NCO")));
        pickProgram(panel, 7);
        panel.press(Qt::Key_F3);
        QTRY_VERIFY2(directoryRow(panel, 7).contains("[E]"), qPrintable(directoryRow(panel, 7)));
        QVERIFY(QFile::exists(path("N1010007.ERR")));
        QVERIFY(!directoryRow(panel, 9).contains("[N]"));
        {  // station 2's object again, after the compiler setting cleared it
            QFile object(path("N1011008.NCO"));
            QVERIFY(object.open(QIODevice::WriteOnly));
            object.write("stale\n");
        }
        QVERIFY2(rowOf(panel, 1, 8).contains("[C]"), qPrintable(rowOf(panel, 1, 8)));
        pickProgram(panel, 8);
        panel.press(Qt::Key_F2);  // the editor shows program 8 with its status
        auto* heading = child<QLabel>(panel, "editor", "editorHeading");
        QTRY_VERIFY2(heading->text().contains("status [C]"), qPrintable(heading->text()));

        panel.window->showScreen("nc-options");
        panel.press(Qt::Key_F2);
        typeEntry(panel, "DEFINE COOL AS M8");
        QTRY_COMPARE(panel.session->ncOptions().globalMacros().size(), std::size_t(2));
        QTRY_VERIFY2(directoryRow(panel, 8).contains("[N]"), qPrintable(directoryRow(panel, 8)));
        QVERIFY2(rowOf(panel, 1, 8).contains("[N]"), qPrintable(rowOf(panel, 1, 8)));
        QVERIFY(!QFile::exists(path("N1010008.NCO")));
        QVERIFY(!QFile::exists(path("N1011008.NCO")));
        QVERIFY2(heading->text().contains("status [N]"), qPrintable(heading->text()));
        // seed 001 ch. 9: the error files are cleared as well
        QVERIFY2(directoryRow(panel, 7).contains("[N]"), qPrintable(directoryRow(panel, 7)));
        QVERIFY(!QFile::exists(path("N1010007.ERR")));
        QVERIFY(!directoryRow(panel, 9).contains("[N]"));  // uses no macro
        // the new status compiles again with the new macro list
        pickProgram(panel, 8);
        panel.press(Qt::Key_F3);
        QTRY_VERIFY2(directoryRow(panel, 8).contains("[C]"), qPrintable(directoryRow(panel, 8)));
    }

    void aFailedWriteKeepsTheOldOptionsAndSaysWhy() {
        PanelFixture panel(options());
        panel.window->showScreen("nc-options");
        const QStringList before = rows(panel);
        // the program directory disappears under the panel
        const QString moved = dir_.path() + "-away";
        QVERIFY(QDir().rename(dir_.path(), moved));
        panel.press(Qt::Key_F2);
        typeEntry(panel, "DEFINE COOL AS M8");
        QTRY_VERIFY2(message(panel).contains("not written"), qPrintable(message(panel)));
        QCOMPARE(rows(panel), before);
        QCOMPARE(panel.session->ncOptions().globalMacros().size(), std::size_t(1));
        QTest::keyClick(child<QLineEdit>(panel, "nc-options", "ncoEditor"), Qt::Key_Escape);
        panel.press(Qt::Key_F4);
        QTRY_VERIFY2(message(panel).contains("NC_OPTIONS.CFG not written"),
                     qPrintable(message(panel)));
        QVERIFY(!panel.session->ncOptions().compilerActive());
        QVERIFY(QDir().rename(moved, dir_.path()));
        QCOMPARE(readAll(path("GLOBAL_MACROS.MAC")), QString("DEFINE FAST AS G0\n"));
    }

    void aUserCompilerCommandIsSetAndAWrongOneRefused() {
        PanelFixture panel(options());
        panel.window->showScreen("nc-options");
        panel.press(Qt::Key_Down);  // user compiler 1
        panel.press(Qt::Key_Return);
        typeEntry(panel, "true");
        QTRY_COMPARE(mtc::core::userCompilerCommand(panel.session->ncOptions().userCompilers(), 1),
                     std::string("true"));
        QVERIFY(rows(panel).value(1).contains("true"));
        QVERIFY(readAll(path("NC_OPTIONS.CFG")).contains("USER_COMPILER_1 = true\n"));
        panel.press(Qt::Key_Down);  // user compiler 2
        panel.press(Qt::Key_Return);
        typeEntry(panel, QString(201, 'x'));
        QTRY_VERIFY2(message(panel).contains("more than 200"), qPrintable(message(panel)));
        QVERIFY(
            mtc::core::userCompilerCommand(panel.session->ncOptions().userCompilers(), 2).empty());
        QTest::keyClick(child<QLineEdit>(panel, "nc-options", "ncoEditor"), Qt::Key_Escape);
        // seed 001 ch. 8: with a user compiler every program goes through the chain
        panel.press(Qt::Key_F4);  // Compiler active = Yes
        QTRY_VERIFY(panel.session->ncOptions().compilerActive());
        pickProgram(panel, 9);
        QVERIFY2(directoryRow(panel, 9).contains("[N]"), qPrintable(directoryRow(panel, 9)));
        panel.press(Qt::Key_F3);  // Compile: user compiler 1 `true`, then INDRAMAT
        QTRY_VERIFY2(directoryRow(panel, 9).contains("[C]"), qPrintable(directoryRow(panel, 9)));
        QVERIFY(QFile::exists(path("N1010009.NCO")));
    }

    void nothingChangesWhileAStationRunsAProgram() {
        PanelFixture panel(options());
        pickProgram(panel, 9);
        panel.press(Qt::Key_Return);
        QCOMPARE(panel.session->control(0).selectedProgram(), 9);
        panel.press(Qt::Key_F8, Qt::ShiftModifier);  // single block: holds after a block
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start
        QTRY_VERIFY(panel.session->control(0).programActive());
        panel.window->showScreen("nc-options");
        panel.press(Qt::Key_F4);
        QTRY_VERIFY2(message(panel).contains("is running a program"), qPrintable(message(panel)));
        QVERIFY(!panel.session->ncOptions().compilerActive());
        panel.press(Qt::Key_F2);
        typeEntry(panel, "DEFINE COOL AS M8");
        QTRY_VERIFY2(message(panel).startsWith("Global macros not changed"),
                     qPrintable(message(panel)));
        QCOMPARE(panel.session->ncOptions().globalMacros().size(), std::size_t(1));
        QCOMPARE(readAll(path("GLOBAL_MACROS.MAC")), QString("DEFINE FAST AS G0\n"));
    }

    void theOptionsFileIsReadAtStartAndItsBadLinesReported() {
        mtc::hmi::PanelOptions o = options();
        QFile file(path("NC_OPTIONS.CFG"));
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("COMPILER_ACTIVE = YES\nUSER_COMPILER_9 = x\n");
        file.close();
        PanelFixture panel(o);
        QVERIFY(panel.session->ncOptions().compilerActive());
        QVERIFY(panel.session->ncOptions().userCompilers().empty());
        for (int slot = 0; slot < 2; ++slot) {  // both stations' error windows
            panel.window->showStation(slot);
            panel.window->showScreen("errors");
            auto* list = panel.window->screen(slot, "errors")->findChild<QListWidget*>("errorList");
            QTRY_VERIFY(list->count() >= 1);
            QVERIFY2(!list->findItems("NC_OPTIONS.CFG line 2", Qt::MatchContains).isEmpty(),
                     qPrintable(list->item(0)->text()));
        }
    }

    void theBuiltInCellKeepsTheOptionsInMemory() {
        PanelFixture panel;  // built-in demo programs, no directory
        panel.window->showScreen("nc-options");
        QVERIFY(child<QLabel>(panel, "nc-options", "ncoHeader")->text().contains("memory"));
        panel.press(Qt::Key_F2);
        typeEntry(panel, "DEFINE COOL AS M8");
        QTRY_COMPARE(panel.session->ncOptions().globalMacros().size(), std::size_t(1));
        QVERIFY2(message(panel).startsWith("Taken"), qPrintable(message(panel)));
    }
};

QTEST_MAIN(NcOptionsTest)
#include "test_nc_options.moc"
