// Signal monitor: values and step log follow the machine keys live.
#include <QTableView>

#include "PanelFixture.h"

class SignalsScreenTest : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { useTestSettings(); }

    void logShowsEachChangeNewestFirst() {
        PanelFixture panel;
        QVERIFY(panel.window->showScreen("signals"));
        auto* log = panel.window->screen(0, "signals")->findChild<QTableView*>("signalLog");
        QVERIFY(log);
        QCOMPARE(log->model()->rowCount(), 0);
        panel.press(Qt::Key_F3, Qt::ShiftModifier);  // Manual
        QCOMPARE(log->model()->rowCount(), 2);
        QCOMPARE(log->model()->index(0, 1).data().toString(), QString("P00SMANU"));
        QCOMPARE(log->model()->index(0, 2).data().toInt(), 1);
        QCOMPARE(log->model()->index(1, 1).data().toString(), QString("P00SAUTO"));
        QCOMPARE(log->model()->index(1, 2).data().toInt(), 0);
        QVERIFY(log->model()->index(0, 0).data().toInt() >
                log->model()->index(1, 0).data().toInt());
    }

    void valuesTableAndClearLog() {
        PanelFixture panel;
        QVERIFY(panel.window->showScreen("signals"));
        auto* screen = panel.window->screen(0, "signals");
        auto* values = screen->findChild<QTableView*>("signalValues");
        auto* log = screen->findChild<QTableView*>("signalLog");
        panel.press(Qt::Key_F1, Qt::ShiftModifier);  // NC program restart M key
        // The M key brings up the restart screen (seed 000, 2.2); back to the monitor.
        QCOMPARE(panel.window->currentScreenName(), QString("restart"));
        QVERIFY(panel.window->showScreen("signals"));
        bool found = false;
        for (int row = 0; row < values->model()->rowCount(); ++row)
            if (values->model()->index(row, 0).data().toString() == "mBPREP")
                found = values->model()->index(row, 1).data().toInt() == 1;
        QVERIFY(found);
        QVERIFY(log->model()->rowCount() > 0);
        panel.press(Qt::Key_F1);  // soft key: clear log
        QCOMPARE(log->model()->rowCount(), 0);
        QVERIFY(values->model()->rowCount() > 0);
    }
};

QTEST_MAIN(SignalsScreenTest)
#include "test_signals_screen.moc"
