// Adaptive feed trend screen: the demo program with G26/ITM fills the trend
// of the simulated machine; soft keys change the window and export PNG and
// CSV (written atomically).
#include <QDir>
#include <QFile>
#include <QImage>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QProcess>
#include <QTemporaryDir>

#include "PanelFixture.h"
#include "cnc_core/afc/AfcTrendRecorder.h"
#include "cnc_core/machine_data/MachineDataFile.h"
#include "cnc_core/machine_data/MachineDataStore.h"
#include "screens/afc_trend/AfcTrendPlot.h"
#include "screens/afc_trend/AfcTrendScreen.h"

class AfcTrendScreenTest : public QObject {
    Q_OBJECT
    /// Selects the slot milling demo (program 2 of the mill) and runs it to
    /// its end at high speed with the Start key (Shift+F5).
    static void runSlotDemo(PanelFixture& panel) {
        panel.session->setSpeed(mtc::hmi::CellSession::kMaxSpeed);
        QVERIFY(panel.session->selectProgram(0, 2));
        panel.press(Qt::Key_F5, Qt::ShiftModifier);
        QTRY_VERIFY_WITH_TIMEOUT(!panel.session->control(0).programActive(), 20000);
        QVERIFY(panel.session->afcTrend(0).size() > 0);  // it ran
        QCOMPARE(QString::fromStdString(panel.session->control(0).alarm()), QString());
    }

  private slots:
    void initTestCase() { useTestSettings(); }

    void demoProgramFillsTheTrendAndExports() {
        PanelFixture panel;
        QVERIFY(panel.window->showScreen("afc-trend"));
        auto* screen =
            qobject_cast<mtc::screens::AfcTrendScreen*>(panel.window->screen(0, "afc-trend"));
        QVERIFY(screen);
        auto* plot = screen->findChild<mtc::screens::AfcTrendPlot*>("afcTrendPlot");
        auto* status = screen->findChild<QLabel*>("afcTrendStatus");
        auto* message = screen->findChild<QLabel*>("afcTrendMessage");
        QVERIFY(plot && status && message);
        QVERIFY(plot->samples().empty());
        QVERIFY(status->text().startsWith("No trend yet"));

        // The slot milling demo (program 2 of the mill) at high speed.
        panel.session->setSpeed(1e6);
        QVERIFY(panel.session->selectProgram(0, 2));
        QVERIFY(panel.session->pressKey(0, mtc::core::ControlKey::Start));
        QTRY_VERIFY_WITH_TIMEOUT(!panel.session->control(0).programActive(), 20000);
        QCOMPARE(QString::fromStdString(panel.session->control(0).alarm()), QString());
        QTRY_VERIFY(!plot->samples().empty());
        QVERIFY(status->text().contains("samples"));
        double peak = 0;
        for (const auto& s : panel.session->afcTrend(0).samples())
            peak = std::max(peak, s.feedReduction);
        QVERIFY(peak > 50.0);  // the F3200 section is reduced by about 70 %

        QCOMPARE(screen->windowSeconds(), 10.0);
        panel.press(Qt::Key_F1);
        QCOMPARE(screen->windowSeconds(), 60.0);
        panel.press(Qt::Key_F1);
        QCOMPARE(screen->windowSeconds(), 0.0);
        QCOMPARE(plot->samples().size(), panel.session->afcTrend(0).size());

        QTemporaryDir dir;
        screen->setExportDirectory(dir.path());
        panel.press(Qt::Key_F2);
        QImage image(dir.filePath("afc-trend-P0.png"));
        QVERIFY(!image.isNull());
        QVERIFY(message->text().contains("afc-trend-P0.png"));
        panel.press(Qt::Key_F3);
        QFile csv(dir.filePath("afc-trend-P0.csv"));
        QVERIFY(csv.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = csv.readAll().split('\n');
        QVERIFY(lines.first().startsWith("time_s,torque_actual_pct"));
        QCOMPARE(lines.size() - 2, static_cast<int>(panel.session->afcTrend(0).size()));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files).size(), 2);  // no temporary files left
    }

    /// Seed 002 Fig. 6-1 on the screen: maximum idling torque 006, stall
    /// torque 014, the signals EXCTH / THMIS and the measuring period of ITM.
    void trendShowsLimitsSignalsAndTheItmPhase() {
        PanelFixture panel;
        QVERIFY(panel.window->showScreen("afc-trend"));
        auto* screen =
            qobject_cast<mtc::screens::AfcTrendScreen*>(panel.window->screen(0, "afc-trend"));
        auto* plot = screen->findChild<mtc::screens::AfcTrendPlot*>("afcTrendPlot");
        auto* status = screen->findChild<QLabel*>("afcTrendStatus");
        runSlotDemo(panel);
        panel.press(Qt::Key_F1);  // window 60 s
        panel.press(Qt::Key_F1);  // every sample
        QCOMPARE(screen->windowSeconds(), 0.0);
        QTRY_COMPARE(plot->samples().size(), panel.session->afcTrend(0).size());

        const auto phases = plot->itmPhases();
        QCOMPARE(phases.size(), std::size_t{1});  // N0004 ... ITM
        const double measured = phases[0].second - phases[0].first;
        QVERIFY2(measured > 0.15 && measured < 0.25, qPrintable(QString::number(measured)));
        const QImage image = plot->grab().toImage();
        const int x = static_cast<int>(plot->xOf((phases[0].first + phases[0].second) / 2));
        const QColor band = image.pixelColor(x, 44);  // just under the top of the torque panel
        const QColor itm = mtc::screens::AfcTrendPlot::itmColor();
        QVERIFY2(std::abs(band.red() - itm.red()) + std::abs(band.green() - itm.green()) +
                         std::abs(band.blue() - itm.blue()) <
                     30,
                 qPrintable(band.name()));

        bool excessive = false, measuring = false;
        for (const auto& s : plot->samples()) {
            excessive = excessive || s.excessiveThrust;
            measuring = measuring || s.measuringIdle;
            QCOMPARE(s.maximumIdleTorque, 30.0);  // Bxx.066 default
        }
        QVERIFY(excessive);  // the F3200 section passes 013 = 70 %
        QVERIFY(measuring);
        for (const char* name :
             {"max. idling 006", "stall 014", "PxxS.EXCTH", "PxxS.THMIS", "ITM measuring period"})
            QVERIFY2(mtc::screens::AfcTrendPlot::legend().contains(name), name);
        QVERIFY(status->text().contains("max. 006 30.0 %"));
        QVERIFY(status->text().contains("EXCTH"));
        QVERIFY(status->text().contains("THMIS"));
    }

    /// The CLI and the panel give the same adaptive feed control for the same
    /// program: one noise of the torque model, a function of the machine
    /// clock and the configured seed (regression: the noise differed).
    void panelAndCliProduceTheSameTorqueNoise() {
        const QString cli = qEnvironmentVariable("MTC_CLI");
        if (cli.isEmpty()) QSKIP("MTC_CLI is not set (ctest sets it)");
        PanelFixture panel;
        runSlotDemo(panel);
        QProcess process;
        process.start(cli, {"--json", "run", "2"});
        QVERIFY(process.waitForFinished(60000));
        QCOMPARE(process.exitCode(), 0);
        const QJsonObject afc =
            QJsonDocument::fromJson(process.readAllStandardOutput()).object()["afc"].toObject();
        const std::pair<int, const char*> elements[] = {{5, "005_idle_torque"},
                                                        {7, "007_machining_torque"},
                                                        {8, "008_peak_machining_torque"},
                                                        {11, "011_feed_reduction"},
                                                        {12, "012_peak_feed_reduction"}};
        for (const auto& [element, key] : elements) {
            double value = -1;
            panel.session->machineData().read({30, 0, 0, element}, value);
            QVERIFY2(afc.contains(key), key);
            QVERIFY2(std::abs(afc[key].toDouble() - value) < 1e-9,
                     qPrintable(QString("%1: CLI %2, panel %3")
                                    .arg(key)
                                    .arg(afc[key].toDouble(), 0, 'g', 17)
                                    .arg(value, 0, 'g', 17)));
        }
    }

    void exportIntoAMissingDirectoryIsReported() {
        PanelFixture panel;
        QVERIFY(panel.window->showScreen("afc-trend"));
        auto* screen =
            qobject_cast<mtc::screens::AfcTrendScreen*>(panel.window->screen(0, "afc-trend"));
        screen->setExportDirectory("/nonexistent/afc/dir");
        panel.press(Qt::Key_F3);
        auto* message = screen->findChild<QLabel*>("afcTrendMessage");
        QVERIFY(message->text().startsWith("CSV export failed"));
    }

    /// Values the NC writes (page 30 status of G26/G25) reach the data file
    /// within a second, and at the latest when the session ends.
    void ncWrittenMachineDataIsSaved() {
        QTemporaryDir dir;
        const QString file = dir.filePath("cell.mdt");
        mtc::hmi::PanelOptions options;
        options.dataFile = file;
        double peak = -1;
        mtc::core::MachineConfig config;
        {
            PanelFixture panel(options);
            config = panel.session->config();
            panel.session->setSpeed(1e6);
            QVERIFY(panel.session->selectProgram(0, 2));
            QVERIFY(panel.session->pressKey(0, mtc::core::ControlKey::Start));
            QTRY_VERIFY_WITH_TIMEOUT(!panel.session->control(0).programActive(), 20000);
            QTRY_VERIFY_WITH_TIMEOUT(!panel.session->machineDataUnsaved(), 5000);
            mtc::core::MachineDataStore saved(panel.session->config());
            QVERIFY(mtc::core::MachineDataFile(file.toStdString()).load(saved).diagnostics.empty());
            saved.read({30, 0, 0, 12}, peak);
            QVERIFY(peak > 50.0);  // 012 peak feed reduction, written at G25
            // A change right before the end: saved by the destructor, not lost.
            QCOMPARE(panel.session->machineData().write({30, 0, 0, 10}, 44.0,
                                                        mtc::core::MachineDataWriter::Nc),
                     mtc::core::MachineDataStatus::Ok);
            QVERIFY(panel.session->machineDataUnsaved());
        }
        mtc::core::MachineDataStore reloaded(config);
        QVERIFY(mtc::core::MachineDataFile(file.toStdString()).load(reloaded).diagnostics.empty());
        double limit = -1;
        reloaded.read({30, 0, 0, 10}, limit);
        QCOMPARE(limit, 44.0);
    }
};

QTEST_MAIN(AfcTrendScreenTest)
#include "test_afc_trend_screen.moc"
