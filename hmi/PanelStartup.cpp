#include "hmi/PanelStartup.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>

#include "cnc_core/machine/MachineConfigReader.h"
#include "hmi/CellSession.h"
#include "hmi/PanelWindow.h"
#include "resources/EmbeddedResources.h"

namespace mtc::hmi {

namespace {

/// Seed file naming NuxxYzzz.DAT: y = process, zzz = program number.
bool programFileName(const QString& fileName, int& process, int& number) {
    static const QRegularExpression pattern("^N\\d{3}(\\d)(\\d{3})\\.DAT$",
                                            QRegularExpression::CaseInsensitiveOption);
    auto match = pattern.match(fileName);
    if (!match.hasMatch()) return false;
    process = match.captured(1).toInt();
    number = match.captured(2).toInt();
    return true;
}

int slotOfProcess(const CellSession& session, int process) {
    for (int slot = 0; slot < session.processCount(); ++slot)
        if (session.processConfig(slot).index == process) return slot;
    return -1;
}

void addProgramText(CellSession& session, const QString& fileName, const QString& text) {
    int process = 0, number = 0;
    if (!programFileName(fileName, process, number)) return;
    const int slot = slotOfProcess(session, process);
    if (slot >= 0) session.addProgram(slot, {number, fileName, text});
}

bool readFile(const QString& path, QString& text, QString& error) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        error = QString("cannot read %1: %2").arg(path, file.errorString());
        return false;
    }
    text = QString::fromUtf8(file.readAll());
    return true;
}

}  // namespace

std::unique_ptr<CellSession> createSession(const PanelOptions& options, QString& error) {
    QString configText;
    if (options.machineFile.isEmpty()) {
        configText = QString::fromUtf8(
            mtc::resources::find(mtc::resources::kDemoCellName).data(),
            static_cast<int>(mtc::resources::find(mtc::resources::kDemoCellName).size()));
    } else if (!readFile(options.machineFile, configText, error)) {
        return nullptr;
    }
    auto result = mtc::core::readMachineConfig(configText.toStdString());
    if (!result.ok()) {
        const auto& first = result.diagnostics.items().front();
        error = QString("machine configuration %1 line %2: %3")
                    .arg(options.machineFile.isEmpty() ? "(built-in)" : options.machineFile)
                    .arg(first.where.line)
                    .arg(QString::fromStdString(first.message));
        return nullptr;
    }
    auto session = std::make_unique<CellSession>(std::move(result.config));
    if (options.programsDir.isEmpty()) {
        for (const auto& name : mtc::resources::list("programs/")) {
            auto data = mtc::resources::find(name);
            addProgramText(*session, QFileInfo(QString::fromStdString(name)).fileName(),
                           QString::fromUtf8(data.data(), static_cast<int>(data.size())));
        }
    } else {
        QDir dir(options.programsDir);
        if (!dir.exists()) {
            error = "program directory does not exist: " + options.programsDir;
            return nullptr;
        }
        for (const QString& name : dir.entryList(QDir::Files, QDir::Name)) {
            QString text;
            if (readFile(dir.filePath(name), text, error)) addProgramText(*session, name, text);
        }
        error.clear();
    }
    return session;
}

bool applyStartOptions(const PanelOptions& options, CellSession& session, PanelWindow& window,
                       QString& error) {
    if (options.process >= 0) {
        const int slot = slotOfProcess(session, options.process);
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
            number = 1;
            int process = 0;
            if (!programFileName(QFileInfo(options.program).fileName(), process, number))
                number = 1;
            session.addProgram(slot, {number, QFileInfo(options.program).fileName(), text});
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
