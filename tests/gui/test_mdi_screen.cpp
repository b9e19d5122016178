// MDI screen (docs/decisions/mdi.md): the MDI key selects the mode, typed
// blocks run on Start from the station's state, global macros of the program
// directory are expanded, DEFINE and compiler keywords are refused with the
// input kept, runtime errors reach the error window with origin MDI, Start in
// automatic mode runs the selected program and not the MDI entry, while a
// program runs the screen shows the block the axes execute, and each
// station keeps its own input.
#include <QLabel>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QTemporaryDir>

#include "PanelFixture.h"
#include "cnc_core/machine/SimulatedMachine.h"

using mtc::core::OperatingMode;

class MdiScreenTest : public QObject {
    Q_OBJECT
  private:
    QTemporaryDir dir_;

    mtc::hmi::PanelOptions options(const QString& language = "en") {
        const QDir dir = emptiedDirectory(dir_.path());
        writeProgram(dir, 3, programHeader(3, "Move to X44") + "N0000 G0 G90 X44\nN0001 M30\n");
        writeProgram(dir, 4,
                     programHeader(4, "Long move, then incremental") +
                         "N0000 G0 G90 X0\nN0001 G1 X100 F600\nN0002 G0 G91 X10\n"
                         "N0003 G1 F900 X5\nN0004 M30\n");
        writeGlobalMacros(dir, "DEFINE FAST AS G1 F3000\nDEFINE ROUND AS RD2\n");
        mtc::hmi::PanelOptions o;
        o.programsDir = dir_.path();
        o.language = language;
        return o;
    }

    /// Shows the MDI screen of the current station; the input has the focus.
    static QPlainTextEdit* openMdi(PanelFixture& panel) {
        panel.window->showScreen("mdi");
        auto* input = panel.window->currentScreen()->findChild<QPlainTextEdit*>("mdiInput");
        if (!input) qFatal("no MDI input");
        if (!QTest::qWaitFor([input] { return input->hasFocus(); }))
            qWarning("MDI input has no focus");
        return input;
    }

    /// Types `text` (lines separated by '\n') with real keys into the focus widget.
    static void type(PanelFixture& panel, const QString& text) {
        const QStringList lines = text.split('\n');
        for (int i = 0; i < lines.size(); ++i) {
            if (i > 0) panel.press(Qt::Key_Return);
            QTest::keyClicks(QApplication::focusWidget(), lines[i]);
        }
    }

    static void mdiMode(PanelFixture& panel) {
        panel.press(Qt::Key_F9, Qt::ShiftModifier);  // M key MDI
        QCOMPARE(panel.session->control(panel.window->currentStation()).mode(), OperatingMode::Mdi);
    }

    /// Start (Shift+F5) and wait until the station is idle again.
    static void startAndWait(PanelFixture& panel) {
        const int slot = panel.window->currentStation();
        panel.press(Qt::Key_F5, Qt::ShiftModifier);
        QTRY_VERIFY(!panel.session->control(slot).programActive());
    }

    static QString label(PanelFixture& panel, const char* name) {
        return child<QLabel>(panel, "mdi", name)->text();
    }

  private slots:
    void initTestCase() { useTestSettings(); }

    // The screen's texts in the panel's language; the message and the
    // history's outcome come from the core (docs/DECISIONS.md D-026).
    void typedBlocksMoveTheAxisAndTheStateContinues_data() {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QString>("ready");
        QTest::addColumn<QString>("done");      // message
        QTest::addColumn<QString>("outcome");   // history
        QTest::addColumn<QString>("recalled");  // message after F2
        QTest::newRow("en") << "en"
                            << "Start runs the input"
                            << "MDI entry done"
                            << "[done]"
                            << "Entry 2 recalled: Start runs it";
        QTest::newRow("de") << "de"
                            << "Start führt die Eingabe aus"
                            << "MDI-Eingabe ausgeführt"
                            << "[ausgeführt]"
                            << "Eingabe 2 zurückgeholt: Start führt sie aus";
    }

    void typedBlocksMoveTheAxisAndTheStateContinues() {
        QFETCH(QString, language);
        QFETCH(QString, ready);
        QFETCH(QString, done);
        QFETCH(QString, outcome);
        QFETCH(QString, recalled);
        PanelFixture panel(options(language));
        panel.session->setSpeed(1000);
        QPlainTextEdit* input = openMdi(panel);
        mdiMode(panel);
        QVERIFY2(label(panel, "mdiMode").contains(ready), qPrintable(label(panel, "mdiMode")));
        type(panel, "G1 G91 X10 F1000\nY5");
        QCOMPARE(input->toPlainText(), QString("G1 G91 X10 F1000\nY5"));
        startAndWait(panel);
        const auto& machine = panel.session->machine(0);
        QCOMPARE(machine.position(0), 10.0);
        QCOMPARE(machine.position(1), 5.0);
        QVERIFY2(label(panel, "mdiPosition").contains("X 10.000"),
                 qPrintable(label(panel, "mdiPosition")));
        QVERIFY2(label(panel, "mdiModal").contains("G91"), qPrintable(label(panel, "mdiModal")));
        QVERIFY2(label(panel, "mdiModal").contains("F1000"), qPrintable(label(panel, "mdiModal")));
        QCOMPARE(input->toPlainText(), QString());  // done: ready for the next entry (MDI-004)
        auto* history = child<QListWidget>(panel, "mdi", "mdiHistory");
        QCOMPARE(history->count(), 1);
        QVERIFY2(history->item(0)->text().endsWith(outcome), qPrintable(history->item(0)->text()));
        QCOMPARE(label(panel, "mdiMessage"), done);

        // The next entry continues incrementally with the modal G1 and F.
        type(panel, "X-4");
        startAndWait(panel);
        QCOMPARE(machine.position(0), 6.0);
        QCOMPARE(machine.position(1), 5.0);
        QCOMPARE(history->count(), 2);

        panel.press(Qt::Key_F2);  // Recall the selected (last) entry
        QCOMPARE(input->toPlainText(), QString("X-4"));
        QCOMPARE(label(panel, "mdiMessage"), recalled);
        startAndWait(panel);
        QCOMPARE(machine.position(0), 2.0);
    }

    void aGlobalMacroIsExpanded() {
        PanelFixture panel(options());
        panel.session->setSpeed(1000);
        openMdi(panel);
        mdiMode(panel);
        type(panel, "G90 FAST X20");
        panel.press(Qt::Key_F1);  // Check input
        QVERIFY2(label(panel, "mdiMessage").contains("G90 G1 F3000 X20"),
                 qPrintable(label(panel, "mdiMessage")));
        startAndWait(panel);
        QCOMPARE(panel.session->machine(0).position(0), 20.0);
        QVERIFY2(label(panel, "mdiModal").contains("F3000"), qPrintable(label(panel, "mdiModal")));
        QCOMPARE(panel.session->control(0).alarm(), std::string());
    }

    void aDefineOrACompilerKeywordIsRefusedAndTheInputStays() {
        PanelFixture panel(options());
        panel.session->setSpeed(1000);
        QPlainTextEdit* input = openMdi(panel);
        mdiMode(panel);
        type(panel, "G1 X5 F100\nDEFINE SLOW AS F10");
        panel.press(Qt::Key_F5, Qt::ShiftModifier);
        QVERIFY(!panel.session->control(0).programActive());
        QVERIFY2(label(panel, "mdiMessage").startsWith("MDI line 2: error [MDI_KEYWORD_REFUSED]"),
                 qPrintable(label(panel, "mdiMessage")));
        QCOMPARE(input->toPlainText(), QString("G1 X5 F100\nDEFINE SLOW AS F10"));
        QCOMPARE(panel.session->machine(0).position(0), 0.0);

        input->clear();
        type(panel, "G1 X5 F100 ROUND");  // the macro brings RD in
        panel.press(Qt::Key_F5, Qt::ShiftModifier);
        QVERIFY2(label(panel, "mdiMessage").contains("RD"), qPrintable(label(panel, "mdiMessage")));
        QCOMPARE(input->toPlainText(), QString("G1 X5 F100 ROUND"));
        QCOMPARE(panel.session->machine(0).position(0), 0.0);
        QVERIFY2(QString::fromStdString(panel.session->control(0).alarm()).startsWith("MDI line 1"),
                 panel.session->control(0).alarm().c_str());

        auto* history = child<QListWidget>(panel, "mdi", "mdiHistory");
        QCOMPARE(history->count(), 0);  // nothing ran
        const auto* screen = panel.window->screen(0, "errors");
        auto* list = screen->findChild<QListWidget*>("errorList");
        QVERIFY(list->count() >= 2);
        QVERIFY2(list->item(list->count() - 1)->text().contains("MDI"),
                 qPrintable(list->item(list->count() - 1)->text()));
    }

    void aRuntimeErrorLandsInTheErrorWindowWithOriginMdi() {
        PanelFixture panel(options());
        panel.session->setSpeed(1000);
        QPlainTextEdit* input = openMdi(panel);
        mdiMode(panel);
        type(panel, "G1 X5 F500\nG1 X8 A10");
        startAndWait(panel);
        QCOMPARE(panel.session->machine(0).position(0), 5.0);
        QCOMPARE(input->toPlainText(), QString("G1 X5 F500\nG1 X8 A10"));  // kept
        QVERIFY2(label(panel, "mdiMessage").startsWith("MDI line 2: error [AXIS_UNKNOWN]"),
                 qPrintable(label(panel, "mdiMessage")));
        auto* history = child<QListWidget>(panel, "mdi", "mdiHistory");
        QVERIFY2(history->item(0)->text().contains("[error line 2: this process has no axis A]"),
                 qPrintable(history->item(0)->text()));

        panel.press(Qt::Key_F4);  // Error display
        QCOMPARE(panel.window->currentScreenName(), QString("errors"));
        auto* list = child<QListWidget>(panel, "errors", "errorList");
        int row = -1;
        for (int i = 0; i < list->count(); ++i)
            if (list->item(i)->text().contains("AXIS_UNKNOWN") ||
                list->item(i)->text().contains("MDI "))
                row = i;
        QVERIFY2(row >= 0, "an MDI message in the error window");
        QVERIFY2(list->item(row)->text().contains("MDI"), qPrintable(list->item(row)->text()));
        list->setCurrentRow(row);
        panel.press(Qt::Key_F2);  // additional text
        const QString text = list->item(row)->text();
        QVERIFY2(text.contains("MDI input line 2"), qPrintable(text));
        QVERIFY2(text.contains("G1 X8 A10"), qPrintable(text));
        QVERIFY2(text.contains("[AXIS_UNKNOWN]"), qPrintable(text));
        // Not also reported as a runtime error of the selected program.
        for (int i = 0; i < list->count(); ++i)
            QVERIFY2(!list->item(i)->text().contains("runtime"), qPrintable(list->item(i)->text()));
    }

    void startInAutomaticModeRunsTheProgramNotTheEntry() {
        PanelFixture panel(options());
        panel.session->setSpeed(1000);
        openMdi(panel);
        type(panel, "G1 X33 F1000");
        QVERIFY2(label(panel, "mdiMode").contains("Start does not run this input"),
                 qPrintable(label(panel, "mdiMode")));
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // automatic, nothing selected
        QVERIFY(!panel.session->control(0).programActive());
        QCOMPARE(panel.session->machine(0).position(0), 0.0);
        QVERIFY(panel.session->selectProgram(0, 3));
        startAndWait(panel);
        QCOMPARE(panel.session->machine(0).position(0), 44.0);
        QCOMPARE(child<QListWidget>(panel, "mdi", "mdiHistory")->count(), 0);
        QCOMPARE(child<QPlainTextEdit>(panel, "mdi", "mdiInput")->toPlainText(),
                 QString("G1 X33 F1000"));

        // MDI after the program: from X44, then the program is selected again.
        mdiMode(panel);
        type(panel, "\nG91 X1");
        startAndWait(panel);
        QCOMPARE(panel.session->machine(0).position(0), 34.0);
        QCOMPARE(panel.session->control(0).selectedProgram(), 3);
    }

    // While a program runs, the interpreter is the look-ahead ahead of the
    // axes: the screen shows the block the axes execute (as the base screen
    // does), not the state the interpreter has reached further on.
    void whileAProgramRunsTheScreenShowsTheBlockTheAxesExecute() {
        PanelFixture panel(options());
        panel.session->setTimerEnabled(false);
        openMdi(panel);
        QVERIFY(panel.session->selectProgram(0, 4));
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start in automatic mode
        panel.session->advance(3.0);                 // the axes are on N0001 (10 s at F600)
        QVERIFY(panel.session->control(0).programActive());
        const double x = panel.session->machine(0).position(0);
        QVERIFY2(x > 10.0 && x < 40.0, qPrintable(QString::number(x)));
        const QString modal = label(panel, "mdiModal");
        QVERIFY2(modal.startsWith("G1 ") && modal.contains("G90") && modal.contains("F600"),
                 qPrintable(modal));
        QCOMPARE(label(panel, "mdiPositionCaption"), QString("Position (actual, running program)"));
        const QString position = label(panel, "mdiPosition");
        QVERIFY2(position.startsWith(QString("X %1").arg(x, 0, 'f', 3)), qPrintable(position));

        panel.session->advance(30.0);  // the program ends: the interpreter's state again
        QVERIFY(!panel.session->control(0).programActive());
        QVERIFY2(label(panel, "mdiModal").contains("F900"), qPrintable(label(panel, "mdiModal")));
        QCOMPARE(label(panel, "mdiPositionCaption"), QString("Position (programmed)"));
        QVERIFY2(label(panel, "mdiPosition").startsWith("X 115.000"),
                 qPrintable(label(panel, "mdiPosition")));
    }

    void controlResetAbandonsAHeldEntryAndKeepsTheInput() {
        PanelFixture panel(options());
        panel.session->setSpeed(1000);
        QPlainTextEdit* input = openMdi(panel);
        mdiMode(panel);
        type(panel, "G1 X3 F600\nM0\nX9");
        panel.press(Qt::Key_F5, Qt::ShiftModifier);
        QTRY_VERIFY(panel.session->control(0).programHeld());
        QCOMPARE(panel.session->machine(0).position(0), 3.0);
        panel.press(Qt::Key_F4, Qt::ShiftModifier);  // Automatic: refused while the entry is active
        QCOMPARE(panel.session->control(0).mode(), OperatingMode::Mdi);
        panel.press(Qt::Key_F7, Qt::ShiftModifier);  // Control reset
        QVERIFY(!panel.session->control(0).programActive());
        QCOMPARE(input->toPlainText(), QString("G1 X3 F600\nM0\nX9"));
        auto* history = child<QListWidget>(panel, "mdi", "mdiHistory");
        QVERIFY2(history->item(0)->text().contains("[reset]"),
                 qPrintable(history->item(0)->text()));
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // the whole entry again; M0 holds
        QTRY_VERIFY(panel.session->control(0).programHeld());
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // go on after M0
        QTRY_VERIFY(!panel.session->control(0).programActive());
        QCOMPARE(panel.session->machine(0).position(0), 9.0);
    }

    void singleBlockHoldsAfterEachBlockOfTheEntry() {
        PanelFixture panel(options());
        panel.session->setSpeed(1000);
        openMdi(panel);
        mdiMode(panel);
        type(panel, "G1 X2 F600\nX4");
        panel.press(Qt::Key_F8, Qt::ShiftModifier);  // single block on
        panel.press(Qt::Key_F5, Qt::ShiftModifier);
        QTRY_VERIFY(panel.session->control(0).programHeld());
        QCOMPARE(panel.session->machine(0).position(0), 2.0);
        QVERIFY2(label(panel, "mdiMode").contains("held"), qPrintable(label(panel, "mdiMode")));
        startAndWait(panel);  // the last block ends the entry: no further hold
        QCOMPARE(panel.session->machine(0).position(0), 4.0);
        QVERIFY(!panel.session->control(0).programHeld());
        QVERIFY(child<QListWidget>(panel, "mdi", "mdiHistory")->item(0)->text().contains("[done]"));
    }

    void eachStationKeepsItsInput() {
        PanelFixture panel(options());
        QPlainTextEdit* mill = openMdi(panel);
        type(panel, "G1 X1 F100");
        panel.press(Qt::Key_PageDown, Qt::ControlModifier);
        QCOMPARE(panel.window->currentStation(), 1);
        QPlainTextEdit* lathe = openMdi(panel);
        QVERIFY(lathe != mill);
        type(panel, "G0 Z2");
        panel.press(Qt::Key_PageUp, Qt::ControlModifier);
        QCOMPARE(panel.window->currentStation(), 0);
        QCOMPARE(panel.window->currentScreenName(), QString("mdi"));
        QCOMPARE(mill->toPlainText(), QString("G1 X1 F100"));
        QCOMPARE(lathe->toPlainText(), QString("G0 Z2"));
    }
};

QTEST_MAIN(MdiScreenTest)
#include "test_mdi_screen.moc"
