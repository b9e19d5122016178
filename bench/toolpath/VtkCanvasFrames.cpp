// Frame times of the real toolpath view (issue 8), outside ctest: the panel
// with a generated program of `count` (1,000,000) straight moves, the
// toolpath screen's VTK canvas (QVTKOpenGLNativeWidget, grid, triad, stock):
//   xvfb-run -a -s "-screen 0 1280x800x24" mtc_toolpath_canvas_bench [count] -platform xcb
// Prints the build time of the view (program run, geometry, poly-data and
// coarse copy), frame times while moving (coarse copy) and still (full
// path), the time of a panel tick while the program runs (the station's
// 20 ms step, the view following it: tool, backplot, running block, and the
// render; issue 19 §2), and the process's peak RSS.
#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "bench/ProcessMeters.h"
#include "hmi/CellSession.h"
#include "hmi/PanelStartup.h"
#include "hmi/PanelWindow.h"
#include "hmi/ScreenRegistry.h"
#include "screens/ScreenCatalog.h"
#include "screens/toolpath/ToolpathModel.h"
#include "screens/toolpath/ToolpathScreen.h"
#include "screens/toolpath/VtkToolpathCanvas.h"

namespace {

using mtc::bench::Clock;
using mtc::bench::msSince;
using mtc::bench::peakRssMb;

/// Program 9 of the mill: `count` 0.1 mm moves in 100 mm passes over the
/// stock, every 100th a rapid (the shape mtc_toolpath_bench draws).
bool writeProgram(const QString& dir, int count) {
    std::string text =
        "iMTc/01009/01.00/0000000000/21.11.2026/19:00:00/N1010009.DAT/1\n%NPG:1:01:0:009\n"
        "!01.00\n#01Frames\n$\n$\n$\n$\n*Frames\n%NPG\nN0000 G0 G17 G90 G94 X-150 Y-80 Z-120\n";
    text.reserve(static_cast<std::size_t>(count) * 36);
    char line[64];
    for (int i = 1; i <= count; ++i) {
        const int pass = (i - 1) / 1000, step = (i - 1) % 1000 + 1;
        const double x = pass % 2 ? -50.0 - step * 0.1 : -150.0 + step * 0.1;
        const int n = std::snprintf(line, sizeof line, "N%04d %s X%.3f Y%.3f Z%.3f\n", i % 10000,
                                    i % 100 == 0 ? "G0" : "G1 F1000", x, -80.0 + pass * 0.06,
                                    -120.0 - (pass / 100) * 0.5);
        text.append(line, static_cast<std::size_t>(n));
    }
    text += "N9999 M30\n";
    QFile file(QDir(dir).filePath("N1010009.DAT"));
    return file.open(QIODevice::WriteOnly) &&
           file.write(text.data(), static_cast<qint64>(text.size())) ==
               static_cast<qint64>(text.size());
}

/// Median and first of `frames` renders, each after `step()`.
template <typename Step>
void measure(const char* what, mtc::screens::VtkToolpathCanvas* canvas, Step step) {
    std::vector<double> times;
    for (int i = 0; i < 11; ++i) {
        step();
        const auto t = Clock::now();
        canvas->renderNow();
        times.push_back(msSince(t));
    }
    const double first = times.front();
    std::sort(times.begin(), times.end());
    std::printf("%-40s first %7.1f ms, median %7.1f ms, max %7.1f ms\n", what, first, times[5],
                times.back());
    std::fflush(stdout);
}

/// Still frames with Qt's paint of the window after each render (what a
/// frame costs beyond VTK's render on the panel).
void measurePainted(mtc::screens::VtkToolpathCanvas* canvas) {
    std::vector<double> times;
    for (int i = 0; i < 11; ++i) {
        const auto t = Clock::now();
        canvas->renderNow();
        QApplication::processEvents();
        times.push_back(msSince(t));
    }
    std::sort(times.begin(), times.end());
    std::printf("%-40s median %7.1f ms\n", "still, rendered and painted by Qt", times[5]);
}

/// Ticks of the running program: the station moves on by one panel tick
/// (20 ms at x10 speed, so the backplot grows visibly), the screen follows
/// and renders; per tick the whole time until the render is done.
void measureTicks(const char* what, mtc::hmi::CellSession& session,
                  mtc::screens::VtkToolpathCanvas* canvas) {
    std::vector<double> times, steps;
    for (int i = 0; i < 41; ++i) {
        const int renders = canvas->renderCount();
        const auto t = Clock::now();
        session.advance(0.2);  // the station's step, the model and canvas following it
        steps.push_back(msSince(t));
        while (canvas->renderCount() == renders && msSince(t) < 5000)
            QApplication::processEvents();
        times.push_back(msSince(t));
    }
    const double first = times.front();
    std::sort(times.begin(), times.end());
    std::sort(steps.begin(), steps.end());
    std::printf(
        "%-40s first %7.1f ms, median %7.1f ms, max %7.1f ms (step + model: median %.1f ms)\n",
        what, first, times[times.size() / 2], times.back(), steps[steps.size() / 2]);
    std::fflush(stdout);
}

/// The running program's ticks with the whole scene drawn each tick (as
/// before TP-018), then with the steady picture kept as an image.
void measureRunning(mtc::hmi::CellSession& session, mtc::screens::VtkToolpathCanvas* canvas) {
    session.setTimerEnabled(false);
    session.pressKey(0, mtc::core::ControlKey::Start);
    for (int i = 0; i < 5; ++i)  // the approach and the first frames
        session.advance(0.2);
    QApplication::processEvents();
    canvas->keepSteadyPicture(false);
    measureTicks("running, whole scene each tick", session, canvas);
    canvas->keepSteadyPicture(true);
    const int kept = canvas->keptRenders();
    measureTicks("running, steady picture kept", session, canvas);
    std::printf("(%d of 41 ticks drawn from the kept picture)\n", canvas->keptRenders() - kept);
}

}  // namespace

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    const int count = argc > 1 ? std::max(1, std::atoi(argv[1])) : 1'000'000;
    QTemporaryDir dir;
    if (!dir.isValid() || !writeProgram(dir.path(), count)) return 1;
    mtc::hmi::PanelOptions options;
    options.programsDir = dir.path();
    QString error;
    auto session = mtc::hmi::createSession(options, error);
    if (!session) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return 1;
    }
    mtc::hmi::ScreenRegistry registry;
    mtc::screens::registerAllScreens(registry);
    mtc::hmi::PanelWindow window(session.get(), &registry);
    window.show();
    session->selectProgram(0, 9);
    const double rss0 = peakRssMb();
    const auto t0 = Clock::now();
    window.showScreen("toolpath");  // runs the program, builds geometry and poly-data
    auto* screen = static_cast<mtc::screens::ToolpathScreen*>(window.screen(0, "toolpath"));
    auto* canvas = qobject_cast<mtc::screens::VtkToolpathCanvas*>(screen->canvas());
    if (!canvas) {
        std::fprintf(stderr, "no VTK canvas (no OpenGL?)\n");
        return 1;
    }
    std::printf("%s\nview built in %.0f ms (program run, geometry, poly-data, coarse copy)\n",
                qPrintable(screen->model()->summary()), msSince(t0));
    const auto t1 = Clock::now();
    canvas->renderNow();
    std::printf("first frame %.0f ms, canvas %d x %d, coarse copy %zu cells\n", msSince(t1),
                canvas->width(), canvas->height(), canvas->levelOfDetailCells());
    measure("while moving (coarse copy, rotate 5 deg)", canvas, [&] { canvas->rotate(5, 0); });
    QElapsedTimer still;
    still.start();
    while (canvas->showingLevelOfDetail() && still.elapsed() < 5000)
        QApplication::processEvents(QEventLoop::AllEvents, 50);
    measure("still (full path)", canvas, [] {});
    measurePainted(canvas);
    measureRunning(*session, canvas);
    std::printf("peak RSS %.1f MB (+%.1f MB for the view)\n", peakRssMb(), peakRssMb() - rss0);
    return 0;
}
