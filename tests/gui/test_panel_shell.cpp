// The panel shell driven by keys: soft keys, stations, machine keys, settings.
#include <QFile>
#include <QLabel>
#include <QPushButton>
#include <QScreen>
#include <QSettings>
#include <QStackedWidget>
#include <QTemporaryDir>

#include "PanelFixture.h"
#include "cnc_core/machine/SimulatedMachine.h"
#include "hmi/SoftKeyBar.h"

using mtc::core::ControlKey;

class PanelShellTest : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() {
        useTestSettings();
        QSettings().clear();
    }

    void startsOnTheMainMenuOfStationZero() {
        PanelFixture panel;
        QCOMPARE(panel.window->currentStation(), 0);
        QCOMPARE(panel.window->currentScreenName(), QString("menu"));
        auto* station = panel.window->findChild<QLabel*>("headerStation");
        QVERIFY(station);
        QCOMPARE(station->text(), QString("Station 0: Mill"));
        QCOMPARE(panel.window->findChild<QLabel*>("headerMode")->text(),
                 QString("Mode: automatic"));
    }

    void softKeysFollowTheScreenAndWorkByKeyboardAndMouse() {
        PanelFixture panel;
        auto* bar = panel.window->softKeyBar();
        QCOMPARE(bar->label(0), QString("Program directory"));
        panel.press(Qt::Key_F1);  // keyboard
        QCOMPARE(panel.window->currentScreenName(), QString("programs"));
        QCOMPARE(bar->label(7), QString("Back"));
        QCOMPARE(panel.window->findChild<QLabel*>("headerScreen")->text(),
                 QString("Program directory"));
        auto* f8 = panel.window->findChild<QPushButton*>("softkey8");
        QVERIFY(f8 && f8->isEnabled());
        QTest::mouseClick(f8, Qt::LeftButton);  // mouse
        QCOMPARE(panel.window->currentScreenName(), QString("menu"));
        panel.press(Qt::Key_F12);
        QCOMPARE(panel.window->currentScreenName(), QString("help"));
        panel.press(Qt::Key_Escape);
        QCOMPARE(panel.window->currentScreenName(), QString("menu"));
    }

    void blankSoftKeysDoNothing() {
        PanelFixture panel;
        panel.press(Qt::Key_F1);
        QCOMPARE(panel.window->currentScreenName(), QString("programs"));
        panel.press(Qt::Key_F5);  // NC options: F5-F7 are blank there
        QCOMPARE(panel.window->currentScreenName(), QString("nc-options"));
        QVERIFY(!panel.window->findChild<QPushButton*>("softkey5")->isEnabled());
        panel.press(Qt::Key_F5);
        QCOMPARE(panel.window->currentScreenName(), QString("nc-options"));
    }

    void stationsSwitchWithCtrlPageKeysAndKeepTheirScreen() {
        PanelFixture panel;
        panel.press(Qt::Key_F2);  // station 0: second menu entry
        const QString screenOfStation0 = panel.window->currentScreenName();
        QVERIFY(screenOfStation0 != "menu");
        panel.press(Qt::Key_PageDown, Qt::ControlModifier);
        QCOMPARE(panel.window->currentStation(), 1);
        QCOMPARE(panel.window->currentScreenName(), QString("menu"));
        QCOMPARE(panel.window->findChild<QLabel*>("headerStation")->text(),
                 QString("Station 1: Lathe"));
        panel.press(Qt::Key_F12);
        QCOMPARE(panel.window->currentScreenName(), QString("help"));
        panel.press(Qt::Key_PageDown, Qt::ControlModifier);  // wraps to station 0
        QCOMPARE(panel.window->currentStation(), 0);
        QCOMPARE(panel.window->currentScreenName(), screenOfStation0);
        panel.press(Qt::Key_PageUp, Qt::ControlModifier);
        QCOMPARE(panel.window->currentStation(), 1);
        QCOMPARE(panel.window->currentScreenName(), QString("help"));
        QVERIFY(panel.window->screen(0, "help") != panel.window->screen(1, "help"));
    }

    void machineKeysGoToTheCoreOfTheCurrentStation() {
        PanelFixture panel;
        auto& mill = panel.session->control(0);
        auto& lathe = panel.session->control(1);
        panel.press(Qt::Key_F3, Qt::ShiftModifier);  // Manual
        QCOMPARE(mill.mode(), mtc::core::OperatingMode::Manual);
        QCOMPARE(mill.signalTable().get("P00SMANU"), 1);
        QCOMPARE(mill.signalTable().get("P00SAUTO"), 0);
        QCOMPARE(lathe.mode(), mtc::core::OperatingMode::Automatic);
        QCOMPARE(panel.window->findChild<QLabel*>("headerMode")->text(), QString("Mode: manual"));
        // Start in manual mode is refused with an alarm in the header.
        panel.press(Qt::Key_F5, Qt::ShiftModifier);
        QVERIFY(!mill.alarm().empty());
        QVERIFY(panel.window->findChild<QLabel*>("headerAlarm")->text().startsWith("Alarm:"));
        // Control reset (mouse on the M key bar) clears it.
        auto* reset = panel.window->findChild<QPushButton*>("mkey-7");
        QCOMPARE(reset->text().simplified(), QString("Control reset"));  // 1 or 2 lines
        QTest::mouseClick(reset, Qt::LeftButton);
        QVERIFY(mill.alarm().empty());
        QCOMPARE(panel.window->findChild<QLabel*>("headerAlarm")->text(), QString("No alarm"));
        panel.press(Qt::Key_F4, Qt::ShiftModifier);  // Automatic
        QCOMPARE(mill.mode(), mtc::core::OperatingMode::Automatic);
        // NC program restart key toggles the M key flag the restart logic reads.
        panel.press(Qt::Key_F1, Qt::ShiftModifier);
        QCOMPARE(mill.signalTable().get("mBPREP"), 1);
        QCOMPARE(lathe.signalTable().get("mBPREP"), 0);
        // The log keeps the order of the changes.
        const auto& log = mill.signalTable().log();
        QVERIFY(log.size() >= 5);
        QCOMPARE(QString::fromStdString(log.front().name), QString("P00SAUTO"));
        QCOMPARE(QString::fromStdString(log.back().name), QString("mBPREP"));
    }

    void startRunsTheProgramInSimulatedTimeUntilItsEnd() {
        QTemporaryDir dir;
        const QString path = dir.filePath("drill.nc");
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(
            "N0001 G0 G90 X10 Y10 Z5\nN0002 G1 Z-1 F600\nN0003 X50\n"
            "N0004 M00\nN0005 X10\nN0006 M30\n");
        file.close();
        mtc::hmi::PanelOptions options;
        options.program = path;
        PanelFixture panel;
        QString error;
        QVERIFY2(mtc::hmi::applyStartOptions(options, *panel.session, *panel.window, error),
                 qPrintable(error));
        auto& mill = panel.session->control(0);
        QVERIFY(mill.selectedProgram() != 0);
        panel.session->setSpeed(1000);
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start
        QVERIFY(mill.programActive());
        QCOMPARE(mill.signalTable().get("P00SACTIV"), 1);
        QTRY_VERIFY(mill.programHeld());  // M00 programmed stop
        QCOMPARE(QString::fromStdString(mill.currentBlock()), QString("N0004"));
        QCOMPARE(mill.signalTable().get("P00SHOLD"), 1);
        QVERIFY(panel.window->findChild<QLabel*>("headerProgram")->text().contains("N0004"));
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start continues
        QTRY_VERIFY(!mill.programActive());
        QVERIFY2(mill.alarm().empty(), mill.alarm().c_str());
        QCOMPARE(mill.signalTable().get("P00SACTIV"), 0);
        QCOMPARE(mill.signalTable().get("P00SHOLD"), 0);
        // 5 + 6 + 40 + 40 mm: the simulated machine took its time for each move.
        QVERIFY(panel.session->machine(0).seconds() > 8.0);
    }

    void stopHoldsAndControlResetAbandonsTheRun() {
        PanelFixture panel;
        auto& mill = panel.session->control(0);
        panel.session->addProgram(0, 50, "slow.nc", "N0001 G1 G90 X300 F10\nN0002 M30\n");
        QVERIFY(panel.session->selectProgram(0, 50));
        panel.press(Qt::Key_F5, Qt::ShiftModifier);
        QVERIFY(mill.programActive());
        QVERIFY(panel.session->station(0).running());
        panel.press(Qt::Key_F6, Qt::ShiftModifier);  // Stop: feed hold
        QVERIFY(mill.programActive());
        QVERIFY(mill.programHeld());
        QVERIFY(!panel.session->station(0).running());
        panel.press(Qt::Key_F3, Qt::ShiftModifier);  // Manual refused while active
        QCOMPARE(mill.mode(), mtc::core::OperatingMode::Automatic);
        QVERIFY(!mill.alarm().empty());
        panel.press(Qt::Key_F7, Qt::ShiftModifier);  // Control reset
        QVERIFY(!mill.programActive());
        QVERIFY(!mill.programHeld());
        QVERIFY(mill.alarm().empty());
        QVERIFY(!panel.session->station(0).running());
    }

    void aProgramErrorEndsTheRunWithAnAlarm() {
        PanelFixture panel;
        auto& mill = panel.session->control(0);
        panel.session->addProgram(0, 51, "bad.nc", "N0001 G1 X10 F100\nN0002 T999\nN0003 M30\n");
        QVERIFY(panel.session->selectProgram(0, 51));
        panel.session->setSpeed(1000);
        panel.press(Qt::Key_F5, Qt::ShiftModifier);
        QTRY_VERIFY(!mill.programActive());
        QVERIFY(!mill.alarm().empty());
        QVERIFY2(QString::fromStdString(mill.alarm()).contains("N0002"), mill.alarm().c_str());
    }

    void withoutSavedGeometryTheWindowShrinksToItsScreen() {
        QSettings().remove("window/geometry");
        PanelFixture panel;
        const QSize room = panel.window->QWidget::screen()->availableGeometry().size();
        const QSize needed = panel.window->minimumSizeHint();
        const QSize opened = panel.window->size();
        // The offscreen screen (800 x 600) is smaller than the default size,
        // as a 1280 x 1024 screen is at 144 dpi (scale 1.5).
        if (room.width() >= opened.width() && room.height() >= opened.height())
            QSKIP("the default window size already fits this screen");
        panel.window->restoreSettings();
        // As small as the screen's free area, but never below what the
        // contents need (then, as offscreen, the screen is too small anyway).
        QCOMPARE(panel.window->size(), room.expandedTo(needed).boundedTo(opened));
        QVERIFY(panel.window->width() < opened.width() || panel.window->height() < opened.height());
    }

    void settingsKeepScreensStationAndGeometry() {
        {
            PanelFixture panel;
            panel.window->resize(900, 650);
            panel.press(Qt::Key_F1);
            panel.press(Qt::Key_PageDown, Qt::ControlModifier);
            panel.press(Qt::Key_F12);
            panel.window->close();  // closing saves
        }
        PanelFixture again;
        again.window->restoreSettings();
        QCOMPARE(again.window->currentStation(), 1);
        QCOMPARE(again.window->currentScreenName(), QString("help"));
        QCOMPARE(again.window->size(), QSize(900, 650));
        again.press(Qt::Key_PageUp, Qt::ControlModifier);
        QCOMPARE(again.window->currentScreenName(), QString("programs"));
    }
};

QTEST_MAIN(PanelShellTest)
#include "test_panel_shell.moc"
