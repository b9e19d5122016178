// Machine control keys around NC program restart, by real keys: the REPOS M
// key (Shift+F2) opens the repositioning screen of the current station while
// its restart is between the target block and the re-entry (seed 000, 6.3
// step 5, Fig. 7-14 rung 6) and is refused otherwise; single-block mode
// (Shift+F8) holds the computing process after every block (seed 000, 2.7);
// a FAX in one station's computing process waits for the other station's GAX
// (seed 000, 5.4).
#include <QLabel>

#include "PanelFixture.h"
#include "screens/restart/RestartController.h"
#include "screens/restart/RestartRun.h"
#include "screens/restart/RestartScreen.h"

using mtc::core::RestartPhase;

namespace {

/// Program 99 of station `slot` with ADJUST (manual mode) and REPOS.
const char* kLibrary =
    "N0000 M30\n"
    "N0001 .ADJUST @150=1\n"
    "N0002 Q9500 ;manual mode\n"
    "N0003 .REPOS G77 X0 Y0 Z0 RTS\n";

/// Five counting blocks and the target N0006.
const char* kCounting =
    "N0001 G0 G54 X10 Y10 Z5\n"
    "N0002 @1=1\n"
    "N0003 @1=@1+1\n"
    "N0004 @1=@1+1\n"
    "N0005 @1=@1+1\n"
    "N0006 G1 X20 F300 ;target\n"
    "N0007 M30\n";

mtc::screens::RestartScreen* restartScreen(PanelFixture& panel, int slot) {
    return static_cast<mtc::screens::RestartScreen*>(panel.window->screen(slot, "restart"));
}

mtc::screens::RestartRun* runOf(PanelFixture& panel, int slot) {
    return restartScreen(panel, slot)->controller()->run();
}

/// Opens the restart screen on program 40 (`text`, default kCounting) of
/// the current station with Shift+F1 and puts the cursor on N0006 (five Down
/// keys from the first block, N0001).
void selectTarget(PanelFixture& panel, int slot, const char* text = kCounting) {
    panel.session->addProgram(slot, 99, "library.nc", kLibrary);
    panel.session->addProgram(slot, 40, "counting.nc", text);
    panel.session->selectProgram(slot, 40);
    panel.press(Qt::Key_F1, Qt::ShiftModifier);
    QCOMPARE(panel.window->currentScreenName(), QString("restart"));
    for (int i = 0; i < 5; ++i)
        panel.press(Qt::Key_Down);
    QVERIFY(restartScreen(panel, slot)->controller()->status().startsWith("Target P40 N0006"));
}

QString alarm(PanelFixture& panel, int slot) {
    return QString::fromStdString(panel.session->control(slot).alarm());
}

}  // namespace

class RestartKeysTest : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { useTestSettings(); }

    void reposKeyIsRefusedWithoutARestart() {
        PanelFixture panel;
        panel.press(Qt::Key_F2, Qt::ShiftModifier);
        QCOMPARE(panel.window->currentScreenName(), QString("menu"));
        QVERIFY(alarm(panel, 0).startsWith("REPOS refused"));
        QCOMPARE(panel.session->control(0).signalTable().get("P00CREPOS"), 0);
    }

    void reposKeyOpensTheRepositioningScreenOfTheCurrentStation() {
        PanelFixture panel;
        panel.press(Qt::Key_PageDown, Qt::ControlModifier);  // the lathe
        selectTarget(panel, 1);
        panel.press(Qt::Key_Return);
        auto* run = runOf(panel, 1);
        QTRY_COMPARE(run->phase(), RestartPhase::TargetReached);
        QCOMPARE(panel.window->currentScreenName(), QString("restart-result"));
        panel.press(Qt::Key_F2, Qt::ShiftModifier);  // REPOS
        QCOMPARE(panel.window->currentScreenName(), QString("repos"));
        QCOMPARE(panel.window->currentStation(), 1);
        QCOMPARE(panel.session->control(1).signalTable().get("P01CREPOS"), 1);
        QCOMPARE(panel.session->control(1).signalTable().get("mREPOS"), 0);
        // The mill has no restart: its REPOS key is refused, its screen stays.
        panel.press(Qt::Key_PageUp, Qt::ControlModifier);
        panel.press(Qt::Key_F2, Qt::ShiftModifier);
        QCOMPARE(panel.window->currentScreenName(), QString("menu"));
        QCOMPARE(panel.session->control(0).signalTable().get("P00CREPOS"), 0);
        // Back on the lathe: Start runs ADJUST into manual mode; REPOS again
        // from the menu brings the repositioning screen back.
        panel.press(Qt::Key_PageDown, Qt::ControlModifier);
        panel.press(Qt::Key_F5, Qt::ShiftModifier);
        QTRY_COMPARE(run->phase(), RestartPhase::ManualMode);
        panel.press(Qt::Key_Escape);
        QCOMPARE(panel.window->currentScreenName(), QString("menu"));
        panel.press(Qt::Key_F2, Qt::ShiftModifier);
        QCOMPARE(panel.window->currentScreenName(), QString("repos"));
        panel.press(Qt::Key_F4, Qt::ShiftModifier);  // Automatic
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start: REPOS
        QTRY_COMPARE(run->phase(), RestartPhase::Reestablished);
        panel.press(Qt::Key_Escape);
        panel.press(Qt::Key_F2, Qt::ShiftModifier);  // re-established: nothing to do
        QCOMPARE(panel.window->currentScreenName(), QString("menu"));
        QVERIFY(alarm(panel, 1).startsWith("REPOS refused"));
    }

    void reposKeyIsRefusedDuringTheComputingProcess() {
        PanelFixture panel;
        selectTarget(panel, 0);
        panel.press(Qt::Key_F8, Qt::ShiftModifier);  // single block: it stops after a block
        panel.press(Qt::Key_Return);
        auto* run = runOf(panel, 0);
        QTRY_VERIFY(run->held());
        QCOMPARE(run->phase(), RestartPhase::Computing);
        panel.press(Qt::Key_F2, Qt::ShiftModifier);
        QCOMPARE(panel.window->currentScreenName(), QString("restart"));
        QVERIFY(alarm(panel, 0).contains("not possible yet"));
        QCOMPARE(panel.session->control(0).signalTable().get("P00CREPOS"), 0);
    }

    void singleBlockStepsTheComputingProcessWithStart() {
        PanelFixture panel;
        selectTarget(panel, 0);
        panel.press(Qt::Key_F8, Qt::ShiftModifier);  // single block on
        QVERIFY(panel.session->control(0).singleBlock());
        panel.press(Qt::Key_Return);
        auto* run = runOf(panel, 0);
        auto* progress = restartScreen(panel, 0)->findChild<QLabel*>("restartProgress");
        for (std::uint64_t block = 1; block <= 5; ++block) {
            QTRY_VERIFY(run->held());
            QCOMPARE(run->computedBlocks(), block);
            QCOMPARE(panel.session->control(0).signalTable().get("P00SHOLD"), 1);
            QTRY_VERIFY2(progress->text().contains("Single block: held"),
                         qPrintable(progress->text()));
            panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start: the next block
        }
        QTRY_COMPARE(run->phase(), RestartPhase::TargetReached);
        QCOMPARE(run->computedBlocks(), std::uint64_t(5));
        QCOMPARE(run->sequence().computing().state().variables.values[1], 4.0);
    }

    void singleBlockSwitchedOffRunsOn() {
        PanelFixture panel;
        selectTarget(panel, 0);
        panel.press(Qt::Key_F8, Qt::ShiftModifier);
        panel.press(Qt::Key_Return);
        auto* run = runOf(panel, 0);
        QTRY_VERIFY(run->held());
        QCOMPARE(run->computedBlocks(), std::uint64_t(1));
        panel.press(Qt::Key_F8, Qt::ShiftModifier);  // off again
        QVERIFY(!panel.session->control(0).singleBlock());
        QVERIFY(run->held());
        panel.press(Qt::Key_F5, Qt::ShiftModifier);
        QTRY_COMPARE(run->phase(), RestartPhase::TargetReached);
        QCOMPARE(run->computedBlocks(), std::uint64_t(5));
    }

    void faxWaitsForTheOtherStationsGax() {
        PanelFixture panel;
        selectTarget(panel, 0,
                     "N0001 G0 G54 X10 Y10 Z5\nN0002 @1=1\nN0003 @1=2 FAX(X1)\nN0004 @1=3\n"
                     "N0005 @1=4\nN0006 G1 X20 F300\nN0007 M30\n");
        panel.press(Qt::Key_Return);
        auto* mill = runOf(panel, 0);
        auto* progress = restartScreen(panel, 0)->findChild<QLabel*>("restartProgress");
        QTRY_VERIFY2(progress->text().contains("Waiting for another process: FAX X1"),
                     qPrintable(progress->text()));
        QCOMPARE(mill->phase(), RestartPhase::Computing);
        QCOMPARE(mill->computedBlocks(), std::uint64_t(3));
        panel.press(Qt::Key_PageDown, Qt::ControlModifier);  // the lathe requests X1
        selectTarget(panel, 1,
                     "N0001 G0 X10 Z5\nN0002 @1=1\nN0003 GAX(X1)\nN0004 @1=2\nN0005 @1=3\n"
                     "N0006 G1 Z20 F300\nN0007 M30\n");
        panel.press(Qt::Key_Return);
        QTRY_COMPARE(runOf(panel, 1)->phase(), RestartPhase::TargetReached);
        QTRY_COMPARE(mill->phase(), RestartPhase::TargetReached);
        QCOMPARE(mill->computedBlocks(), std::uint64_t(5));
        QVERIFY(panel.session->axisTransfer().open().empty());
    }
};

QTEST_MAIN(RestartKeysTest)
#include "test_restart_keys.moc"
