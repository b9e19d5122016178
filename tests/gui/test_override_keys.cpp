// The override switches on the panel (issue 17 §3): Alt+Up / Alt+Down step
// the feed override, Alt+PgUp / Alt+PgDn the rapid override, of the station
// shown; the percentages stand under the M keys and on the base screen,
// and a running move changes its feed at once. Time is stepped by the test.
#include <QLabel>
#include <QPushButton>
#include <QtTest>

#include "PanelFixture.h"
#include "cnc_core/cell/StationStatus.h"

namespace {

QString text(PanelFixture& panel, const char* name) {
    auto* label = panel.window->findChild<QLabel*>(name);
    if (!label) qFatal("no label %s", name);
    return label->text();
}

}  // namespace

class OverrideKeysTest : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase() { useTestSettings(); }

    void feedOverrideKeysSlowTheRunningMove() {
        PanelFixture panel;
        panel.session->setTimerEnabled(false);
        panel.session->addProgram(0, 64, "override.nc", "N0001 G90 G1 X200 F600\nN0002 M30\n");
        QVERIFY(panel.session->selectProgram(0, 64));
        QCOMPARE(text(panel, "feedOverrideSwitch"), QString("F 100%"));
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start
        panel.session->advance(1.0);
        const mtc::core::Station& mill = panel.session->station(0);
        QCOMPARE(mtc::core::describeStation(mill).actualFeed, 600.0);

        for (int i = 0; i < 5; ++i)
            panel.press(Qt::Key_Down, Qt::AltModifier);  // 90, 80, 70, 60, 50 %
        QCOMPARE(mill.feedOverride(), 50);
        QCOMPARE(text(panel, "feedOverrideSwitch"), QString("F 50%"));
        panel.session->advance(1.0);
        QCOMPARE(mtc::core::describeStation(mill).actualFeed, 300.0);

        for (int i = 0; i < 20; ++i)
            panel.press(Qt::Key_Up, Qt::AltModifier);
        QCOMPARE(mill.feedOverride(), mill.feedOverrideMax());  // the switch ends at B074
        for (int i = 0; i < 30; ++i)
            panel.press(Qt::Key_Down, Qt::AltModifier);
        QCOMPARE(mill.feedOverride(), 0);
        const double x = mill.machine().position(0);
        panel.session->advance(2.0);
        QVERIFY2(mill.machine().position(0) - x < 2.0, "at 0 % the axes brake and stand");
        panel.session->advance(2.0);
        QCOMPARE(mtc::core::describeStation(mill).actualFeed, 0.0);
        QVERIFY(mill.control().programActive());
    }

    void rapidOverrideAndTheButtonsActOnTheStationShown() {
        PanelFixture panel;
        panel.press(Qt::Key_PageDown, Qt::AltModifier);
        QCOMPARE(panel.session->station(0).rapidOverride(), 50);
        QCOMPARE(text(panel, "rapidOverrideSwitch"), QString("G0 50%"));
        panel.press(Qt::Key_PageDown, Qt::ControlModifier);  // the lathe
        QCOMPARE(text(panel, "rapidOverrideSwitch"), QString("G0 100%"));
        panel.window->findChild<QPushButton*>("feedOverrideSwitchDown")->click();
        QCOMPARE(panel.session->station(1).feedOverride(), 90);
        QCOMPARE(panel.session->station(0).feedOverride(), 100);  // the mill keeps its own
        QCOMPARE(text(panel, "feedOverrideSwitch"), QString("F 90%"));
        panel.window->findChild<QPushButton*>("rapidOverrideSwitchUp")->click();
        QCOMPARE(panel.session->station(1).rapidOverride(), 100);
    }
};

QTEST_MAIN(OverrideKeysTest)
#include "test_override_keys.moc"
