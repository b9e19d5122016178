// Jogging on the base screen in manual mode (issue 17 §2), by the real
// keys: ↑/↓ choose the axis, + / − jog it by the step F6 chooses, a held
// key in continuous mode moves until it is released, the mouse wheel is
// the handwheel, a jog beyond the travel limit is refused with an alarm
// (in the panel's language).
// Time is stepped by the test through CellSession::advance.
#include <QLabel>
#include <QWheelEvent>
#include <QtTest>

#include "PanelFixture.h"

namespace {

/// A label of the screen shown (the header's when the screen has none).
QString label(PanelFixture& panel, const char* name) {
    QLabel* found = panel.window->currentScreen()->findChild<QLabel*>(name);
    if (!found) found = panel.window->findChild<QLabel*>(name);
    if (!found) qFatal("no label %s", name);
    return found->text();
}

void settle(PanelFixture& panel, int slot = 0) {
    for (int tick = 0; tick < 20'000 && panel.session->station(slot).jogging(); ++tick)
        panel.session->advance(0.02);
}

/// The base screen of the mill in manual mode.
void manualBaseScreen(PanelFixture& panel) {
    panel.session->setTimerEnabled(false);
    panel.press(Qt::Key_F3, Qt::ShiftModifier);  // M key Manual
    panel.press(Qt::Key_F11);
    QCOMPARE(panel.window->currentScreenName(), QString("position"));
}

}  // namespace

class ManualJogTest : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase() { useTestSettings(); }

    void incrementsByKeysOnTheChosenAxis() {
        PanelFixture panel;
        manualBaseScreen(panel);
        QVERIFY2(label(panel, "jogLine").contains("jog X"), qPrintable(label(panel, "jogLine")));
        panel.press(Qt::Key_Plus);  // 1 mm, the default step
        settle(panel);
        const auto& mill = panel.session->station(0);
        QCOMPARE(mill.machine().position(0), 1.0);
        QCOMPARE(label(panel, "axisMachine-0"), QString("+1.000"));
        panel.press(Qt::Key_Down);  // Y
        QVERIFY(label(panel, "jogLine").contains("jog Y"));
        panel.press(Qt::Key_F6);  // step 10
        panel.press(Qt::Key_Minus);
        panel.press(Qt::Key_Minus);
        settle(panel);
        QCOMPARE(mill.machine().position(1), -20.0);
        for (int i = 0; i < 3; ++i)
            panel.press(Qt::Key_F6);  // continuous, 0.001, 0.01
        QVERIFY(label(panel, "jogLine").contains("step 0.010"));
        panel.press(Qt::Key_Plus);
        settle(panel);
        QCOMPARE(mill.machine().position(1), -19.99);
    }

    void aHeldKeyMovesUntilReleased() {
        PanelFixture panel;
        manualBaseScreen(panel);
        panel.press(Qt::Key_F6);
        panel.press(Qt::Key_F6);  // 10 -> continuous
        QVERIFY(label(panel, "jogLine").contains("continuous"));
        QWidget* screen = panel.window->currentScreen();
        QTest::keyPress(screen, Qt::Key_Plus);
        panel.session->advance(0.5);
        const auto& mill = panel.session->station(0);
        const double whileHeld = mill.machine().position(0);
        QVERIFY2(whileHeld > 10.0, qPrintable(QString::number(whileHeld)));
        QTest::keyRelease(screen, Qt::Key_Plus);
        settle(panel);
        QVERIFY(mill.machine().position(0) > whileHeld);
        QVERIFY(mill.machine().position(0) < 400.0);
        QVERIFY(mill.machine().idle());
    }

    void theWheelIsAHandwheel() {
        PanelFixture panel;
        manualBaseScreen(panel);
        panel.press(Qt::Key_F6);  // 10
        panel.press(Qt::Key_F6);  // continuous
        panel.press(Qt::Key_F6);  // 0.001
        QWidget* screen = panel.window->currentScreen();
        const QPointF at(screen->width() / 4.0, screen->height() / 4.0);
        QWheelEvent wheel(at, screen->mapToGlobal(at.toPoint()), QPoint(), QPoint(0, 3 * 120),
                          Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(screen, &wheel);
        settle(panel);
        QCOMPARE(panel.session->station(0).machine().position(0), 0.003);
    }

    // The refusal in the panel's language (docs/DECISIONS.md D-026): the
    // core's text for the code ALARM_JOG_TRAVEL_LIMIT with its values.
    void aJogBeyondTheTravelLimitIsRefusedWithAnAlarm_data() {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QString>("rapid");
        QTest::addColumn<QString>("alarm");
        QTest::newRow("en") << "en"
                            << "rapid"
                            << "Travel limit: X may move from -400.000 to 400.000 (jog to 410.000 "
                               "refused)";
        QTest::newRow("de") << "de"
                            << "Eilgang"
                            << "Verfahrgrenze: X darf von -400.000 bis 400.000 fahren (Tippen nach "
                               "410.000 abgelehnt)";
    }

    void aJogBeyondTheTravelLimitIsRefusedWithAnAlarm() {
        QFETCH(QString, language);
        QFETCH(QString, rapid);
        QFETCH(QString, alarm);
        mtc::hmi::PanelOptions options;
        options.language = language;
        PanelFixture panel(options);
        manualBaseScreen(panel);
        panel.press(Qt::Key_F6);  // 10 mm steps
        panel.press(Qt::Key_F7);  // rapid
        QVERIFY(label(panel, "jogLine").contains(rapid));
        for (int i = 0; i < 40; ++i)
            panel.press(Qt::Key_Plus);
        settle(panel);
        QCOMPARE(panel.session->station(0).machine().position(0), 400.0);
        panel.press(Qt::Key_Plus);
        QVERIFY2(label(panel, "headerAlarm").contains(alarm),
                 qPrintable(label(panel, "headerAlarm")));
        settle(panel);
        QCOMPARE(panel.session->station(0).machine().position(0), 400.0);
    }

    void theSpindleKeysTurnTheFirstSpindle() {
        PanelFixture panel;
        manualBaseScreen(panel);
        panel.press(Qt::Key_3);  // M3 at the 500 rpm start speed
        panel.press(Qt::Key_PageUp);
        panel.press(Qt::Key_PageUp);
        for (int tick = 0; tick < 500; ++tick)
            panel.session->advance(0.02);
        QCOMPARE(panel.session->station(0).machine().spindles().actualSpeed(1), 700.0);
        QVERIFY2(label(panel, "spindleValues").contains("700 / 700 rpm CW"),
                 qPrintable(label(panel, "spindleValues")));
        panel.press(Qt::Key_5);
        for (int tick = 0; tick < 500; ++tick)
            panel.session->advance(0.02);
        QVERIFY2(label(panel, "spindleValues").contains("stopped"),
                 qPrintable(label(panel, "spindleValues")));
    }

    void theLatheJogsItsOwnAxes() {
        PanelFixture panel;
        panel.session->setTimerEnabled(false);
        panel.press(Qt::Key_PageDown, Qt::ControlModifier);  // the lathe
        panel.press(Qt::Key_F3, Qt::ShiftModifier);          // its M key Manual
        panel.press(Qt::Key_F11);
        QVERIFY2(label(panel, "jogLine").contains("jog X"), qPrintable(label(panel, "jogLine")));
        panel.press(Qt::Key_Down);  // the lathe's second axis
        const auto& lathe = panel.session->station(1);
        const int axis = 1;
        const double before = lathe.machine().position(axis);
        panel.press(Qt::Key_Minus);  // 1 mm
        settle(panel, 1);
        QCOMPARE(lathe.machine().position(axis), before - 1.0);
        QCOMPARE(panel.session->station(0).machine().position(0), 0.0);  // the mill stays
        QCOMPARE(panel.session->station(0).control().mode(), mtc::core::OperatingMode::Automatic);
    }

    void automaticModeDoesNotJog() {
        PanelFixture panel;
        panel.session->setTimerEnabled(false);
        panel.press(Qt::Key_F11);
        QVERIFY(!panel.window->currentScreen()->findChild<QLabel*>("jogLine")->isVisible());
        panel.press(Qt::Key_Plus);
        panel.session->advance(1.0);
        QCOMPARE(panel.session->station(0).machine().position(0), 0.0);
    }
};

QTEST_MAIN(ManualJogTest)
#include "test_manual_jog.moc"
