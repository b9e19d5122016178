#include <QApplication>
#include <QBuffer>
#include <QTextStream>
#include <QTimer>
#include <algorithm>

#include "cnc_core/program/AtomicWrite.h"
#include "hmi/CellSession.h"
#include "hmi/NcOptionsHolder.h"
#include "hmi/PanelStartup.h"
#include "hmi/PanelWindow.h"
#include "hmi/ScreenRegistry.h"
#include "hmi/SimulationClock.h"
#include "screens/ScreenCatalog.h"

namespace {
int fail(const QString& message) {
    QTextStream(stderr) << "mtc200-panel: " << message << "\n";
    return 2;
}

/// --run: starts the selected program of the station and steps it to its
/// end at (nearly) unlimited simulation speed. Returns "" or the alarm.
QString runToEnd(mtc::hmi::CellSession& session, int process) {
    const int slot = std::max(0, session.slotOfProcess(std::max(0, process)));
    session.clock(slot).setSpeed(1e9);
    if (!session.pressKey(slot, mtc::core::ControlKey::Start))
        return QString::fromStdString(session.control(slot).alarm());
    for (int tick = 0; tick < 1000000 && session.control(slot).programActive(); ++tick)
        session.clock(slot).tick();
    session.clock(slot).setSpeed(1.0);
    return QString::fromStdString(session.control(slot).alarm());
}
}  // namespace

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    QApplication::setOrganizationName("MTC200Sim");
    QApplication::setApplicationName("mtc200-panel");

    mtc::hmi::PanelOptions options;
    QString error;
    bool exitNow = false;
    if (!mtc::hmi::parsePanelOptions(QApplication::arguments(), options, error, exitNow))
        return fail(error);
    if (exitNow) {
        QTextStream(stdout) << error;
        return 0;
    }
    auto session = mtc::hmi::createSession(options, error);
    if (!session) return fail(error);

    mtc::hmi::ScreenRegistry registry;
    mtc::screens::registerAllScreens(registry);
    mtc::hmi::PanelWindow window(session.get(), &registry);
    if (options.screenshot.isEmpty()) window.restoreSettings();
    // An automatic run has nobody to ask: a user compiler that came with the
    // program folder is not run (D-010), the error window says so.
    if (!options.screenshot.isEmpty() || options.run) session->ncOptions().setUserCompilerAsker({});
    if (!mtc::hmi::applyStartOptions(options, *session, window, error)) return fail(error);
    if (options.run) {
        const QString alarm = runToEnd(*session, options.process);
        if (!alarm.isEmpty()) QTextStream(stderr) << "mtc200-panel: --run: " << alarm << "\n";
    }
    window.show();

    if (!options.screenshot.isEmpty()) {
        int status = 0;
        QTimer::singleShot(0, &window, [&] {
            QByteArray png;
            QBuffer buffer(&png);
            buffer.open(QIODevice::WriteOnly);
            std::string reason;
            if (!window.grab().save(&buffer, "PNG") ||
                !mtc::core::writeFileAtomically(options.screenshot.toStdString(), png.toStdString(),
                                                reason)) {
                QTextStream(stderr) << "mtc200-panel: cannot write " << options.screenshot << ": "
                                    << QString::fromStdString(reason) << "\n";
                status = 2;
            }
            app.exit(status);
        });
        return app.exec();
    }
    return app.exec();
}
