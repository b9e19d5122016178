#include "hmi/PanelStartup.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTextStream>
#include <clocale>
#include <optional>

#include "cnc_core/machine/MachineConfigFile.h"
#include "cnc_core/machine_data/MachineDataLocation.h"
#include "cnc_core/program/DatFileName.h"
#include "cnc_core/program/ProgramLoader.h"
#include "hmi/CellSession.h"
#include "hmi/PanelWindow.h"
#include "resources/EmbeddedResources.h"

namespace mtc::hmi {

namespace {

/// The start-up messages' texts, context "PanelStartup" of the catalogues.
struct Text {
    Q_DECLARE_TR_FUNCTIONS(PanelStartup)
};

bool readFile(const QString& path, QString& text, QString& error) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        error = Text::tr("cannot read %1: %2").arg(path, file.errorString());
        return false;
    }
    text = QString::fromUtf8(file.readAll());
    return true;
}

/// Number for a program file given with --program: its NuxxYzzz number, or
/// for a loose file the lowest number 1..98 the station does not use yet.
int numberForProgramFile(const CellSession& session, int slot, const QString& path) {
    if (auto name = mtc::core::parseDatFileName(path.toStdString())) return name->number;
    for (int number = 1; number < 99; ++number)
        if (!session.program(slot, number)) return number;
    return 0;
}

void reportLoaderProblems(const mtc::core::DiagnosticList& diagnostics) {
    for (const auto& d : diagnostics.items())
        QTextStream(stderr) << "mtc200-panel: " << QString::fromStdString(formatDiagnostic(d))
                            << "\n";
}

/// Loads the machine data file the options name (or the default one);
/// what went wrong with it is printed and kept for the machine data screen.
void openMachineData(const PanelOptions& options, CellSession& session) {
    QString path = options.dataFile == "-" ? QString() : options.dataFile;
    if (options.dataDefault) {
        const std::string fallback = mtc::core::defaultMachineDataPath(session.config().name);
        std::string error;
        if (!fallback.empty() && mtc::core::makeParentDirectories(fallback, error))
            path = QString::fromStdString(fallback);
        else if (!fallback.empty())
            QTextStream(stderr) << "mtc200-panel: " << QString::fromStdString(error) << "; "
                                << Text::tr("machine data is not kept") << "\n";
    }
    for (const QString& message : session.openMachineDataFile(path))
        QTextStream(stderr) << "mtc200-panel: " << message << "\n";
}

/// The machine configuration of the options (--machine FILE or the built-in
/// cell), read by the core's reader like every CLI command reads it; the
/// errors (at most kShownErrors of them) in `error`.
std::optional<mtc::core::MachineConfig> loadConfiguration(const PanelOptions& options,
                                                          QString& error) {
    constexpr int kShownErrors = 20;
    mtc::core::MachineConfigReadResult result;
    if (options.machineFile.isEmpty()) {
        mtc::core::MachineConfigReadOptions builtIn;
        builtIn.fileName = "built-in demo cell";
        builtIn.requireEndMarker = true;
        result = mtc::core::readMachineConfig(mtc::resources::find(mtc::resources::kDemoCellName),
                                              builtIn);
    } else {
        result = mtc::core::readMachineConfigFile(options.machineFile.toStdString());
    }
    if (result.ok()) return std::move(result.config);
    QStringList lines;
    for (const auto& d : result.diagnostics.items()) {
        if (d.severity != mtc::core::Severity::Error) continue;
        if (lines.size() == kShownErrors) {
            lines << "...";
            break;
        }
        lines << QString::fromStdString(formatDiagnostic(d));
    }
    error = Text::tr("the machine configuration is refused:") + "\n" + lines.join("\n");
    return std::nullopt;
}

}  // namespace

void useCNumberFormat() {
    std::setlocale(LC_NUMERIC, "C");
}

std::unique_ptr<CellSession> createSession(const PanelOptions& options, QString& error) {
    useCNumberFormat();
    std::optional<mtc::core::MachineConfig> config = loadConfiguration(options, error);
    if (!config) return nullptr;
    auto session = std::make_unique<CellSession>(std::move(*config));
    mtc::core::ProgramLoader loader(session->mutableStore());
    if (options.programsDir.isEmpty()) {
        loader.loadTexts(mtc::resources::demoPrograms());
    } else {
        const QFileInfo directory(options.programsDir);
        if (!directory.isDir()) {
            error = QString("--programs %1: %2")
                        .arg(options.programsDir,
                             directory.exists() ? Text::tr("is a file, not a program directory")
                                                : Text::tr("does not exist"));
            return nullptr;
        }
        // First the NC options: the programs are parsed knowing the global
        // macro names, as the CLI parses them.
        session->setProgramDirectory(options.programsDir);
        loader.setMacroNames(session->cell().macroNames());
        loader.loadDirectory(options.programsDir.toStdString());
    }
    reportLoaderProblems(loader.diagnostics());
    session->setLoadProblems(loader.diagnostics());  // also in the error windows
    openMachineData(options, *session);
    return session;
}

bool applyStartOptions(const PanelOptions& options, CellSession& session, PanelWindow& window,
                       QString& error) {
    if (options.process >= 0) {
        const int slot = session.slotOfProcess(options.process);
        if (slot < 0) {
            error = Text::tr("the cell has no process %1").arg(options.process);
            return false;
        }
        window.showStation(slot);
    }
    // Every station starts on its base screen (docs/DECISIONS.md D-014);
    // --screen shows another one on the station of --process.
    window.showScreenOnEveryStation("position");
    const int slot = window.currentStation();
    if (!options.program.isEmpty()) {
        bool isNumber = false;
        int number = options.program.toInt(&isNumber);
        if (!isNumber) {
            QString text;
            if (!readFile(options.program, text, error)) return false;
            number = numberForProgramFile(session, slot, options.program);
            if (number == 0) {
                error = Text::tr("no free program number for %1").arg(options.program);
                return false;
            }
            session.addProgram(slot, number, QFileInfo(options.program).fileName().toStdString(),
                               text.toStdString());
        } else if (!session.program(slot, number)) {
            error = Text::tr("station %1 has no program %2").arg(slot).arg(number);
            return false;
        }
        session.selectProgram(slot, number);
    }
    if (!options.screen.isEmpty() && !window.showScreen(options.screen)) {
        error = Text::tr("unknown screen '%1'").arg(options.screen);
        return false;
    }
    return true;
}

}  // namespace mtc::hmi
