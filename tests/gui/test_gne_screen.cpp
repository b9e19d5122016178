// The graphical NC editor screen (seed 001 ch. 3), driven with real keys
// from the program editor's GNE soft key: a milling contour and its cycle
// built by keys only, saved as function call and as NC blocks, compiled by
// the NC compiler and run by the interpreter; keyword -> dialog -> keyword;
// a refused value keeps the old one; choosing another solution redraws.
#include <QDir>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QListView>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QRegularExpression>
#include <QSet>
#include <QTableWidget>
#include <QTemporaryDir>
#include <random>

#include "PanelFixture.h"
#include "cnc_core/compiler/Compiler.h"
#include "cnc_core/contour/GneSchema.h"
#include "cnc_core/language/Parser.h"
#include "cnc_core/program/ProgramStore.h"
#include "cnc_core/toolpath/ToolpathRun.h"
#include "hmi/ProgramWorkspace.h"
#include "screens/gne/GneCanvas.h"
#include "screens/gne/GneScreen.h"
#include "screens/programs/ProgramDirectoryModel.h"

namespace {

/// Line 11 is the first block, line 12 is empty: the GNE section goes there.
const char* kEmptyProgram =
    "N0000 G0 G17 G90 X-20 Y-20 Z50\n\nN0001 G0 Z50\nN0002 M30\n"
    "N0003 PROGRAMMENDE\n";

/// Lines 11-16: a turning section whose arc has two solutions.
const char* kSectionProgram =
    "N0000 G0 G90 Z50\n"
    "WINDOW_01 (-40, 5, 30, 0)\n"
    "CONT (3, FINAL)\n"
    "START Z0 X20\n"
    "CCW Z-10 X20 R8\n"
    "END_CONT\n"
    "N0001 M30\n"
    "N0002 PROGRAMMENDE\n";

/// Lines 11-20: a numbered turning section (GS-007: numbers are kept).
const char* kNumberedProgram =
    "N0000 G0 G90 X40 Z10\n"
    "N0001 WINDOW_01 (-40, 5, 30, 0)\n"
    "N0002 CONT (3, FINAL) ;shaft\n"
    "N0003 START Z0 X10\n"
    "N0004 LINE Z-20 X10\n"
    "N0005 LINE Z-20 X25\n"
    "N0006 END_CONT\n"
    "N0007 CYCLE_10 (3, 1, 0.2)\n"
    "N0008 M30\n"
    "N0009 PROGRAMMENDE\n";

/// Every block line of the object text is numbered Nxxxx:yyyy, no number twice.
void expectNumberedObject(const std::string& object) {
    const QStringList lines = QString::fromStdString(object).split('\n');
    QSet<QString> seen;
    const QRegularExpression numbered("^N\\d{4}:\\d{4}( |$)");
    for (const QString& line : lines) {
        if (!line.startsWith('N')) continue;  // header, continuation lines
        QVERIFY2(numbered.match(line).hasMatch(), qPrintable(line));
        const QString id = line.left(10);
        QVERIFY2(!seen.contains(id), qPrintable("twice: " + id));
        seen.insert(id);
    }
    QVERIFY(seen.size() > 10);
}

mtc::screens::GneScreen* gneScreen(PanelFixture& panel) {
    return qobject_cast<mtc::screens::GneScreen*>(panel.window->screen(0, "gne"));
}

/// Program directory -> compiler on -> editor on `number`, cursor on `line`.
void editAt(PanelFixture& panel, int number, int line) {
    panel.window->showScreen("programs");
    auto* list = child<QListView>(panel, "programs", "programList");
    const auto* model = qobject_cast<const mtc::screens::ProgramDirectoryModel*>(list->model());
    QVERIFY(model && model->rowOf(number) >= 0);
    list->setCurrentIndex(model->index(model->rowOf(number)));
    panel.press(Qt::Key_F6);  // NC options: compiler active
    panel.press(Qt::Key_F2);  // Edit
    QCOMPARE(panel.window->currentScreenName(), QString("editor"));
    for (int i = 1; i < line; ++i)
        panel.press(Qt::Key_Down);
    auto* edit = child<QPlainTextEdit>(panel, "editor", "programEditor");
    QCOMPARE(edit->textCursor().blockNumber() + 1, line);
}

/// Types `text` and Enter (a value into the open entry line).
void typeValue(PanelFixture& panel, const QString& text) {
    for (const QChar c : text)
        QTest::keyClick(QApplication::focusWidget(), c.toLatin1());
    panel.press(Qt::Key_Return);
}

/// Selects `choice` in the open chooser by keys and takes it.
void chooseByKeys(PanelFixture& panel, const QString& choice) {
    auto* chooser = child<QListWidget>(panel, "gne", "gneChooser");
    QVERIFY(chooser->isVisible());
    panel.press(Qt::Key_Home);
    for (int i = 0; i < chooser->count() && chooser->currentItem()->text() != choice; ++i)
        panel.press(Qt::Key_Down);
    QCOMPARE(chooser->currentItem()->text(), choice);
    panel.press(Qt::Key_Return);
}

/// Enter on the selected row, then the values in order; Esc back to the rows.
void enterValues(PanelFixture& panel, const QStringList& values) {
    panel.press(Qt::Key_Return);
    for (const QString& v : values)
        typeValue(panel, v);
    panel.press(Qt::Key_Escape);
}

QString fieldValue(PanelFixture& panel, int row) {
    return child<QTableWidget>(panel, "gne", "gneFields")->item(row, 1)->text();
}

/// Runs `object` (an object or source program text) on a fresh interpreter
/// of process 0 to its end: no error, the end reached, `minBlocks` blocks.
void runProgram(PanelFixture& panel, int number, const std::string& text, int minBlocks) {
    mtc::core::ParseOptions options;
    options.programNumber = number;
    auto program = std::make_shared<mtc::core::Program>(mtc::core::parseProgram(text, options));
    mtc::core::ProgramStore store;
    store.put(0, number, program);
    const auto run = mtc::core::buildToolpath(panel.session->processConfig(0), store, number);
    QString errors;
    for (const auto& d : run.diagnostics.items())
        if (d.severity == mtc::core::Severity::Error)
            errors += QString::fromStdString(d.code + " line " + std::to_string(d.where.line) +
                                             ": " + d.message + "\n");
    QVERIFY2(errors.isEmpty(), qPrintable(errors));
    QVERIFY(run.complete);
    QVERIFY2(run.blocks >= static_cast<std::uint64_t>(minBlocks),
             qPrintable(QString::number(run.blocks)));
}

/// Compiles program `number` as saved (NC compiler, standard passes, the
/// station's options) and runs the object program.
void compileAndRun(PanelFixture& panel, int number) {
    mtc::core::CompilerOptions options;
    options.compilerActive = true;
    options.programNumber = number;
    const auto result = mtc::core::Compiler().compile(*panel.session->program(0, number), options);
    QString errors;
    for (const auto& e : result.errors)
        errors += QString::fromStdString(e.code + " line " + std::to_string(e.sourceLine) + ": " +
                                         e.message + "\n");
    QVERIFY2(result.status == mtc::core::CompileStatus::Compiled, qPrintable(errors));
    runProgram(panel, number, result.objectText, 12);
}

}  // namespace

class GneScreenTest : public QObject {
    Q_OBJECT
  private:
    QTemporaryDir dir_;

    mtc::hmi::PanelOptions options() {
        const QDir dir = emptiedDirectory(dir_.path());
        writeProgram(dir, 8, programHeader(8, "GNE new") + kEmptyProgram);
        writeProgram(dir, 9, programHeader(9, "GNE section") + kSectionProgram);
        writeProgram(dir, 10, programHeader(10, "GNE numbered") + kNumberedProgram);
        mtc::hmi::PanelOptions o;
        o.programsDir = dir_.path();
        return o;
    }

    /// Builds a 80 x 40 milling contour with a rounded corner and its
    /// CYCLE_40 by keys only, starting from the editor on the empty line.
    void buildMillingContourByKeys(PanelFixture& panel) {
        editAt(panel, 8, 12);
        panel.press(Qt::Key_F4);  // GNE
        QCOMPARE(panel.window->currentScreenName(), QString("gne"));
        auto* rows = child<QListWidget>(panel, "gne", "gneRows");
        QCOMPARE(QApplication::focusWidget(), rows);
        QVERIFY(gneScreen(panel)->model().isNew());
        QCOMPARE(rows->count(), 3);  // WINDOW_01, CONT, START
        // Milling: WINDOW_02 after the turning window, then the latter deleted.
        panel.press(Qt::Key_Insert);
        chooseByKeys(panel, "WINDOW_02");
        panel.press(Qt::Key_Up);
        panel.press(Qt::Key_Delete);
        QVERIFY(rows->item(0)->text().startsWith("WINDOW_02"));
        panel.press(Qt::Key_Down);
        panel.press(Qt::Key_Down);  // START
        QVERIFY(rows->currentItem()->text().contains("START"));
        enterValues(panel, {"5", "5"});
        QVERIFY2(rows->currentItem()->text().contains("START X5 Y5"),
                 qPrintable(rows->currentItem()->text()));
        const QList<QPair<QString, QStringList>> elements = {{"LINE", {"85", "5"}},
                                                             {"LINE", {"85", "45"}},
                                                             {"RD", {"6"}},
                                                             {"LINE", {"5", "45"}},
                                                             {"LINE", {"5", "5"}}};
        for (const auto& [kind, values] : elements) {
            panel.press(Qt::Key_Insert);
            chooseByKeys(panel, kind);
            enterValues(panel, values);
        }
        QVERIFY2(rows->item(5)->text().contains("RD 6"), qPrintable(rows->item(5)->text()));
        panel.press(Qt::Key_Insert);
        chooseByKeys(panel, "CYCLE_40");
        QVERIFY2(rows->currentItem()->text().startsWith("CYCLE_40 (1, 1, 300"),
                 qPrintable(rows->currentItem()->text()));
        auto* problems = child<QLabel>(panel, "gne", "gneProblems");
        QVERIFY2(problems->text().isEmpty(), qPrintable(problems->text()));
    }

  private slots:
    void initTestCase() { useTestSettings(); }

    void contourByKeysSavedAsFunctionCallCompilesAndRuns() {
        PanelFixture panel(options());
        buildMillingContourByKeys(panel);
        panel.press(Qt::Key_F8);  // Exit
        chooseByKeys(panel, "Save as function call (keywords with parameters)");
        QCOMPARE(panel.window->currentScreenName(), QString("editor"));
        auto* edit = child<QPlainTextEdit>(panel, "editor", "programEditor");
        const QString text = edit->toPlainText();
        // GS-007: new lines are numbered after the numbered line before them
        QVERIFY2(text.contains("N0000:0001 WINDOW_02 (-10, -10, 110, 70)\n"
                               "N0000:0002 CONT (1, FINAL)\nN0000:0003 START X5 Y5\n"
                               "N0000:0004 LINE X85 Y5\nN0000:0005 LINE X85 Y45\n"
                               "N0000:0006 RD 6\nN0000:0007 LINE X5 Y45\nN0000:0008 LINE X5 Y5\n"
                               "N0000:0009 END_CONT\nN0000:0010 CYCLE_40 (1, 1, 300"),
                 qPrintable(text));
        QVERIFY(text.contains("N0000 G0 G17 G90 X-20 Y-20 Z50\nN0000:0001 WINDOW_02"));
        QVERIFY(text.contains(")\nN0001 G0 Z50"));  // the empty line was replaced
        QCOMPARE(edit->textCursor().blockNumber() + 1, 12);
        compileAndRun(panel, 8);
        panel.press(Qt::Key_F2);  // and the editor's Compile: status C, .NCO written
        auto* heading = child<QLabel>(panel, "editor", "editorHeading");
        QTRY_VERIFY2(heading->text().contains("[C]"), qPrintable(heading->text()));
        QVERIFY(QFile::exists(QDir(dir_.path()).filePath("N1010008.NCO")));
    }

    void contourByKeysSavedAsNcBlocksCompilesAndRuns() {
        PanelFixture panel(options());
        buildMillingContourByKeys(panel);
        panel.press(Qt::Key_F8);
        chooseByKeys(panel, "Save as NC blocks (expanded)");
        QCOMPARE(panel.window->currentScreenName(), QString("editor"));
        const QString text = child<QPlainTextEdit>(panel, "editor", "programEditor")->toPlainText();
        QVERIFY2(!text.contains("\nCONT") && !text.contains("\nCYCLE_40"), qPrintable(text));
        QVERIFY2(text.contains("; GNE CONT (1, FINAL)"), qPrintable(text));
        QVERIFY2(text.contains("G17"), qPrintable(text));
        QVERIFY2(text.contains(QRegularExpression("\\nN0000:\\d{4} G[23] X\\S+ Y\\S+ I\\S+ J")),
                 qPrintable(text));  // the rounding as an arc, numbered (GS-007)
        compileAndRun(panel, 8);
        // Plain NC blocks need no compiler: the source runs as it is.
        runProgram(panel, 8, panel.session->program(0, 8)->source.str(), 12);
    }

    void keywordDialogKeywordRoundTrip() {
        PanelFixture panel(options());
        const QString before = QString::fromStdString(panel.session->program(0, 9)->source.str());
        editAt(panel, 9, 14);  // on START
        panel.press(Qt::Key_F4);
        auto* screen = gneScreen(panel);
        QVERIFY(!screen->model().isNew());
        QCOMPARE(screen->model().firstLine(), 12);
        QCOMPARE(screen->model().lastLine(), 16);
        auto* rows = child<QListWidget>(panel, "gne", "gneRows");
        QCOMPARE(rows->count(), 4);
        QCOMPARE(rows->item(3)->text(), QString("  CCW Z-10 X20 R8"));
        panel.press(Qt::Key_F8);
        chooseByKeys(panel, "Save as function call (keywords with parameters)");
        QCOMPARE(QString::fromStdString(panel.session->program(0, 9)->source.str()), before);
        // And the model alone: text -> rows -> text for every kind of item.
        const std::string section =
            "WINDOW_01 (-60, 2, 25, 0)\nCONT (2, RAW)\nSTART Z0 X0\nLINE Z0 X12 A90\nCF 1\n"
            "LINE Z-20 TAN\nRD 2\nCW Z-30 X22 K-30 I12 R10 ALT1\nRELIEF F R0.6 T0.3 W2.5 U0.2\n"
            "LINE Z-50 X22\nEND_CONT\nFORM_20 (5, -40, 22, 4, 2)\nCYCLE_11 (2, 3, 0.25, 800, 3, "
            "0.8, 80, 95, 1, 1.5, 0.4, 0.1)\n";
        mtc::screens::GneEditModel model;
        model.openText(section);
        QCOMPARE(QString::fromStdString(model.keywordText()), QString::fromStdString(section));
        QCOMPARE(model.rows().size(), std::size_t{12});
    }

    void numbersOfTheSourceAreKeptAndInsertedLinesNumbered() {
        PanelFixture panel(options());
        const QString before = QString::fromStdString(panel.session->program(0, 10)->source.str());
        editAt(panel, 10, 15);  // on N0004 LINE
        panel.press(Qt::Key_F4);
        panel.press(Qt::Key_F8);  // exit unchanged: the lines stay exactly as they were
        chooseByKeys(panel, "Save as function call (keywords with parameters)");
        QCOMPARE(QString::fromStdString(panel.session->program(0, 10)->source.str()), before);
        panel.press(Qt::Key_F4);  // again, now on the section's first line
        auto* rows = child<QListWidget>(panel, "gne", "gneRows");
        panel.press(Qt::Key_Down);
        panel.press(Qt::Key_Down);
        QVERIFY(rows->currentItem()->text().contains("START"));
        panel.press(Qt::Key_Insert);
        chooseByKeys(panel, "LINE");
        enterValues(panel, {"-10", "10"});
        panel.press(Qt::Key_F8);
        chooseByKeys(panel, "Save as function call (keywords with parameters)");
        const QString text = QString::fromStdString(panel.session->program(0, 10)->source.str());
        QVERIFY2(text.contains("N0001 WINDOW_01 (-40, 5, 30, 0)\nN0002 CONT (3, FINAL) ;shaft\n"
                               "N0003 START Z0 X10\nN0003:0001 LINE Z-10 X10\n"
                               "N0004 LINE Z-20 X10\nN0005 LINE Z-20 X25\nN0006 END_CONT\n"
                               "N0007 CYCLE_10 (3, 1, 0.2)\nN0008 M30"),
                 qPrintable(text));
        mtc::core::CompilerOptions options;
        options.compilerActive = true;
        const auto result = mtc::core::Compiler().compile(*panel.session->program(0, 10), options);
        QVERIFY(result.status == mtc::core::CompileStatus::Compiled);
        QVERIFY2(result.objectText.find("N0003:0001 ;LINE Z-10 X10") != std::string::npos,
                 result.objectText.c_str());
        expectNumberedObject(result.objectText);
    }

    void ncBlocksAreNumberedAfterTheirCycle() {
        PanelFixture panel(options());
        editAt(panel, 10, 18);  // on the cycle
        panel.press(Qt::Key_F4);
        panel.press(Qt::Key_F8);
        chooseByKeys(panel, "Save as NC blocks (expanded)");
        const QString text = QString::fromStdString(panel.session->program(0, 10)->source.str());
        QVERIFY2(text.contains("N0002 ; GNE CONT (3, FINAL) ;shaft\nN0003 ; GNE START Z0 X10\n"),
                 qPrintable(text));
        QVERIFY2(text.contains("N0007 ; GNE CYCLE_10 (3, 1, 0.2) expanded\n"
                               "N0007:0001 G90 G18 G40 G15\nN0007:0002 T1 ;GNE TOOL"),
                 qPrintable(text));
        QVERIFY2(!text.contains(QRegularExpression("\\n[GTSX]")), qPrintable(text));
        mtc::core::CompilerOptions options;
        options.compilerActive = true;
        const auto result = mtc::core::Compiler().compile(*panel.session->program(0, 10), options);
        QVERIFY(result.status == mtc::core::CompileStatus::Compiled);
        expectNumberedObject(result.objectText);
        runProgram(panel, 10, result.objectText, 12);
    }

    void controlWInTheEditorOpensTheGne() {
        // seed 001 ch. 3: <Control W> calls the GNE from the full screen editor
        PanelFixture panel(options());
        editAt(panel, 9, 14);
        panel.press(Qt::Key_W, Qt::ControlModifier);
        QCOMPARE(panel.window->currentScreenName(), QString("gne"));
        QCOMPARE(gneScreen(panel)->model().firstLine(), 12);
        QVERIFY(!gneScreen(panel)->model().isNew());
    }

    void unsavedEditorChangesReachTheGne() {
        PanelFixture panel(options());
        editAt(panel, 9, 14);  // START Z0 X20
        panel.press(Qt::Key_End);
        QTest::keyClick(QApplication::focusWidget(), '5');  // X205, not saved yet
        panel.press(Qt::Key_F4);
        QCOMPARE(panel.window->currentScreenName(), QString("gne"));
        auto* rows = child<QListWidget>(panel, "gne", "gneRows");
        QCOMPARE(rows->currentItem()->text(), QString("  START Z0 X205"));
        QVERIFY(panel.session->program(0, 9)->source.view().find("START Z0 X205") !=
                std::string::npos);
    }

    void randomKeysNeverBreakTheDialog() {
        PanelFixture panel(options());
        editAt(panel, 9, 15);
        panel.press(Qt::Key_F4);
        auto* screen = gneScreen(panel);
        auto* rows = child<QListWidget>(panel, "gne", "gneRows");
        const int keys[] = {Qt::Key_Up,     Qt::Key_Down,   Qt::Key_Return, Qt::Key_Escape,
                            Qt::Key_Insert, Qt::Key_Delete, Qt::Key_F1,     Qt::Key_F2,
                            Qt::Key_F3,     Qt::Key_F4,     Qt::Key_F5,     Qt::Key_F6,
                            Qt::Key_F7,     Qt::Key_F8,     Qt::Key_Right,  Qt::Key_Left,
                            Qt::Key_Plus,   Qt::Key_Minus,  Qt::Key_1,      Qt::Key_0,
                            Qt::Key_5,      Qt::Key_Period, Qt::Key_E,      Qt::Key_Home};
        std::mt19937 random(20261121);
        int saved = 0;
        for (int i = 0; i < 1500; ++i) {
            const int key = keys[random() % (sizeof keys / sizeof keys[0])];
            if (key == Qt::Key_Minus || key == Qt::Key_Period || key == Qt::Key_Plus)
                QTest::keyClick(QApplication::focusWidget(),
                                static_cast<char>(key == Qt::Key_Minus  ? '-'
                                                  : key == Qt::Key_Plus ? '+'
                                                                        : '.'));
            else
                panel.press(key);
            if (panel.window->currentScreenName() != "gne") {  // left: Esc or saved
                saved += panel.window->currentScreenName() == "editor";
                panel.window->showScreen("gne");
            }
            const auto& model = screen->model();
            QCOMPARE(rows->count(), static_cast<int>(model.rows().size()));
            QVERIFY(model.rows().empty() ||
                    model.currentRow() < static_cast<int>(model.rows().size()));
            QCOMPARE(rows->currentRow(), model.rows().empty() ? -1 : model.currentRow());
        }
        // A section without problems (the only kind that is saved) reads back as written.
        const std::string text = screen->model().keywordText();
        mtc::screens::GneEditModel again;
        again.openText(text);
        if (screen->model().sectionProblems().empty())
            QCOMPARE(QString::fromStdString(again.keywordText()), QString::fromStdString(text));
        qInfo("random keys: %d saves into the program", saved);
    }

    void cycleApartFromItsContourUsesTheProgramGeometry() {
        // A tool change between contour and cycle: two sections; the cycle's
        // section finds contour 3 (and the window) earlier in the program.
        const std::string program =
            "N0000 G0 X40 Z10\nWINDOW_01 (-40, 5, 30, 0)\nCONT (3, FINAL)\nSTART Z0 X10\n"
            "LINE Z-20 X10\nLINE Z-20 X25\nEND_CONT\nN0001 T1\nCYCLE_10 (3, 1, 0.2)\n"
            "N0002 M30\n";
        mtc::screens::GneEditModel model;
        model.open(program, 9);
        QCOMPARE(model.firstLine(), 9);
        QCOMPARE(model.rows().size(), std::size_t{1});
        QVERIFY2(model.problems().empty(), model.problems().c_str());
        std::string blocks;
        mtc::screens::gnefields::ModelText problem;
        QVERIFY2(model.ncBlocks(blocks, problem), problem.english().c_str());
        QVERIFY2(blocks.find("G1 X10 Z-20") != std::string::npos, blocks.c_str());
        // The contour's own section ends before the tool change.
        model.open(program, 5);
        QCOMPARE(model.firstLine(), 2);
        QCOMPARE(model.lastLine(), 7);
        QCOMPARE(model.currentRow(), 3);  // the LINE of line 5
        // A form numbered 3 as well is refused by the expansion, named by its row.
        mtc::screens::gnefields::ModelText message;
        QVERIFY(model.insert("FORM_20", message));
        QVERIFY(model.setField(0, "3", message));
        QVERIFY2(model.sectionProblems().find("already used") != std::string::npos,
                 model.sectionProblems().c_str());
    }

    void refusedValueKeepsTheOldOne() {
        PanelFixture panel(options());
        editAt(panel, 9, 15);  // on CCW
        panel.press(Qt::Key_F4);
        auto* rows = child<QListWidget>(panel, "gne", "gneRows");
        QVERIFY(rows->currentItem()->text().contains("CCW"));
        panel.press(Qt::Key_Return);  // to the values: Z X K I R TAN ALT
        for (int i = 0; i < 4; ++i)
            panel.press(Qt::Key_Down);
        QCOMPARE(fieldValue(panel, 4), QString("8"));
        typeValue(panel, "-3");  // a negative radius
        auto* message = child<QLabel>(panel, "gne", "gneMessage");
        QVERIFY2(message->text().contains("R = -3 is outside") &&
                     message->text().contains("old value is kept"),
                 qPrintable(message->text()));
        QCOMPARE(fieldValue(panel, 4), QString("8"));
        auto* input = child<QLineEdit>(panel, "gne", "gneInput");
        QCOMPARE(QApplication::focusWidget(), input);  // still open for a correction
        input->clear();
        typeValue(panel, "1x");
        QVERIFY2(message->text().contains("'1x' is not a number"), qPrintable(message->text()));
        panel.press(Qt::Key_Escape);
        QCOMPARE(fieldValue(panel, 4), QString("8"));
        QVERIFY(rows->currentItem()->text().endsWith("R8"));
        QVERIFY(!gneScreen(panel)->model().canUndo());  // nothing was changed
    }

    // The model's texts in German (issue 20 §1): a value's meaning, a
    // refusal with the values it names, and every parameter meaning of the
    // core's GNE calls (which lupdate cannot see) in the catalogue.
    void germanPanelShowsTheModelTextsInGerman() {
        mtc::hmi::PanelOptions german = options();
        german.language = "de";
        PanelFixture panel(german);
        for (const mtc::core::gne::CallSpec& spec : mtc::core::gne::callSpecs())
            for (const mtc::core::gne::ParamSpec& p : spec.params)
                QVERIFY2(mtc::hmi::installedCatalogueHas("GneModel", p.meaning), p.meaning);
        editAt(panel, 9, 15);  // on CCW
        panel.press(Qt::Key_F4);
        panel.press(Qt::Key_Return);  // to the values: Z X K I R TAN ALT
        for (int i = 0; i < 4; ++i)
            panel.press(Qt::Key_Down);
        auto* help = child<QLabel>(panel, "gne", "gneFieldHelp");
        QCOMPARE(help->text(), QString("Radius des Kreisbogens"));
        typeValue(panel, "-3");
        auto* message = child<QLabel>(panel, "gne", "gneMessage");
        QVERIFY2(message->text().startsWith("R = -3 liegt außerhalb 0.001 .. ") &&
                     message->text().endsWith(" - der alte Wert bleibt"),
                 qPrintable(message->text()));
        panel.press(Qt::Key_Escape);
    }

    void alternativeSelectionChangesTheDrawing() {
        PanelFixture panel(options());
        editAt(panel, 9, 15);
        panel.press(Qt::Key_F4);
        auto* screen = gneScreen(panel);
        const auto& model = screen->model();
        QCOMPARE(model.alternativeCount(), 2);
        auto* canvas = child<mtc::screens::GneCanvas>(panel, "gne", "gneCanvas");
        const QImage before = canvas->grab().toImage();
        const auto arcBefore = model.solution(1).elements[1].segments.at(0);
        panel.press(Qt::Key_F3);  // Alternative
        QCOMPARE(model.items()[1].contour.elements[1].alternative, 1);
        const auto arcAfter = model.solution(1).elements[1].segments.at(0);
        QVERIFY(std::abs(arcAfter.sweep() - arcBefore.sweep()) > 0.5);  // small <-> large arc
        const QImage after = canvas->grab().toImage();
        QVERIFY(before != after);
        QVERIFY(
            child<QListWidget>(panel, "gne", "gneRows")->currentItem()->text().endsWith("ALT1"));
        panel.press(Qt::Key_F4);  // Undo
        QCOMPARE(model.items()[1].contour.elements[1].alternative, 0);
        QCOMPARE(canvas->grab().toImage(), before);
        panel.press(Qt::Key_F5);  // Redo
        QCOMPARE(model.items()[1].contour.elements[1].alternative, 1);
        panel.press(Qt::Key_F6);  // zoom to the contour: another view
        QVERIFY(!canvas->zoomToWindow());
        QVERIFY(canvas->worldView().width() < 40);
    }
};

QTEST_MAIN(GneScreenTest)
#include "test_gne_screen.moc"
