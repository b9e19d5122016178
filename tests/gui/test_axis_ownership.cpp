// GAX / FAX between the two stations of the panel (docs/decisions/restart.md
// the lathe's GAX waits while the mill holds the axis, its message
// line says so (in the panel's language), the mill keeps running; the mill's
// FAX lets the lathe go on; Control reset withdraws a waiting GAX. Machine
// keys as the operator presses them.
#include <QLabel>
#include <QtTest>

#include "PanelFixture.h"
#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/machine/SimulatedMachine.h"

class AxisOwnershipTest : public QObject {
    Q_OBJECT
  private:
    /// The mill (station 0) starts a program that takes X and moves it for
    /// 200 simulated seconds before it frees it.
    static void startMillHoldingX(PanelFixture& panel) {
        std::string program = "N0001 GAX(X)\n";
        for (int i = 0; i < 200; ++i)  // 1 s of simulated time each
            program += i % 2 ? "G1 G90 X0 F600\n" : "G1 G90 X10 F600\n";
        program += "FAX(X)\nM30\n";
        panel.session->addProgram(0, 50, "hold-x.nc", program);
        QVERIFY(panel.session->selectProgram(0, 50));
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start on the mill
        QTRY_COMPARE(panel.session->axisTransfer().holder("X"), 0);
    }
    /// The lathe (station 1) starts a program whose first block is GAX(X).
    static void startLatheWantingX(PanelFixture& panel) {
        panel.session->addProgram(1, 50, "want-x.nc", "N0001 GAX(X)\nN0002 G0 X20\nN0003 M30\n");
        QVERIFY(panel.session->selectProgram(1, 50));
        panel.session->setSpeed(100);                        // the mill's 200 s take 2 s
        panel.press(Qt::Key_PageDown, Qt::ControlModifier);  // to the lathe
        panel.press(Qt::Key_F5, Qt::ShiftModifier);          // Start on the lathe
    }

  private slots:
    void initTestCase() { useTestSettings(); }

    // The wait in the panel's language (docs/DECISIONS.md D-026).
    void gaxWaitsUntilTheOtherStationFreesTheAxis_data() {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QString>("alarm");
        QTest::newRow("en") << "en"
                            << "Waiting for axis X (GAX: another process holds it)";
        QTest::newRow("de") << "de"
                            << "Warten auf Achse X (GAX: ein anderer Prozess belegt sie)";
    }

    void gaxWaitsUntilTheOtherStationFreesTheAxis() {
        QFETCH(QString, language);
        QFETCH(QString, alarm);
        mtc::hmi::PanelOptions options;
        options.language = language;
        PanelFixture panel(options);
        startMillHoldingX(panel);
        startLatheWantingX(panel);
        auto& lathe = panel.session->control(1);
        QTRY_COMPARE(QString::fromStdString(panel.session->station(1).waitingAxis()), QString("X"));
        QVERIFY(lathe.programActive());
        QVERIFY(!lathe.programHeld());
        QCOMPARE(lathe.signalTable().get("P01SHOLD"), 0);
        QCOMPARE(QString::fromStdString(lathe.alarm()), alarm);
        const QString header = panel.window->findChild<QLabel*>("headerAlarm")->text();
        QVERIFY2(header.endsWith(alarm), qPrintable(header));
        // The mill goes on meanwhile; the lathe's simulated time stands still.
        const double millBefore = panel.session->machine(0).seconds();
        const double latheBefore = panel.session->machine(1).seconds();
        QTRY_VERIFY(panel.session->machine(0).seconds() > millBefore + 1.5);
        QCOMPARE(panel.session->machine(1).seconds(), latheBefore);
        // The mill finishes its move at once and frees X: the lathe goes on.
        panel.session->setSpeed(100000);
        QTRY_VERIFY(!panel.session->control(0).programActive());
        QTRY_VERIFY(!lathe.programActive());
        QVERIFY2(lathe.alarm().empty(), lathe.alarm().c_str());
        QCOMPARE(panel.session->axisTransfer().holder("X"), 1);
        QCOMPARE(panel.session->interpreter(1).programmedPosition(0), 20.0);
    }

    void controlResetWithdrawsTheWaitingGax() {
        PanelFixture panel;
        startMillHoldingX(panel);
        startLatheWantingX(panel);
        QTRY_COMPARE(QString::fromStdString(panel.session->station(1).waitingAxis()), QString("X"));
        QCOMPARE(panel.session->axisTransfer().open().size(), std::size_t{1});
        panel.press(Qt::Key_F7, Qt::ShiftModifier);  // Control reset on the lathe
        QVERIFY(!panel.session->control(1).programActive());
        QVERIFY(panel.session->axisTransfer().open().empty());
        QCOMPARE(QString::fromStdString(panel.session->station(1).waitingAxis()), QString());
        QVERIFY2(panel.session->control(0).programActive(), "the mill is not affected");
    }
};

QTEST_MAIN(AxisOwnershipTest)
#include "test_axis_ownership.moc"
