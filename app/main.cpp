#include <QApplication>
#include <QTextStream>
#include <QTimer>

#include "hmi/CellSession.h"
#include "hmi/PanelStartup.h"
#include "hmi/PanelWindow.h"
#include "hmi/ScreenRegistry.h"
#include "screens/ScreenCatalog.h"

namespace {
int fail(const QString& message) {
    QTextStream(stderr) << "mtc200-panel: " << message << "\n";
    return 2;
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
    if (!mtc::hmi::applyStartOptions(options, *session, window, error)) return fail(error);
    window.show();

    if (!options.screenshot.isEmpty()) {
        int status = 0;
        QTimer::singleShot(0, &window, [&] {
            if (!window.grab().save(options.screenshot, "PNG")) {
                QTextStream(stderr) << "mtc200-panel: cannot write " << options.screenshot << "\n";
                status = 2;
            }
            app.exit(status);
        });
        return app.exec();
    }
    return app.exec();
}
