// The machine runs in time, driven by the real M keys: Start, the position
// changes as time passes, Stop holds, Start resumes; two stations at once;
// the Speed key and its header text. Time is stepped by the test through
// CellSession::advance (the call the panel's timer makes), so nothing here
// depends on the wall clock, except one case that lets the real timer run.
#include <QLabel>
#include <QPushButton>
#include <QtTest>

#include "PanelFixture.h"
#include "cnc_core/cell/Station.h"

namespace {

// 10 mm at F600 = 1 s per move.
const char* kSteps =
    "N0001 G1 G90 X10 F600\nN0002 X20\nN0003 X30\nN0004 X40\nN0005 X50\nN0006 M30\n";

double millX(PanelFixture& panel) {
    return panel.session->station(0).machine().position(0);
}

QString headerText(PanelFixture& panel, const char* name) {
    return panel.window->findChild<QLabel*>(name)->text();
}

}  // namespace

class StationTimeTest : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase() { useTestSettings(); }

    void startMovesTheAxesInTimeStopHoldsStartResumes() {
        PanelFixture panel;
        panel.session->setTimerEnabled(false);
        panel.session->addProgram(0, 60, "steps.nc", kSteps);
        QVERIFY(panel.session->selectProgram(0, 60));
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start
        QVERIFY(panel.session->control(0).programActive());
        panel.session->advance(0.5);
        const double first = millX(panel);
        QVERIFY2(first > 0.0 && first <= 10.0, qPrintable(QString::number(first)));
        QVERIFY(headerText(panel, "headerProgram").contains("N0001"));
        panel.session->advance(1.0);
        const double second = millX(panel);
        QVERIFY2(second > 10.0 && second <= 20.0, qPrintable(QString::number(second)));
        QVERIFY(headerText(panel, "headerProgram").contains("N0002"));

        panel.press(Qt::Key_F6, Qt::ShiftModifier);  // Stop: feed hold
        QVERIFY(panel.session->control(0).programHeld());
        panel.session->advance(1.0);  // time to brake
        const double held = millX(panel);
        const double busy = panel.session->station(0).machine().seconds();
        for (int tick = 0; tick < 100; ++tick)
            panel.session->advance(0.02);
        QCOMPARE(millX(panel), held);
        QCOMPARE(panel.session->station(0).machine().seconds(), busy);
        QVERIFY(panel.session->control(0).programActive());

        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start resumes
        QVERIFY(!panel.session->control(0).programHeld());
        panel.session->advance(1.0);
        QVERIFY(millX(panel) > held);
        for (int tick = 0; tick < 1000 && panel.session->control(0).programActive(); ++tick)
            panel.session->advance(0.02);
        QVERIFY(!panel.session->control(0).programActive());
        QCOMPARE(millX(panel), 50.0);
        QVERIFY(panel.session->station(0).machine().seconds() >= 5.0 - 1e-9);
    }

    void twoStationsRunAtOnce() {
        PanelFixture panel;
        panel.session->setTimerEnabled(false);
        panel.session->addProgram(0, 60, "steps.nc", kSteps);
        panel.session->addProgram(1, 60, "lathe.nc",
                                  "N0001 G1 G90 X20 F600\nN0002 X40\nN0003 M30\n");
        QVERIFY(panel.session->selectProgram(0, 60));
        QVERIFY(panel.session->selectProgram(1, 60));
        panel.press(Qt::Key_F5, Qt::ShiftModifier);          // Start on the mill
        panel.press(Qt::Key_PageDown, Qt::ControlModifier);  // to the lathe
        panel.press(Qt::Key_F5, Qt::ShiftModifier);          // Start on the lathe
        QVERIFY(panel.session->control(0).programActive());
        QVERIFY(panel.session->control(1).programActive());
        panel.session->advance(1.5);
        QVERIFY(millX(panel) > 10.0);
        QVERIFY(panel.session->station(1).machine().position(0) > 0.0);
        QVERIFY(panel.session->station(1).machine().seconds() > 1.0);
        QVERIFY(headerText(panel, "headerStation").contains("1"));
        for (int tick = 0; tick < 1000; ++tick)
            panel.session->advance(0.02);
        QVERIFY(!panel.session->control(0).programActive());
        QVERIFY(!panel.session->control(1).programActive());
    }

    void theTimerMovesTheMachineInRealTime() {
        PanelFixture panel;
        panel.session->addProgram(0, 60, "steps.nc", kSteps);
        QVERIFY(panel.session->selectProgram(0, 60));
        panel.press(Qt::Key_F5, Qt::ShiftModifier);
        QTRY_VERIFY(millX(panel) >= 20.0);  // about a second at x1
        QTRY_VERIFY(!panel.session->control(0).programActive());
    }

    void theSpeedKeyCyclesAndTheHeaderShowsIt() {
        PanelFixture panel;
        QVERIFY(headerText(panel, "headerSpeed").contains("\u00d71"));
        auto* key = panel.window->findChild<QPushButton*>("speedKey");
        QVERIFY(key && key->text().contains("\u00d71"));
        panel.press(Qt::Key_F10, Qt::ShiftModifier);
        QCOMPARE(panel.session->speed(), 10.0);
        QVERIFY(headerText(panel, "headerSpeed").contains("\u00d710"));
        QVERIFY(key->text().contains("\u00d710"));
        panel.press(Qt::Key_F10, Qt::ShiftModifier);
        QCOMPARE(panel.session->speed(), mtc::hmi::CellSession::kMaxSpeed);
        QVERIFY(headerText(panel, "headerSpeed").contains("max"));
        // As fast as possible: a long program is done within a few ticks.
        panel.session->addProgram(0, 61, "long.nc", "N0001 G1 G90 X300 F1\nN0002 M30\n");
        QVERIFY(panel.session->selectProgram(0, 61));
        panel.press(Qt::Key_F5, Qt::ShiftModifier);
        QTRY_VERIFY(!panel.session->control(0).programActive());
        QVERIFY(panel.session->station(0).machine().seconds() > 17000.0);  // 300 mm at F1
        key->click();
        QCOMPARE(panel.session->speed(), 1.0);
    }
};

QTEST_MAIN(StationTimeTest)
#include "test_station_time.moc"
