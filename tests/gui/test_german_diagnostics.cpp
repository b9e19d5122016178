// The core's diagnostics in the panel's language (issue 20 §1,
// docs/DECISIONS.md D-023): with the panel in German the error window shows
// the German brief message of the diagnostic's code from the core's message
// table, and its additional text (F2) keeps the core's English message with
// the values it names; in English the window shows the core's message.
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
    }
};

QTEST_MAIN(GermanDiagnosticsTest)
#include "test_german_diagnostics.moc"
