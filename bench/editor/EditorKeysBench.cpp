// Response of the program editor (decision ED-009) on a 1,000,000-block
// program, outside ctest: the real NcCodeEdit (windowing on, as in the
// editor screen), shown offscreen at 1024x600, every key followed by the
// event processing that repaints it:
//   QT_QPA_PLATFORM=offscreen mtc_editor_bench [google-benchmark flags]
// Open (text into the editor; windowed and, for comparison, ED-007's whole
// document), Ctrl+End/Ctrl+Home (each moves the window), PgDn through the
// program (window moves included), Down, a typed character with its
// Backspace, Enter with its Backspace, the whole text for Save after an
// edit. Counter peak_rss_mb: the process's peak resident memory so far.
#include <benchmark/benchmark.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QKeyEvent>
#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

#include "bench/ProcessMeters.h"
#include "screens/editor/NcCodeEdit.h"

namespace {

using mtc::bench::peakRssMb;

using mtc::screens::NcCodeEdit;

constexpr int kBlocks = 1'000'000;

const std::string& programText() {
    static const std::string text = [] {
        std::string t = "%NPG:1:01:0:001\n";
        t.reserve(static_cast<std::size_t>(kBlocks) * 28);
        char line[96];
        for (int i = 0; i < kBlocks; ++i) {
            const int n = std::snprintf(line, sizeof line, "N%04d G1 X%d.%d Y%d F%d\n", i % 10000,
                                        i % 97, i % 10, i % 89, 800 + (i % 4) * 100);
            t.append(line, static_cast<std::size_t>(n));
        }
        return t;
    }();
    return text;
}

std::unique_ptr<NcCodeEdit> shownEditor(bool windowing) {
    auto edit = std::make_unique<NcCodeEdit>();
    edit->setWindowing(windowing);
    edit->resize(1024, 600);
    edit->show();
    QApplication::processEvents();
    return edit;
}

/// One key as the user gives it, and the repaint it causes.
void press(NcCodeEdit& edit, int key, Qt::KeyboardModifiers modifiers = Qt::NoModifier,
           const QString& text = {}) {
    QKeyEvent down(QEvent::KeyPress, key, modifiers, text);
    QApplication::sendEvent(&edit, &down);
    QKeyEvent up(QEvent::KeyRelease, key, modifiers, text);
    QApplication::sendEvent(&edit, &up);
    QApplication::processEvents();
}

/// The editor the key benchmarks share (released before the application).
std::unique_ptr<NcCodeEdit>& sharedEditor() {
    static std::unique_ptr<NcCodeEdit> edit;
    return edit;
}

NcCodeEdit& openEditor() {
    if (!sharedEditor()) {
        sharedEditor() = shownEditor(true);
        sharedEditor()->load(programText());
        QApplication::processEvents();
    }
    return *sharedEditor();
}

void BM_EditorOpen(benchmark::State& state) {
    const bool windowing = state.range(0) != 0;
    for (auto _ : state) {
        state.PauseTiming();
        auto edit = shownEditor(windowing);
        state.ResumeTiming();
        edit->load(programText());
        QApplication::processEvents();  // the first paint
        benchmark::DoNotOptimize(edit->lineCount());
        state.PauseTiming();
        edit.reset();
        state.ResumeTiming();
    }
    state.counters["peak_rss_mb"] = peakRssMb();
}
BENCHMARK(BM_EditorOpen)->Arg(1)->Iterations(5)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EditorOpen)->Arg(0)->Iterations(1)->Unit(benchmark::kMillisecond);

void BM_CtrlEndCtrlHome(benchmark::State& state) {
    NcCodeEdit& edit = openEditor();
    bool atEnd = false;
    for (auto _ : state) {
        press(edit, atEnd ? Qt::Key_Home : Qt::Key_End, Qt::ControlModifier);
        atEnd = !atEnd;
    }
    state.counters["line"] = edit.cursorLine();
}
BENCHMARK(BM_CtrlEndCtrlHome)->Unit(benchmark::kMillisecond);

void BM_PageDown(benchmark::State& state) {
    NcCodeEdit& edit = openEditor();
    int windowMoves = 0;
    QElapsedTimer clock;
    qint64 slowestNs = 0;
    for (auto _ : state) {
        const int window = edit.windowStart();
        clock.start();
        press(edit, Qt::Key_PageDown);
        slowestNs = std::max(slowestNs, clock.nsecsElapsed());
        if (edit.windowStart() != window) ++windowMoves;
        if (edit.cursorLine() == edit.lineCount()) {
            state.PauseTiming();
            press(edit, Qt::Key_Home, Qt::ControlModifier);
            state.ResumeTiming();
        }
    }
    state.counters["window_moves"] = windowMoves;
    state.counters["slowest_ms"] = static_cast<double>(slowestNs) / 1e6;
}
BENCHMARK(BM_PageDown)->Unit(benchmark::kMillisecond);

void BM_Down(benchmark::State& state) {
    NcCodeEdit& edit = openEditor();
    for (auto _ : state)
        press(edit, Qt::Key_Down);
}
BENCHMARK(BM_Down)->Unit(benchmark::kMillisecond);

/// A character typed and taken back (two keys per iteration).
void BM_TypeAndBackspace(benchmark::State& state) {
    NcCodeEdit& edit = openEditor();
    press(edit, Qt::Key_End, Qt::ControlModifier);
    press(edit, Qt::Key_Up);
    press(edit, Qt::Key_End);
    for (auto _ : state) {
        press(edit, Qt::Key_X, Qt::NoModifier, "x");
        press(edit, Qt::Key_Backspace);
    }
}
BENCHMARK(BM_TypeAndBackspace)->Unit(benchmark::kMillisecond);

void BM_EnterAndBackspace(benchmark::State& state) {
    NcCodeEdit& edit = openEditor();
    for (auto _ : state) {
        press(edit, Qt::Key_Return, Qt::NoModifier, "\r");
        press(edit, Qt::Key_Backspace);
    }
}
BENCHMARK(BM_EnterAndBackspace)->Unit(benchmark::kMillisecond);

/// Ctrl+End after a character typed near the start: the window's splice
/// moves the whole text behind it (the worst case of a window move).
void BM_CtrlEndAfterEditAtStart(benchmark::State& state) {
    NcCodeEdit& edit = openEditor();
    for (auto _ : state) {
        state.PauseTiming();
        press(edit, Qt::Key_Home, Qt::ControlModifier);
        press(edit, Qt::Key_Down);
        press(edit, Qt::Key_X, Qt::NoModifier, "x");
        state.ResumeTiming();
        press(edit, Qt::Key_End, Qt::ControlModifier);
    }
}
BENCHMARK(BM_CtrlEndAfterEditAtStart)->Unit(benchmark::kMillisecond);

/// What Save hands the workspace: the whole text with a fresh edit spliced in.
void BM_WholeTextAfterEdit(benchmark::State& state) {
    NcCodeEdit& edit = openEditor();
    for (auto _ : state) {
        state.PauseTiming();
        press(edit, Qt::Key_X, Qt::NoModifier, "x");
        state.ResumeTiming();
        benchmark::DoNotOptimize(edit.wholeText().size());
    }
    state.counters["peak_rss_mb"] = peakRssMb();
}
BENCHMARK(BM_WholeTextAfterEdit)->Iterations(5)->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    sharedEditor().reset();
    benchmark::Shutdown();
    return 0;
}
