// The core's diagnostics in the panel's language (issue 20 §1,
// docs/DECISIONS.md D-023): with the panel in German the error window shows
// the German brief message of the diagnostic's code from the core's message
// table, and its additional text (F2) keeps the core's English message with
// the values it names; in English the window shows the core's message.
// The one-line places (D-024): the alarm line and the message lines of the
// MDI, restart and tool screens show the German brief message, then the
// core's English message; so does the MDI history's outcome (D-026).
#include <QLabel>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QTemporaryDir>

#include "PanelFixture.h"
#include "cnc_core/cell/StationStatus.h"

using mtc::core::OperatingMode;

class GermanDiagnosticsTest : public QObject {
    Q_OBJECT
  private:
    QTemporaryDir dir_;

    static constexpr const char* kAxisUnknownLine =
        "Achse oder Spindel im Prozess nicht vorhanden — this process has no axis A";

    static QString alarmLine(PanelFixture& panel) {
        auto* alarm = panel.window->findChild<QLabel*>("headerAlarm");
        return alarm ? alarm->text() : QString("no alarm line");
    }

    mtc::hmi::PanelOptions options(const QString& language) {
        emptiedDirectory(dir_.path());
        mtc::hmi::PanelOptions o;
        o.programsDir = dir_.path();
        o.language = language;
        return o;
    }

    /// MDI mode, the blocks typed with real keys into the MDI input, Start,
    /// and the station idle again.
    static void runMdi(PanelFixture& panel, const QStringList& lines) {
        panel.window->showScreen("mdi");
        auto* input = panel.window->currentScreen()->findChild<QPlainTextEdit*>("mdiInput");
        QVERIFY(input);
        QTRY_VERIFY(input->hasFocus());
        panel.press(Qt::Key_F9, Qt::ShiftModifier);  // M key MDI
        QCOMPARE(panel.session->control(0).mode(), OperatingMode::Mdi);
        for (int i = 0; i < lines.size(); ++i) {
            if (i > 0) panel.press(Qt::Key_Return);
            QTest::keyClicks(QApplication::focusWidget(), lines[i]);
        }
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start
        QTRY_VERIFY(!panel.session->control(0).programActive());
    }

    /// The error window (F4 of the MDI screen) and the row with `code`.
    static int openErrorsAt(PanelFixture& panel, const QString& code, QListWidget*& list) {
        panel.press(Qt::Key_F4);  // error display
        if (panel.window->currentScreenName() != "errors") return -1;
        list = child<QListWidget>(panel, "errors", "errorList");
        for (int row = 0; row < list->count(); ++row) {
            list->setCurrentRow(row);
            panel.press(Qt::Key_F2);  // additional text shows the code
            const bool found = list->item(row)->text().contains("[" + code + "]");
            panel.press(Qt::Key_F2);
            if (found) return row;
        }
        return -1;
    }

  private slots:
    void initTestCase() { useTestSettings(); }

    void germanPanelShowsTheGermanMessageOfTheCode() {
        PanelFixture panel(options("de"));
        panel.session->setSpeed(1000);
        runMdi(panel, {"G1 X5 F500", "G1 X8 A10"});
        QListWidget* list = nullptr;
        const int row = openErrorsAt(panel, "AXIS_UNKNOWN", list);
        QVERIFY2(row >= 0, "the MDI error is in the error window");

        const QString brief = list->item(row)->text();
        QVERIFY2(brief.contains("Achse oder Spindel im Prozess nicht vorhanden"),
                 qPrintable(brief));
        QVERIFY2(!brief.contains("has no axis"), qPrintable(brief));

        list->setCurrentRow(row);
        panel.press(Qt::Key_F2);  // additional text: the core's message names the axis
        const QString expanded = list->item(row)->text();
        QVERIFY2(expanded.contains("this process has no axis A"), qPrintable(expanded));
        QVERIFY2(expanded.contains("MDI-Eingabe Zeile 2"), qPrintable(expanded));
        QVERIFY2(expanded.contains("G1 X8 A10"), qPrintable(expanded));
    }

    void englishPanelShowsTheCoresMessage() {
        PanelFixture panel(options("en"));
        panel.session->setSpeed(1000);
        runMdi(panel, {"G1 X5 F500", "G1 X8 A10"});
        QListWidget* list = nullptr;
        const int row = openErrorsAt(panel, "AXIS_UNKNOWN", list);
        QVERIFY2(row >= 0, "the MDI error is in the error window");
        const QString brief = list->item(row)->text();
        QVERIFY2(brief.contains("this process has no axis A"), qPrintable(brief));
        QVERIFY2(!brief.contains("Achse"), qPrintable(brief));
        const QString alarm = alarmLine(panel);
        QVERIFY2(alarm.contains("MDI line 2: error [AXIS_UNKNOWN]"), qPrintable(alarm));
        QVERIFY2(!alarm.contains("Achse"), qPrintable(alarm));
    }

    void germanAlarmLineAndMdiMessage() {
        PanelFixture panel(options("de"));
        panel.session->setSpeed(1000);
        runMdi(panel, {"G1 X5 F500", "G1 X8 A10"});
        const QString message = child<QLabel>(panel, "mdi", "mdiMessage")->text();
        QVERIFY2(message.startsWith("MDI Zeile 2: Fehler [AXIS_UNKNOWN]"), qPrintable(message));
        QVERIFY2(message.contains(kAxisUnknownLine), qPrintable(message));
        QTRY_VERIFY2(alarmLine(panel).contains(kAxisUnknownLine), qPrintable(alarmLine(panel)));
        QVERIFY2(alarmLine(panel).contains("MDI Zeile 2: Fehler [AXIS_UNKNOWN]"),
                 qPrintable(alarmLine(panel)));
        QVERIFY2(!alarmLine(panel).contains("error ["), qPrintable(alarmLine(panel)));
        // The entry's outcome in the history (D-026).
        const QString entry = child<QListWidget>(panel, "mdi", "mdiHistory")->item(0)->text();
        QVERIFY2(entry.endsWith(QString("[Fehler Zeile 2: %1]").arg(kAxisUnknownLine)),
                 qPrintable(entry));
    }

    void refusalOfAMachineKeyInThePanelsLanguage_data() {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QString>("alarm");
        QTest::newRow("de") << "de"
                            << "Start abgelehnt: zuerst Automatik anwählen";
        QTest::newRow("en") << "en"
                            << "Start refused: select automatic mode first";
    }

    void refusalOfAMachineKeyInThePanelsLanguage() {
        QFETCH(QString, language);
        QFETCH(QString, alarm);
        PanelFixture panel(options(language));
        panel.press(Qt::Key_F3, Qt::ShiftModifier);  // M key Manual
        QCOMPARE(panel.session->control(0).mode(), OperatingMode::Manual);
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start: refused in manual mode
        QTRY_VERIFY2(alarmLine(panel).contains(alarm), qPrintable(alarmLine(panel)));
    }

    void germanRestartMessage() {
        mtc::hmi::PanelOptions o;
        o.language = "de";
        PanelFixture panel(o);
        QVERIFY(panel.session->selectProgram(0, 1));
        panel.press(Qt::Key_F1, Qt::ShiftModifier);  // M key NC program restart
        QCOMPARE(panel.window->currentScreenName(), QString("restart"));
        panel.press(Qt::Key_Home);
        panel.press(Qt::Key_Down);
        panel.press(Qt::Key_Down);  // N0002: no jump or call
        panel.press(Qt::Key_F1);    // Plane+
        const QString message =
            panel.window->screen(0, "restart")->findChild<QLabel*>("restartMessage")->text();
        QVERIFY2(message.contains("Satz ohne Sprung oder Aufruf für Ebene+ — the block has no "
                                  "jump or call"),
                 qPrintable(message));
    }

    void germanToolScreenRefusal() {
        QTemporaryDir data;
        mtc::hmi::PanelOptions o;
        o.language = "de";
        o.dataFile = data.filePath("cell.mdt");
        PanelFixture panel(o);
        panel.session->setTimerEnabled(false);
        QVERIFY(panel.window->showScreen("tools"));
        panel.press(Qt::Key_Return);  // edit R of T1 E1
        QTest::keyClicks(QApplication::focusWidget(), "-1");
        panel.press(Qt::Key_Return);
        const QString message =
            panel.window->screen(0, "tools")->findChild<QLabel*>("toolMessage")->text();
        QVERIFY2(message.contains("Werkzeugwert ungültig — key 'radius' = '-1': out of range"),
                 qPrintable(message));
        QVERIFY2(!message.contains("Refused"), qPrintable(message));
    }
};

QTEST_MAIN(GermanDiagnosticsTest)
#include "test_german_diagnostics.moc"
