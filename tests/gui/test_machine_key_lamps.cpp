// The machine control keys carry lamps (issue 17 §3): the active mode,
// single block, feed hold, a running program, an NC program restart; the
// header names the program's state (never "active" after Stop), and an
// ordinary state such as a single-block hold is a prompt, not an alarm.
// Time is stepped by the test through CellSession::advance.
#include <QLabel>
#include <QPushButton>
#include <QtTest>

#include "PanelFixture.h"
#include "hmi/MachineKeyBar.h"

using mtc::core::ControlKey;

namespace {

bool lamp(PanelFixture& panel, ControlKey key) {
    auto* bar = panel.window->findChild<mtc::hmi::MachineKeyBar*>("machineKeyBar");
    QPushButton* button = bar ? bar->button(key) : nullptr;
    if (!button) qFatal("no machine key %s", mtc::core::keyName(key));
    return button->property("lamp").toBool();
}

QString header(PanelFixture& panel, const char* name) {
    return panel.window->findChild<QLabel*>(name)->text();
}

}  // namespace

class MachineKeyLampsTest : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase() { useTestSettings(); }

    void modeKeysLightTheActiveMode() {
        PanelFixture panel;
        QVERIFY(lamp(panel, ControlKey::Automatic));
        QVERIFY(!lamp(panel, ControlKey::Manual));
        panel.press(Qt::Key_F3, Qt::ShiftModifier);  // Manual
        QVERIFY(lamp(panel, ControlKey::Manual));
        QVERIFY(!lamp(panel, ControlKey::Automatic));
        panel.press(Qt::Key_F9, Qt::ShiftModifier);  // MDI
        QVERIFY(lamp(panel, ControlKey::Mdi));
        QVERIFY(!lamp(panel, ControlKey::Manual));
        panel.press(Qt::Key_F1, Qt::ShiftModifier);  // NC program restart (M key flag)
        QVERIFY(lamp(panel, ControlKey::ProgramRestart));
        // The lamps belong to the station shown: the lathe is in automatic.
        panel.press(Qt::Key_PageDown, Qt::ControlModifier);
        QVERIFY(lamp(panel, ControlKey::Automatic));
        QVERIFY(!lamp(panel, ControlKey::Mdi));
        QVERIFY(!lamp(panel, ControlKey::ProgramRestart));
    }

    void startStopAndSingleBlockLampsAndTheHeader() {
        PanelFixture panel;
        panel.session->setTimerEnabled(false);
        panel.session->addProgram(0, 62, "lamps.nc",
                                  "N0001 G90 G1 X10 F600\nN0002 X20\nN0003 X30\nN0004 M30\n");
        QVERIFY(panel.session->selectProgram(0, 62));
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start
        QVERIFY(lamp(panel, ControlKey::Start));
        QVERIFY(!lamp(panel, ControlKey::Stop));
        QVERIFY2(header(panel, "headerProgram").contains("(running)"),
                 qPrintable(header(panel, "headerProgram")));
        panel.session->advance(0.5);

        panel.press(Qt::Key_F6, Qt::ShiftModifier);  // Stop: feed hold
        QVERIFY(lamp(panel, ControlKey::Stop));
        QVERIFY(!lamp(panel, ControlKey::Start));
        const QString held = header(panel, "headerProgram");
        QVERIFY2(held.contains("(feed hold)") && !held.contains("active"), qPrintable(held));

        panel.press(Qt::Key_F8, Qt::ShiftModifier);  // Single block on
        QVERIFY(lamp(panel, ControlKey::SingleBlock));
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start: on to the end of N0001
        QVERIFY(lamp(panel, ControlKey::Start));
        panel.session->advance(2.0);
        QVERIFY(panel.session->control(0).programHeld());
        QVERIFY(lamp(panel, ControlKey::Stop));
        QVERIFY(header(panel, "headerProgram").contains("(single block)"));
        // An ordinary state: the header prompts, no alarm is raised.
        QVERIFY(panel.session->control(0).alarm().empty());
        const QString prompt = header(panel, "headerAlarm");
        QVERIFY2(prompt.contains("press Start") && !prompt.startsWith("Alarm"), qPrintable(prompt));

        panel.press(Qt::Key_F7, Qt::ShiftModifier);  // Control reset
        QVERIFY(!lamp(panel, ControlKey::Start));
        QVERIFY(!lamp(panel, ControlKey::Stop));
        QVERIFY(lamp(panel, ControlKey::SingleBlock));  // the switch stays on
        QVERIFY(!header(panel, "headerProgram").contains("("));
        QCOMPARE(header(panel, "headerAlarm"), QString("No alarm"));
    }

    void anErrorIsAnAlarmAndTheHeaderSaysSo() {
        PanelFixture panel;
        panel.session->setTimerEnabled(false);
        panel.session->addProgram(0, 63, "bad.nc", "N0001 G1 X10 F600\nN0002 T999\n");
        QVERIFY(panel.session->selectProgram(0, 63));
        panel.press(Qt::Key_F5, Qt::ShiftModifier);
        panel.session->advance(5.0);
        QVERIFY(!panel.session->control(0).programActive());
        QVERIFY(!lamp(panel, ControlKey::Start));
        QVERIFY(header(panel, "headerAlarm").startsWith("Alarm:"));
        QVERIFY(header(panel, "headerProgram").contains("(error)"));
    }
};

QTEST_MAIN(MachineKeyLampsTest)
#include "test_machine_key_lamps.moc"
