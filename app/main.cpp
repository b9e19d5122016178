#include <QApplication>
#include <QBuffer>
#include <QTextStream>
#include <QTimer>
#include <algorithm>

#include "cnc_core/program/AtomicWrite.h"
#include "hmi/CellSession.h"
#include "hmi/NcOptionsHolder.h"
#include "hmi/PanelLanguage.h"
#include "hmi/PanelStartup.h"
#include "hmi/PanelWindow.h"
#include "hmi/ScreenRegistry.h"
#include "screens/ScreenCatalog.h"

namespace {
/// The panel's language (--lang, the desk's setting or its locale; D-018)
/// before any text is made: the option texts and errors are translated too.
bool useLanguage(QString& error) {
    const QString option = mtc::hmi::languageArgument(QCoreApplication::arguments());
    return mtc::hmi::installPanelTranslation(mtc::hmi::panelLanguageFor(option), error);
}

int fail(const QString& message) {
    QTextStream(stderr) << "mtc200-panel: " << message << "\n";
    return 2;
}

/// --run: starts the selected program of the station and steps it to its
/// end at (nearly) unlimited simulation speed. Returns "" or the alarm.
QString runToEnd(mtc::hmi::CellSession& session, int process) {
    const int slot = std::max(0, session.slotOfProcess(std::max(0, process)));
    mtc::core::Station& station = session.station(slot);
    if (!session.pressKey(slot, mtc::core::ControlKey::Start))
        return QString::fromStdString(station.control().alarm());
    // As fast as possible, as the CLI runs; bounded like the CLI's --max-blocks.
    while (station.control().programActive() && !station.control().programHeld() &&
           station.runBlocks() < mtc::core::kDefaultBlockBudget)
        station.advance(3600.0);
    session.advance(0.0);  // the screens learn what changed
    // Held at M00 / single block: say so (a prompt, not an alarm).
    const std::string& alarm = station.control().alarm();
    return QString::fromStdString(alarm.empty() ? station.control().prompt() : alarm);
}
}  // namespace

namespace {
void nameTheApplication() {
    QCoreApplication::setOrganizationName("MTC200Sim");
    QCoreApplication::setApplicationName("mtc200-panel");
    QCoreApplication::setApplicationVersion(MTC_PANEL_VERSION);
}

/// --help and --version need no display: answered before QApplication
/// connects to one (a desk script or a package test without X).
int answerHelp(int argc, char** argv) {
    QCoreApplication core(argc, argv);
    nameTheApplication();
    mtc::hmi::PanelOptions options;
    QString text;
    bool exitNow = false;
    if (!useLanguage(text)) return fail(text);
    if (!mtc::hmi::parsePanelOptions(QCoreApplication::arguments(), options, text, exitNow))
        return fail(text);
    QTextStream(stdout) << text;
    return 0;
}
}  // namespace

int main(int argc, char** argv) {
    if (mtc::hmi::onlyAsksForHelp(argc, argv)) return answerHelp(argc, argv);
    // High-dpi screens: the panel scales as a whole (fractional factors too,
    // e.g. 1.5 at 144 dpi) instead of only its fonts growing (issue 20 §3).
    QApplication::setAttribute(Qt::AA_EnableHighDpiScaling);
    QApplication::setHighDpiScaleFactorRoundingPolicy(
        Qt::HighDpiScaleFactorRoundingPolicy::PassThrough);
    QApplication app(argc, argv);
    nameTheApplication();
    mtc::hmi::useCNumberFormat();  // files and NC text keep '.' (D-013)

    mtc::hmi::PanelOptions options;
    QString error;
    bool exitNow = false;
    if (!useLanguage(error)) return fail(error);
    if (!mtc::hmi::parsePanelOptions(QApplication::arguments(), options, error, exitNow))
        return fail(error);
    if (exitNow) {
        QTextStream(stdout) << error;
        return 0;
    }
    auto session = mtc::hmi::createSession(options, error);
    if (!session) return fail(error);

    session->setSpeed(options.speed);
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
                QTextStream(stderr)
                    << "mtc200-panel: "
                    << QCoreApplication::translate("PanelStartup", "cannot write %1: %2")
                           .arg(options.screenshot, QString::fromStdString(reason))
                    << "\n";
                status = 2;
            }
            app.exit(status);
        });
        return app.exec();
    }
    return app.exec();
}
