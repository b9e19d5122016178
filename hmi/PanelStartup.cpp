#include "hmi/PanelStartup.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTextStream>

#include "cnc_core/machine/MachineConfigReader.h"
#include "cnc_core/machine_data/MachineDataLocation.h"
#include "cnc_core/program/DatFileName.h"
#include "cnc_core/program/ProgramLoader.h"
#include "hmi/CellSession.h"
#include "hmi/PanelWindow.h"
#include "resources/EmbeddedResources.h"

namespace mtc::hmi {

namespace {

bool readFile(const QString& path, QString& text, QString& error) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        error = QString("cannot read %1: %2").arg(path, file.errorString());
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
            QTextStream(stderr) << "mtc200-panel: " << QString::fromStdString(error)
                                << "; machine data is not kept\n";
    }
    for (const QString& message : session.openMachineDataFile(path))
        QTextStream(stderr) << "mtc200-panel: " << message << "\n";
}

}  // namespace

std::unique_ptr<CellSession> createSession(const PanelOptions& options, QString& error) {
    std::string configText(mtc::resources::find(mtc::resources::kDemoCellName));
    if (!options.machineFile.isEmpty()) {
        QString fileText;
        if (!readFile(options.machineFile, fileText, error)) return nullptr;
        configText = fileText.toStdString();
    }
    auto result = mtc::core::readMachineConfig(configText);
    if (!result.ok()) {
        const auto& first = result.diagnostics.items().front();
        error = QString("machine configuration %1 line %2: %3")
                    .arg(options.machineFile.isEmpty() ? "(built-in)" : options.machineFile)
                    .arg(first.where.line)
                    .arg(QString::fromStdString(first.message));
        return nullptr;
    }
    auto session = std::make_unique<CellSession>(std::move(result.config));
    mtc::core::ProgramLoader loader(session->mutableStore());
    if (options.programsDir.isEmpty()) {
        loader.loadTexts(mtc::resources::demoPrograms());
    } else {
        if (!QDir(options.programsDir).exists()) {
            error = "program directory does not exist: " + options.programsDir;
            return nullptr;
        }
        loader.loadDirectory(options.programsDir.toStdString());
        session->setProgramDirectory(options.programsDir);
    }
    reportLoaderProblems(loader.diagnostics());
    openMachineData(options, *session);
    return session;
}

bool applyStartOptions(const PanelOptions& options, CellSession& session, PanelWindow& window,
                       QString& error) {
    if (options.process >= 0) {
        const int slot = session.slotOfProcess(options.process);
        if (slot < 0) {
            error = QString("the cell has no process %1").arg(options.process);
            return false;
        }
        window.showStation(slot);
    }
    const int slot = window.currentStation();
    if (!options.program.isEmpty()) {
        bool isNumber = false;
        int number = options.program.toInt(&isNumber);
        if (!isNumber) {
            QString text;
            if (!readFile(options.program, text, error)) return false;
            number = numberForProgramFile(session, slot, options.program);
            if (number == 0) {
                error = "no free program number for " + options.program;
                return false;
            }
            session.addProgram(slot, number, QFileInfo(options.program).fileName().toStdString(),
                               text.toStdString());
        } else if (!session.program(slot, number)) {
            error = QString("station %1 has no program %2").arg(slot).arg(number);
            return false;
        }
        session.selectProgram(slot, number);
    }
    if (!options.screen.isEmpty() && !window.showScreen(options.screen)) {
        error = "unknown screen '" + options.screen + "'";
        return false;
    }
    return true;
}

}  // namespace mtc::hmi
