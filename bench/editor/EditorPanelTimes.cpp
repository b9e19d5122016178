// Whole-panel times of the program editor on a 1,000,000-block program
// (decision ED-009), outside ctest; keys go to the focused widget as a
// user's would, each followed by the event processing that repaints:
//   QT_QPA_PLATFORM=offscreen mtc_editor_panel_bench [blocks]
// Prints: session start (parse), the directory's listing, Edit (F2) to the
// shown editor, Ctrl+End, typing, Save (Ctrl+S: whole text, atomic write,
// program parsed again), Compile (F2), the error window's Enter to the
// faulty line far below, and the process's peak RSS.
#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QKeyEvent>
#include <QListView>
#include <QTemporaryDir>
#include <cstdio>
#include <string>

#include "bench/ProcessMeters.h"
#include "hmi/CellSession.h"
#include "hmi/PanelStartup.h"
#include "hmi/PanelWindow.h"
#include "hmi/ScreenRegistry.h"
#include "screens/ScreenCatalog.h"
#include "screens/editor/NcCodeEdit.h"
#include "screens/programs/ProgramDirectoryModel.h"

namespace {

using mtc::bench::peakRssMb;

/// The process's resident memory now (VmRSS), in MB.
double rssMb() {
    QFile status("/proc/self/status");
    if (!status.open(QIODevice::ReadOnly)) return 0;
    for (const QByteArray& line : status.readAll().split('\n'))
        if (line.startsWith("VmRSS:")) return line.mid(6).trimmed().split(' ')[0].toDouble() / 1024;
    return 0;
}

/// Program 9: `count` moves, a macro definition (compiler keyword) at the
/// start and a faulty one at 90 % of the program.
bool writeProgram(const QString& dir, int count) {
    std::string text =
        "iMTc/01009/01.00/0000000000/21.11.2026/19:00:00/N1010009.DAT/1\n%NPG:1:01:0:009\n"
        "!01.00\n#01Editor\n$\n$\n$\n$\n*Editor\n%NPG\nN0000 DEFINE SAFE AS G0 Z50\n";
    text.reserve(static_cast<std::size_t>(count) * 28);
    char line[64];
    for (int i = 1; i < count; ++i) {
        const int n = i == count / 10 * 9
                          ? std::snprintf(line, sizeof line, "N%04d DEFINE 9BAD AS G1\n", i % 10000)
                          : std::snprintf(line, sizeof line, "N%04d G1 X%d Y%d F1000\n", i % 10000,
                                          i % 97, i % 89);
        text.append(line, static_cast<std::size_t>(n));
    }
    QFile file(QDir(dir).filePath("N1010009.DAT"));
    return file.open(QIODevice::WriteOnly) &&
           file.write(text.data(), static_cast<qint64>(text.size())) ==
               static_cast<qint64>(text.size());
}

/// Milliseconds of one key on the focused widget, repaint included.
double press(int key, Qt::KeyboardModifiers modifiers = Qt::NoModifier, const QString& text = {}) {
    QElapsedTimer clock;
    clock.start();
    QWidget* target = QApplication::focusWidget();
    QKeyEvent down(QEvent::KeyPress, key, modifiers, text);
    QApplication::sendEvent(target, &down);
    QKeyEvent up(QEvent::KeyRelease, key, modifiers, text);
    QApplication::sendEvent(QApplication::focusWidget(), &up);
    QApplication::processEvents();
    return static_cast<double>(clock.nsecsElapsed()) / 1e6;
}

void report(const char* what, double ms) {
    std::printf("%-46s %9.1f ms\n", what, ms);
    std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    const int count = argc > 1 ? std::max(100, std::atoi(argv[1])) : 1'000'000;
    QTemporaryDir dir;
    if (!dir.isValid() || !writeProgram(dir.path(), count)) return 1;
    QElapsedTimer clock;
    clock.start();
    mtc::hmi::PanelOptions options;
    options.programsDir = dir.path();
    QString error;
    auto session = mtc::hmi::createSession(options, error);
    if (!session) return 1;
    mtc::hmi::ScreenRegistry registry;
    mtc::screens::registerAllScreens(registry);
    mtc::hmi::PanelWindow window(session.get(), &registry);
    window.show();
    QApplication::processEvents();
    report("session start and panel (program parsed)", clock.restart());
    std::printf("resident %.0f MB, peak %.0f MB\n", rssMb(), peakRssMb());
    window.showScreen("programs");
    auto* list = window.screen(0, "programs")->findChild<QListView*>("programList");
    const auto* model = qobject_cast<const mtc::screens::ProgramDirectoryModel*>(list->model());
    list->setCurrentIndex(model->index(model->rowOf(9)));
    QApplication::processEvents();
    report("directory: listing of the program", clock.restart());
    press(Qt::Key_F6);  // Compiler active = Yes
    report("F2 Edit: editor shown", press(Qt::Key_F2));
    auto* edit = window.screen(0, "editor")->findChild<mtc::screens::NcCodeEdit*>("programEditor");
    std::printf("editor: %d lines, cursor line %d; resident %.0f MB, peak %.0f MB\n",
                edit->lineCount(), edit->cursorLine(), rssMb(), peakRssMb());
    report("Ctrl+End", press(Qt::Key_End, Qt::ControlModifier));
    report("Up", press(Qt::Key_Up));
    report("End", press(Qt::Key_End));
    report("typed character", press(Qt::Key_X, Qt::NoModifier, "x"));
    report("Backspace", press(Qt::Key_Backspace));
    report("typed character", press(Qt::Key_X, Qt::NoModifier, ";"));
    report("Ctrl+Home (window moves, edit spliced)", press(Qt::Key_Home, Qt::ControlModifier));
    report("Ctrl+S Save (whole text, write, parse)", press(Qt::Key_S, Qt::ControlModifier));
    std::printf("resident %.0f MB, peak %.0f MB\n", rssMb(), peakRssMb());
    report("F2 Compile", press(Qt::Key_F2));
    report("Ctrl+E error display", press(Qt::Key_E, Qt::ControlModifier));
    report("Enter: editor on the faulty line", press(Qt::Key_Return));
    std::printf("editor: cursor line %d (faulty definition at line %d)\n", edit->cursorLine(),
                10 + count / 10 * 9 + 1);
    std::printf("peak RSS %.0f MB\n", peakRssMb());
    return 0;
}
