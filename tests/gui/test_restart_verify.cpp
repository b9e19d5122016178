// The restart verifier on the panel (issue 15 §3, restart.md R-028), by
// keys: F7 on the restart screen verifies every arrival of the program, the
// result review shows the verification of the chosen target before Start —
// the same differences `mtc200-cli verify-restart` lists.
#include <QLabel>
#include <QTableView>

#include "PanelFixture.h"
#include "screens/restart/RestartController.h"
#include "screens/restart/RestartResultModel.h"
#include "screens/restart/RestartRun.h"
#include "screens/restart/RestartScreen.h"

namespace {

mtc::screens::RestartScreen* restartScreen(PanelFixture& panel, int slot) {
    return static_cast<mtc::screens::RestartScreen*>(panel.window->screen(slot, "restart"));
}

QString message(PanelFixture& panel) {
    return restartScreen(panel, 0)->findChild<QLabel*>("restartMessage")->text();
}

/// {at the target, other column, differs} of the row called `item`.
QStringList tableRow(QAbstractItemModel* model, const QString& item) {
    for (int row = 0; row < model->rowCount(); ++row)
        if (model->index(row, 0).data().toString() == item)
            return {
                model->index(row, 1).data().toString(), model->index(row, 2).data().toString(),
                model->index(row, 0).data(mtc::screens::RestartResultModel::DiffersRole).toBool()
                    ? "differs"
                    : "same"};
    return {};
}

void openRestart(PanelFixture& panel, int program) {
    panel.session->selectProgram(0, program);
    panel.press(Qt::Key_F1, Qt::ShiftModifier);
}

/// A library whose ADJUST leaves G0 active (the tool change's G53 G0).
const char* kBadLibrary =
    "N0000 M30\n"
    "N0001 .ADJUST @150=M(2) @151=G(4)\n"
    "N0002 G53 G0 Z90\n"
    "N0003 G=@151 Q9500\n"
    "N0004 .REPOS G77 S0 M=@150\n"
    "N0005 G77 X0 Y0 F2000\n"
    "N0006 G77 Z0 F1000 RTS\n";

const char* kPocket =
    "N0000 G0 G54 X10 Y10 Z5 S2000 M3\n"
    "N0001 G1 Z-2 F300\n"
    "N0002 X50\n"
    "N0003 Y40\n"
    "N0004 G0 Z5\n"
    "N0005 M30\n";

}  // namespace

class RestartVerifyTest : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { useTestSettings(); }

    void f7VerifiesEveryArrivalOfTheDemoProgram() {
        PanelFixture panel;
        openRestart(panel, 1);
        panel.press(Qt::Key_F7);
        QTRY_VERIFY_WITH_TIMEOUT(message(panel).contains("targets re-established"), 60000);
        QVERIFY2(message(panel).contains("Verification of P1: 108 of 108 targets re-established"),
                 qPrintable(message(panel)));
        QCOMPARE(restartScreen(panel, 0)->controller()->message().level,
                 mtc::screens::RestartMessage::Level::Info);
        // The station itself was not touched.
        QCOMPARE(panel.session->control(0).signalTable().get("P00SBPACT"), 0);
        QVERIFY(!restartScreen(panel, 0)->controller()->run()->started());
    }

    void f7NamesTheTargetsAWrongAdjustLeaves() {
        PanelFixture panel;
        panel.session->addProgram(0, 99, "N1010099.DAT", kBadLibrary);
        panel.session->addProgram(0, 30, "pocket.nc", kPocket);
        openRestart(panel, 30);
        panel.press(Qt::Key_F7);
        QTRY_VERIFY_WITH_TIMEOUT(message(panel).contains("targets re-established"), 60000);
        QVERIFY2(message(panel).contains(
                     "3 of 6 targets re-established; 3 leave G0 active: N0002, N0003, N0004"),
                 qPrintable(message(panel)));
        QCOMPARE(restartScreen(panel, 0)->controller()->message().level,
                 mtc::screens::RestartMessage::Level::Warning);
    }

    void resultReviewShowsTheDifferencesOfTheTargetBeforeStart() {
        PanelFixture panel;
        panel.session->addProgram(0, 99, "N1010099.DAT", kBadLibrary);
        panel.session->addProgram(0, 30, "pocket.nc", kPocket);
        openRestart(panel, 30);
        for (int i = 0; i < 3; ++i)
            panel.press(Qt::Key_Down);  // N0003 Y40
        panel.press(Qt::Key_Return);
        auto* run = restartScreen(panel, 0)->controller()->run();
        QTRY_COMPARE(run->phase(), mtc::core::RestartPhase::TargetReached);
        QCOMPARE(panel.window->currentScreenName(), QString("restart-result"));
        auto* table = panel.window->screen(0, "restart-result")->findChild<QTableView*>();
        QCOMPARE(tableRow(table->model(), "After ADJUST / REPOS: G group 1 (interpolation)"),
                 (QStringList{"1", "0", "differs"}));
        auto* summary =
            panel.window->screen(0, "restart-result")->findChild<QLabel*>("resultSummary");
        QVERIFY2(summary->text().contains("verification: 1 differences"),
                 qPrintable(summary->text()));
        QCOMPARE(run->phase(), mtc::core::RestartPhase::TargetReached);  // nothing started
        // F4 verifies again on demand; the good demo library re-establishes it.
        panel.session->addProgram(
            0, 99, "N1010099.DAT",
            "N0000 M30\nN0001 .ADJUST @150=M(2) @152=G(1)\nN0002 Q9500\n"
            "N0003 .REPOS G77 S0 M=@150\nN0004 G=@152\nN0005 G77 X0 Y0 F2000\n"
            "N0006 G77 Z0 F1000 RTS\n");
        panel.press(Qt::Key_F4);
        QCOMPARE(tableRow(table->model(), "Every item"),
                 (QStringList{"re-established", "re-established", "same"}));
    }
};

QTEST_MAIN(RestartVerifyTest)
#include "test_restart_verify.moc"
