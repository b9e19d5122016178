// The 3D toolpath view while the station's program runs (xvfb-run, Mesa
// llvmpipe): the backplot is drawn over the kept steady picture and a frame
// from it is the full frame (TP-016, TP-018); the part being cut is drawn
// (TP-027); a station change with nothing new to show renders nothing; the
// steps are rendered at the frame rate, and a hidden live part keeps the
// steady picture (TP-029).
#include <QDir>
#include <QLabel>
#include <QSignalSpy>
#include <QTemporaryDir>

#include "ToolpathGlSupport.h"
#include "screens/toolpath/ToolpathModel.h"

using mtc::screens::ToolpathScreen;
using mtc::screens::VtkToolpathCanvas;

class ToolpathGlRunningTest : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { useTestSettings(); }

    /// TP-016, TP-018: while the program runs (Start) the backplot is in the
    /// picture, the steady picture is kept as an image between the station's
    /// steps, and a frame drawn from it is the frame drawn in full.
    void runningProgramDrawsTheBackplotOverTheKeptSteadyPicture() {
        PanelFixture panel;
        panel.session->selectProgram(0, 1);
        panel.window->showScreen("toolpath");
        panel.session->setTimerEnabled(false);
        ToolpathScreen* screen = toolpath(panel);
        VtkToolpathCanvas* canvas = vtkCanvas(screen);
        QVERIFY(canvas);
        canvas->setFrameInterval(0);  // one render per step: this test is about the kept picture
        const auto& palette = screen->model()->palette();
        const int nearWhite = count(canvas->picture(), palette.backplot);  // text, labels
        panel.press(Qt::Key_F5, Qt::ShiftModifier);                        // Start
        const int keptBefore = canvas->keptRenders();
        for (int tick = 0; tick < 60; ++tick) {
            panel.session->advance(0.2);
            QCoreApplication::processEvents();  // the coalesced render of the step
        }
        QVERIFY(!screen->model()->backplot(false).empty());
        QVERIFY2(canvas->keptRenders() > keptBefore + 10,
                 qPrintable(QString::number(canvas->keptRenders() - keptBefore)));
        const QImage kept = canvas->picture();
        QVERIFY2(count(kept, palette.backplot) > nearWhite + 100,
                 qPrintable(QString("%1 %2").arg(count(kept, palette.backplot)).arg(nearWhite)));
        canvas->keepSteadyPicture(false);
        const QImage full = canvas->picture();
        QCOMPARE(kept.size(), full.size());
        const QImage a = kept.convertToFormat(QImage::Format_RGB32);
        const QImage b = full.convertToFormat(QImage::Format_RGB32);
        int differing = 0;
        for (int y = 0; y < a.height(); ++y)
            for (int x = 0; x < a.width(); ++x)
                if (a.pixel(x, y) != b.pixel(x, y)) ++differing;
        if (differing != 0 && qEnvironmentVariableIsSet("MTC_KEEP_PICTURES")) {
            kept.save("/tmp/kept.png");
            full.save("/tmp/full.png");
        }
        QVERIFY2(differing == 0, qPrintable(QString("%1 pixels differ").arg(differing)));
    }

    /// TP-027: after Start the view draws the station's part, the blank
    /// first (the pocket and the step of the finished part are gone), cut
    /// as the axes travel; at the end the part the run left.
    void thePartBeingCutIsDrawnWhileTheProgramRuns() {
        PanelFixture panel;
        VtkToolpathCanvas* canvas = nullptr;
        ToolpathScreen* screen = showToolpathOf(panel, 1, canvas);
        QVERIFY(canvas);
        panel.session->setTimerEnabled(false);
        const auto* model = screen->model();
        const auto differing = [](const QImage& a, const QImage& b) {
            int n = 0;
            for (int y = 0; y < a.height(); y += 2)
                for (int x = 0; x < a.width(); x += 2)
                    if (a.pixel(x, y) != b.pixel(x, y)) ++n;
            return n;
        };
        canvas->renderNow();
        const QImage finished = canvas->picture();
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start
        panel.session->advance(0.02);
        QVERIFY(model->partIsLive());
        canvas->renderNow();
        const QImage blank = canvas->picture();
        QVERIFY2(differing(finished, blank) > 2000,
                 qPrintable(QString::number(differing(finished, blank))));
        for (int tick = 0; tick < 20000 && panel.session->station(0).busy(); ++tick)
            panel.session->advance(0.25);
        panel.session->advance(0.02);
        QTRY_VERIFY_WITH_TIMEOUT(model->part().note.startsWith("Part as the run left it"),
                                 4 * mtc::screens::ToolpathModel::kLiveMeshMs);
        canvas->renderNow();
        const QImage cut = canvas->picture();
        QVERIFY2(differing(blank, cut) > 2000, qPrintable(QString::number(differing(blank, cut))));
    }

    void aStationChangeWithNothingNewToShowRendersNothing() {
        QTemporaryDir dir;
        writeProgram(QDir(dir.path()), 6,
                     QString("iMTc/01006/01.00/0000000000/26.11.2026/16:00:00/N1010006.DAT/1\n"
                             "%NPG:1:01:0:006\n!01.00\n#01Dwell\n$\n$\n$\n$\n*Dwell\n%NPG\n"
                             "N0001 G1 G90 X-100 Y-50 Z-100 F3000\nN0002 G4 F3\n"
                             "N0003 G1 X-60\nN0004 M30\n"));
        mtc::hmi::PanelOptions options;
        options.programsDir = dir.path();
        PanelFixture panel(options);
        panel.session->selectProgram(0, 6);
        QVERIFY(panel.window->showScreen("toolpath"));
        panel.session->setTimerEnabled(false);
        VtkToolpathCanvas* canvas = vtkCanvas(toolpath(panel));
        QVERIFY(canvas);
        canvas->setFrameInterval(0);                 // each step's render in its event-loop pass
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start
        const auto& station = panel.session->station(0);
        const auto dwelling = [&] {
            const auto* front = station.machine().engine().queued(0);
            return front && front->kind == mtc::core::motion::QueueItem::Kind::Dwell;
        };
        for (int tick = 0; tick < 2000 && !dwelling(); ++tick) {
            panel.session->advance(0.05);
            QCoreApplication::processEvents();
        }
        QVERIFY(dwelling());
        panel.session->advance(0.1);
        QCoreApplication::processEvents();  // the last move's end drawn
        const int renders = canvas->renderCount();
        const std::uint64_t revision = station.revision();
        for (int tick = 0; tick < 10; ++tick) {
            panel.session->advance(0.1);
            QCoreApplication::processEvents();
        }
        QVERIFY(dwelling());
        QVERIFY(station.revision() > revision);  // the station did change (its time)
        QCOMPARE(canvas->renderCount(), renders);
        for (int tick = 0; tick < 40 && canvas->renderCount() == renders; ++tick) {
            panel.session->advance(0.1);  // the dwell ends, X moves
            QCoreApplication::processEvents();
        }
        QVERIFY(canvas->renderCount() > renders);
    }

    /// TP-029: while M hides the part, the live part meshed again as the
    /// tool cuts it draws nothing: the steady picture kept before stays.
    void aHiddenLivePartKeepsTheSteadyPicture() {
        PanelFixture panel;
        VtkToolpathCanvas* canvas = nullptr;
        ToolpathScreen* screen = showToolpathOf(panel, 1, canvas);
        QVERIFY(canvas);
        panel.session->setTimerEnabled(false);
        canvas->setFrameInterval(0);
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start
        panel.session->advance(0.02);
        QVERIFY(screen->model()->partIsLive());
        panel.press(Qt::Key_M);
        QVERIFY(!screen->model()->partShown());
        // On to the cutting (after the tool change's G53 moves: the labels'
        // zero offset then stays G54, TP-019).
        const auto& cut = panel.session->station(0).liveCut();
        for (int tick = 0; tick < 6000 && !(cut.part()->removedVolume() > 0.0); ++tick) {
            panel.session->advance(0.05);
            QCoreApplication::processEvents();
        }
        QVERIFY(cut.part()->removedVolume() > 0.0);
        canvas->renderNow();
        canvas->renderNow();  // kept from here on
        const int pictures = canvas->keptPictures(), renders = canvas->renderCount();
        QSignalSpy meshed(screen->model(), &mtc::screens::ToolpathModel::partChanged);
        // Until the view has taken the live part twice (at most every
        // kLiveMeshMs while the axes move, so the test waits for it).
        for (int tick = 0; tick < 3000 && meshed.count() < 2; ++tick) {
            panel.session->advance(0.05);
            QTest::qWait(10);
        }
        QVERIFY(meshed.count() >= 2);
        QVERIFY(canvas->renderCount() > renders);  // the tool and backplot moved
        QCOMPARE(canvas->keptPictures(), pictures);
    }

    /// TP-029: while the program runs, the station's steps ask for renders
    /// at the panel's tick; the view renders at most once per frame
    /// interval, with what is newest then. An interval no test run reaches
    /// (one hour) shows that steps alone render nothing until it is over.
    void theStepsOfARunningProgramAreRenderedAtTheFrameRate() {
        PanelFixture panel;
        VtkToolpathCanvas* canvas = nullptr;
        ToolpathScreen* screen = showToolpathOf(panel, 1, canvas);
        QVERIFY(canvas);
        panel.session->setTimerEnabled(false);
        QVERIFY(canvas->frameInterval() > 0 && canvas->frameInterval() <= 50);  // 20 Hz or more
        const QColor backplot = screen->model()->palette().backplot;
        const int nearWhite = count(canvas->picture(), backplot);  // text, labels
        canvas->setFrameInterval(3600 * 1000);
        canvas->renderNow();  // the interval counts from here
        const int renders = canvas->renderCount();
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start
        for (int tick = 0; tick < 60; ++tick) {
            panel.session->advance(0.2);
            QCoreApplication::processEvents();
        }
        QVERIFY(!screen->model()->backplot(false).empty());
        QCOMPARE(canvas->renderCount(), renders);  // asked for, waiting for its time
        QVERIFY(canvas->framePending());
        canvas->setFrameInterval(0);  // its time has come: one render, the newest state
        QTRY_COMPARE(canvas->renderCount(), renders + 1);
        QVERIFY(!canvas->framePending());
        const int drawn = count(canvas->picture(), backplot);
        QVERIFY2(drawn > nearWhite + 100, qPrintable(QString("%1 %2").arg(drawn).arg(nearWhite)));
    }
};

QTEST_MAIN(ToolpathGlRunningTest)
#include "test_toolpath_gl_running.moc"
