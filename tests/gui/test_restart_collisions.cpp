// The restart's way back against the part on the result review (issue 19
// §4, D-021), by keys: Shift+F1, the cursor on the target, Enter; when the
// computing process reaches the target the review lists in red every ADJUST /
// REPOS move that would cut the part (block, phase, position) before Start,
// and says so when the way back is clear.
#include <QLabel>
#include <QTableView>

#include "PanelFixture.h"
#include "screens/restart/RestartController.h"
#include "screens/restart/RestartResultModel.h"
#include "screens/restart/RestartRun.h"
#include "screens/restart/RestartScreen.h"
#include "tests/support/SlotRestartProgram.h"

namespace {

using mtc::screens::RestartResultModel;

// The slot of tests/support/SlotRestartProgram.h (mill, T2, target N0050).
const char* kSlot = mtc::test::kSlotRestartProgram;

// ADJUST leaves the tool beside the part below its top; REPOS goes straight.
const char* kStraightBack =
    "N0000 M30\n"
    "N0001 .ADJUST G0 G54 X120 Y30 Z-2\n"
    "N0002 .REPOS G77 X0 Y0 F2000\n"
    "N0003 G77 Z0 F500 RTS\n";

// The same with the tool above the part first.
const char* kOverTheTop =
    "N0000 M30\n"
    "N0001 .ADJUST G0 G54 Z20\n"
    "N0002 .REPOS G77 X0 Y0 F2000\n"
    "N0003 G77 Z0 F500 RTS\n";

/// Selects program 40, opens the restart screen (Shift+F1), moves the
/// cursor to N0050 and accepts it with Enter, as an operator does.
void restartAtTheTarget(PanelFixture& panel) {
    panel.session->selectProgram(0, 40);
    panel.press(Qt::Key_F1, Qt::ShiftModifier);
    for (int i = 0; i < 4; ++i)
        panel.press(Qt::Key_Down);  // N0010 .. N0050
    panel.press(Qt::Key_Return);
}

mtc::screens::RestartRun* run(PanelFixture& panel) {
    return static_cast<mtc::screens::RestartScreen*>(panel.window->screen(0, "restart"))
        ->controller()
        ->run();
}

/// The rows the review marks as collisions: {item, what}.
QList<QStringList> collisionRows(QAbstractItemModel* model) {
    QList<QStringList> rows;
    for (int row = 0; row < model->rowCount(); ++row)
        if (model->index(row, 0).data(RestartResultModel::CollisionRole).toBool())
            rows << QStringList{model->index(row, 0).data().toString(),
                                model->index(row, 1).data().toString()};
    return rows;
}

}  // namespace

class RestartCollisionsTest : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { useTestSettings(); }

    void aWayBackThroughThePartIsListedInRedBeforeStart() {
        PanelFixture panel;
        panel.session->addProgram(0, 99, "N1010099.DAT", kStraightBack);
        panel.session->addProgram(0, 40, "slot.nc", kSlot);
        restartAtTheTarget(panel);
        QTRY_COMPARE(run(panel)->phase(), mtc::core::RestartPhase::TargetReached);
        QCOMPARE(panel.window->currentScreenName(), QString("restart-result"));
        QWidget* review = panel.window->screen(0, "restart-result");
        auto* table = review->findChild<QTableView*>("resultTable");
        const QList<QStringList> rows = collisionRows(table->model());
        QCOMPARE(rows.size(), 1);
        QVERIFY2(rows[0][0].startsWith("REPOS P99 N0002 (line 3): feed move cuts the part"),
                 qPrintable(rows[0][0]));
        // It enters the part's X100 face with the cutter's centre at X104.9.
        QVERIFY2(rows[0][1].startsWith("X-45.1"), qPrintable(rows[0][1]));
        QVERIFY2(rows[0][1].endsWith("Y-50.000 Z-122.000 (machine)"), qPrintable(rows[0][1]));
        // Red, listed first (before the G functions), not counted as a difference.
        const QModelIndex first = table->model()->index(1, 0);
        QVERIFY(first.data(RestartResultModel::CollisionRole).toBool());
        QCOMPARE(first.data(Qt::ForegroundRole).value<QBrush>().color(), QColor(0xb0, 0x00, 0x00));
        QVERIFY(!first.data(RestartResultModel::DiffersRole).toBool());
        auto* banner = review->findChild<QLabel*>("resultCollisions");
        QVERIFY(banner->isVisible());
        QVERIFY2(banner->text().startsWith("ADJUST/REPOS moves that collide with the part: 1 of 3"),
                 qPrintable(banner->text()));
        QVERIFY(banner->styleSheet().contains("#c00000"));
        // Differences only (F3) keeps the collision in view.
        panel.press(Qt::Key_F3);
        QCOMPARE(collisionRows(table->model()).size(), 1);
        // Nothing was started: the machine has not moved.
        QCOMPARE(run(panel)->phase(), mtc::core::RestartPhase::TargetReached);
        QCOMPARE(run(panel)->actualPosition(2), 0.0);
    }

    void aWayBackOverTheTopIsClearAndF4ChecksAgain() {
        PanelFixture panel;
        panel.session->addProgram(0, 99, "N1010099.DAT", kOverTheTop);
        panel.session->addProgram(0, 40, "slot.nc", kSlot);
        restartAtTheTarget(panel);
        QTRY_COMPARE(run(panel)->phase(), mtc::core::RestartPhase::TargetReached);
        QWidget* review = panel.window->screen(0, "restart-result");
        auto* table = review->findChild<QTableView*>("resultTable");
        QVERIFY(collisionRows(table->model()).isEmpty());
        auto* banner = review->findChild<QLabel*>("resultCollisions");
        QVERIFY2(banner->text() == "Way back clear: ADJUST/REPOS moves checked against the part: 3",
                 qPrintable(banner->text()));
        QVERIFY(!banner->styleSheet().contains("#c00000"));
        // The library changes (the commissioning engineer edits REPOS): F4
        // verifies the target again and checks the new way back.
        panel.session->addProgram(0, 99, "N1010099.DAT", kStraightBack);
        panel.press(Qt::Key_F4);
        QCOMPARE(collisionRows(table->model()).size(), 1);
        QVERIFY(banner->styleSheet().contains("#c00000"));
    }
};

QTEST_MAIN(RestartCollisionsTest)
#include "test_restart_collisions.moc"
