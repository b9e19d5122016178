// Help: every global key and every screen's soft keys are listed.
#include <QTextBrowser>

#include "PanelFixture.h"
#include "hmi/KeyMap.h"

class HelpScreenTest : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { useTestSettings(); }

    void listsGlobalAndScreenKeys() {
        PanelFixture panel;
        panel.press(Qt::Key_F12);
        QCOMPARE(panel.window->currentScreenName(), QString("help"));
        auto* text = panel.window->screen(0, "help")->findChild<QTextBrowser*>("helpText");
        const QString shown = text->toPlainText();
        for (const auto& assignment : mtc::hmi::globalKeyAssignments())
            QVERIFY2(shown.contains(assignment.keys), qPrintable(assignment.keys));
        QVERIFY(shown.contains("Ctrl+PgUp"));
        QVERIFY(shown.contains("Machine control key 'Start'"));
        for (const auto& entry : panel.registry.entries())
            if (entry.name != "help")
                QVERIFY2(shown.contains(entry.title), qPrintable(entry.title));
        QVERIFY(shown.contains("Select program"));
        QVERIFY(shown.contains("Clear log"));
    }
};

QTEST_MAIN(HelpScreenTest)
#include "test_help_screen.moc"
