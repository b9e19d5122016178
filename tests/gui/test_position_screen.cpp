// The base screen ("position") driven by the real keys: it is the first
// screen after start-up, Start from the menu leads to it, F11 brings it
// back; while the program runs in simulated time (the panel's timer call,
// CellSession::advance) its positions, running block and status change.
#include <QLabel>
#include <QtTest>

#include "PanelFixture.h"
#include "screens/position/PositionScreen.h"

namespace {

// G54 of the mill: X-150 Y-80 Z-120. 10 mm at F600 = 1 s per move.
const char* kSteps =
    "N0001 G54 G90 G0 X0 Y0 Z10 S900 M3\n"
    "N0002 G1 X10 F600\n"
    "N0003 X20\n"
    "N0004 X30\n"
    "N0005 X40\n"
    "N0006 M30\n";

QString text(PanelFixture& panel, const QString& name) {
    auto* label = panel.window->screen(0, "position")->findChild<QLabel*>(name);
    if (!label) qFatal("no label %s on the base screen", qPrintable(name));
    return label->text();
}

/// Advances the station in timer ticks until `block` is the shown block (bounded).
void runUntilBlock(PanelFixture& panel, const char* block) {
    for (int tick = 0; tick < 5000 && panel.session->control(0).currentBlock() != block; ++tick)
        panel.session->advance(0.02);
}

}  // namespace

class PositionScreenTest : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase() { useTestSettings(); }

    void everyStationStartsOnItsBaseScreen() {
        PanelFixture panel;
        mtc::hmi::PanelOptions options;
        QString error;
        QVERIFY2(mtc::hmi::applyStartOptions(options, *panel.session, *panel.window, error),
                 qPrintable(error));
        QCOMPARE(panel.window->currentScreenName(), QString("position"));
        panel.press(Qt::Key_PageDown, Qt::ControlModifier);
        QCOMPARE(panel.window->currentScreenName(), QString("position"));
        auto* lathe = qobject_cast<mtc::screens::PositionScreen*>(panel.window->currentScreen());
        QVERIFY(lathe);
        // The lathe's axes X, Z, Y, Z2 and its spindle S1 as rotary axis C.
        QCOMPARE(lathe->findChild<QLabel*>("axisName-0")->text(), QString("X"));
        QVERIFY(lathe->status().axes.size() >= 4);
        QCOMPARE(lathe->status().spindles.size(), std::size_t(3));
    }

    void aRunningProgramIsWatchedOnTheBaseScreen() {
        PanelFixture panel;
        panel.session->setTimerEnabled(false);
        panel.session->addProgram(0, 60, "steps.nc", kSteps);
        QVERIFY(panel.session->selectProgram(0, 60));
        QCOMPARE(panel.window->currentScreenName(), QString("menu"));
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start from the menu
        QCOMPARE(panel.window->currentScreenName(), QString("position"));
        QCOMPARE(text(panel, "programState"), QString("Running"));

        runUntilBlock(panel, "N0002");
        panel.session->advance(0.5);
        QCOMPARE(text(panel, "axisName-0"), QString("X"));
        const QString work = text(panel, "axisWork-0");
        const QString machine = text(panel, "axisMachine-0");
        const double x = panel.session->station(0).machine().position(0);
        QCOMPARE(machine, QString::asprintf("%+.3f", x));
        QCOMPARE(work, QString::asprintf("%+.3f", x + 150.0));
        QVERIFY2(text(panel, "blockList").contains("N0002 G1 X10 F600"),
                 qPrintable(text(panel, "blockList")));
        QVERIFY(text(panel, "blockList").contains("N0004 X30"));  // the blocks after it
        QVERIFY(text(panel, "blockContext").contains("Program 60"));
        QVERIFY(text(panel, "feedValues").contains("600.0 mm/min"));
        QVERIFY(text(panel, "spindleValues").contains("900 rpm"));
        QVERIFY(text(panel, "spindleValues").contains("CW"));
        QVERIFY(text(panel, "zeroOffset").contains("G54"));
        QVERIFY(text(panel, "gFunctions").contains("G1 interpolation"));

        runUntilBlock(panel, "N0004");
        panel.session->advance(0.5);
        QVERIFY(text(panel, "axisWork-0") != work);  // the display moved with the axes
        QVERIFY(text(panel, "blockList").contains("N0006 M30"));

        panel.press(Qt::Key_F6, Qt::ShiftModifier);  // Stop: feed hold
        QVERIFY(text(panel, "programState").startsWith("Feed hold"));
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start continues
        QCOMPARE(text(panel, "programState"), QString("Running"));
        for (int tick = 0; tick < 1000 && panel.session->control(0).programActive(); ++tick)
            panel.session->advance(0.02);
        QVERIFY(!panel.session->control(0).programActive());
        // X40 at G54; program end resets the zero offset to G53.
        QCOMPARE(text(panel, "axisMachine-0"), QString("-110.000"));
        QVERIFY(text(panel, "zeroOffset").contains("G53"));
        QVERIFY(text(panel, "programState").startsWith("Ready"));
    }

    // The state on the base screen and the core's prompt in the header, in
    // the panel's language (the prompts: docs/DECISIONS.md D-026).
    void singleBlockAndTheProgrammedStopAreShown_data() {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QStringList>("stop");    // state, prompt
        QTest::addColumn<QStringList>("single");  // state, prompt
        QTest::addColumn<QString>("ready");
        QTest::newRow("en") << "en"
                            << QStringList{"Programmed stop",
                                           "Programmed stop: press Start to continue"}
                            << QStringList{"Single block",
                                           "Single block: press Start for the next block"}
                            << "Ready";
        QTest::newRow("de") << "de"
                            << QStringList{"Programmierter Halt",
                                           "Programmierter Halt: Start drücken zum Fortsetzen"}
                            << QStringList{"Einzelsatz",
                                           "Einzelsatz: Start drücken für den nächsten Satz"}
                            << "Bereit";
    }

    void singleBlockAndTheProgrammedStopAreShown() {
        QFETCH(QString, language);
        QFETCH(QStringList, stop);
        QFETCH(QStringList, single);
        QFETCH(QString, ready);
        mtc::hmi::PanelOptions options;
        options.language = language;
        PanelFixture panel(options);
        panel.session->setTimerEnabled(false);
        panel.session->addProgram(0, 61, "stop.nc",
                                  "N0001 G90 G1 X10 F600\nN0002 M00\nN0003 X20\nN0004 M30\n");
        QVERIFY(panel.session->selectProgram(0, 61));
        panel.press(Qt::Key_F11);  // the base screen from anywhere
        QCOMPARE(panel.window->currentScreenName(), QString("position"));
        auto* header = panel.window->findChild<QLabel*>("headerAlarm");
        panel.press(Qt::Key_F5, Qt::ShiftModifier);
        panel.session->advance(2.0);
        QVERIFY2(text(panel, "programState").startsWith(stop[0]),
                 qPrintable(text(panel, "programState")));
        QCOMPARE(header->text(), stop[1]);
        panel.press(Qt::Key_F8, Qt::ShiftModifier);  // single block on
        panel.press(Qt::Key_F5, Qt::ShiftModifier);
        panel.session->advance(2.0);
        QVERIFY2(text(panel, "programState").startsWith(single[0]),
                 qPrintable(text(panel, "programState")));
        QCOMPARE(header->text(), single[1]);
        panel.press(Qt::Key_F7, Qt::ShiftModifier);  // Control reset
        QVERIFY(text(panel, "programState").startsWith(ready));
    }

    void softKeysLeadToTheProgramDirectoryAndBack() {
        PanelFixture panel;
        panel.press(Qt::Key_F11);
        panel.press(Qt::Key_F1);
        QCOMPARE(panel.window->currentScreenName(), QString("programs"));
        panel.press(Qt::Key_F11);
        panel.press(Qt::Key_F8);
        QCOMPARE(panel.window->currentScreenName(), QString("menu"));
    }
};

QTEST_MAIN(PositionScreenTest)
#include "test_position_screen.moc"
