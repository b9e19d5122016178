// Help (F12, issue 20 §4): on a screen, that screen's help (what it is for,
// the seed section, its soft keys and other keys) and the panel's keys; from
// the main menu, every screen's soft keys. Every screen has a help text.
#include <QTextBrowser>

#include "PanelFixture.h"
#include "hmi/KeyMap.h"
#include "screens/help/ScreenHelpTexts.h"

class HelpScreenTest : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { useTestSettings(); }

    static QString shownHelp(PanelFixture& panel) {
        auto* text = panel.window->screen(0, "help")->findChild<QTextBrowser*>("helpText");
        return text->toPlainText();
    }

    void fromTheMenuListsGlobalAndScreenKeys() {
        PanelFixture panel;
        panel.window->showScreen("menu");
        panel.press(Qt::Key_F12);
        QCOMPARE(panel.window->currentScreenName(), QString("help"));
        const QString shown = shownHelp(panel);
        for (const auto& assignment : mtc::hmi::globalKeyAssignments())
            QVERIFY2(shown.contains(assignment.keys), qPrintable(assignment.keys));
        QVERIFY(shown.contains("Ctrl+PgUp"));
        QVERIFY(shown.contains("Machine control key 'Start'"));
        for (const auto& entry : panel.registry.entries())
            if (entry.name != "help")
                QVERIFY2(shown.contains(entry.title), qPrintable(entry.title));
        QVERIFY(shown.contains("Select program"));
        QVERIFY(shown.contains("Clear log"));
        panel.press(Qt::Key_F8);  // Back
        QCOMPARE(panel.window->currentScreenName(), QString("menu"));
    }

    void onAScreenF12ShowsThatScreensHelpAndF8GoesBack() {
        PanelFixture panel;
        panel.window->showScreen("tools");
        panel.press(Qt::Key_F12);
        QCOMPARE(panel.window->currentScreenName(), QString("help"));
        const QString shown = shownHelp(panel);
        const auto* help = mtc::screens::screenHelpText("tools");
        QVERIFY(help);
        QVERIFY2(shown.contains(QString::fromUtf8(help->purpose)), qPrintable(shown));
        QVERIFY2(shown.contains("Reproduces: " + QString::fromUtf8(help->seed)), qPrintable(shown));
        QVERIFY2(shown.contains("F1") && shown.contains("Edit"),
                 qPrintable(shown));                                // its soft keys
        QVERIFY2(shown.contains("Home / End"), qPrintable(shown));  // its other keys
        QVERIFY2(!shown.contains("Interface signals"), "only the tool table's help, no overview");
        panel.press(Qt::Key_F8);  // Back to where F12 was pressed
        QCOMPARE(panel.window->currentScreenName(), QString("tools"));

        panel.window->showScreen("position");
        panel.press(Qt::Key_F12);
        QVERIFY2(shownHelp(panel).contains("handwheel"), qPrintable(shownHelp(panel)));
    }

    void everyScreenHasAHelpText() {
        PanelFixture panel;
        for (const auto& entry : panel.registry.entries()) {
            const auto* help = mtc::screens::screenHelpText(entry.name);
            QVERIFY2(help, qPrintable("no help text for " + entry.name));
            QVERIFY2(*help->purpose, qPrintable(entry.name));
        }
    }
};

QTEST_MAIN(HelpScreenTest)
#include "test_help_screen.moc"
