#include "hmi/NcOptionsHolder.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

#include "cnc_core/compiler/Compiler.h"
#include "cnc_core/compiler/GlobalMacroFile.h"
#include "cnc_core/machine/ProcessControl.h"
#include "hmi/CellSession.h"
#include "hmi/UserCompilerTrust.h"

namespace mtc::hmi {

using mtc::core::MacroDefinition;

namespace {

/// Removes the .NCO and .ERR files beside the program file `name`.
void removeCompileFiles(const QString& directory, const std::string& name) {
    const QFileInfo source(QDir(directory).filePath(QString::fromStdString(name)));
    if (directory.isEmpty() || !source.exists()) return;
    for (const char* extension : {"NCO", "ERR"})
        QFile::remove(source.dir().filePath(source.completeBaseName() + "." + extension));
}

/// Whether `program` goes through the compiler with `macros` (keywords, a
/// use of one of the macros).
bool usesCompiler(const mtc::core::Program& program, const std::vector<MacroDefinition>& macros) {
    mtc::core::CompilerOptions options;
    options.compilerActive = true;
    options.globalMacros = macros;
    return mtc::core::needsCompilation(program, options);
}

}  // namespace

NcOptionsHolder::NcOptionsHolder(CellSession* session, QObject* parent)
    : QObject(parent), session_(session) {}

void NcOptionsHolder::load(const QString& directory) {
    directory_ = directory;
    problems_.clear();
    options_ = {};
    if (!directory.isEmpty()) {
        mtc::core::NcOptionsContents contents = mtc::core::readNcOptions(directory.toStdString());
        options_ = std::move(contents.options);
        problems_ = std::move(contents.problems);
    }
    session_->cell().setNcOptions(options_);
    emit optionsChanged();
}

QString NcOptionsHolder::runningStation() const {
    for (int slot = 0; slot < session_->processCount(); ++slot)
        if (session_->control(slot).programActive())
            return QString::fromStdString(session_->processConfig(slot).name);
    return {};
}

bool NcOptionsHolder::setCompilerActive(bool active, QString& error) {
    if (active == options_.compilerActive) return true;
    mtc::core::NcOptions changed = options_;
    changed.compilerActive = active;
    return commitSettings(changed, error);
}

bool NcOptionsHolder::setUserCompiler(int slot, const QString& command, QString& error) {
    const std::string text = command.trimmed().toStdString();
    if (slot < 1 || slot > mtc::core::kUserCompilerSlotCount) {
        error = tr("there is no user compiler %1").arg(slot);
        return false;
    }
    if (std::string problem = mtc::core::checkUserCompilerCommand(text); !problem.empty()) {
        error =
            tr("User compiler %1 not changed: %2").arg(slot).arg(QString::fromStdString(problem));
        return false;
    }
    if (text == mtc::core::userCompilerCommand(options_.userCompilers, slot)) {
        UserCompilerTrust::approve(directory_, slot, QString::fromStdString(text));
        return true;
    }
    mtc::core::NcOptions changed = options_;
    mtc::core::setUserCompilerCommand(changed.userCompilers, slot, text);
    if (!commitSettings(changed, error)) return false;
    UserCompilerTrust::approve(directory_, slot, QString::fromStdString(text));
    return true;
}

bool NcOptionsHolder::userCompilerApproved(int slot) const {
    return UserCompilerTrust::approved(
        directory_, slot,
        QString::fromStdString(mtc::core::userCompilerCommand(options_.userCompilers, slot)));
}

bool NcOptionsHolder::mayRunUserCompilers(QString& refusal) {
    for (int slot = 1; slot <= mtc::core::kUserCompilerSlotCount; ++slot) {
        if (userCompilerApproved(slot)) continue;
        const QString command =
            QString::fromStdString(mtc::core::userCompilerCommand(options_.userCompilers, slot));
        if (asker_ && asker_(slot, command, directory_)) {
            UserCompilerTrust::approve(directory_, slot, command);
            continue;
        }
        refusal = tr("User compiler %1 not run: its command '%2' came with the program "
                     "folder (%3) and was not approved")
                      .arg(slot)
                      .arg(command, mtc::core::kNcOptionsFileName);
        emit optionsChanged();
        return false;
    }
    emit optionsChanged();
    return true;
}

bool NcOptionsHolder::commitSettings(const mtc::core::NcOptions& changed, QString& error) {
    if (const QString station = runningStation(); !station.isEmpty()) {
        error = tr("NC options not changed: station %1 is running a program").arg(station);
        return false;
    }
    std::string reason;
    if (persistent() && !mtc::core::writeNcOptionsFile(directory_.toStdString(), changed, reason)) {
        error = tr("NC options not changed, %1 not written: %2")
                    .arg(mtc::core::kNcOptionsFileName, QString::fromStdString(reason));
        return false;
    }
    options_.compilerActive = changed.compilerActive;
    options_.userCompilers = changed.userCompilers;
    session_->cell().setNcOptions(options_);
    // Seed 001 ch. 11: changing the compiler settings clears all objects.
    invalidatePrograms([](const mtc::core::Program&) { return true; });
    emit optionsChanged();
    return true;
}

bool NcOptionsHolder::addGlobalMacro(const QString& entry, QString& error) {
    MacroDefinition macro;
    std::string problem;
    if (!mtc::core::parseGlobalMacroEntry(entry.trimmed().toStdString(), options_.globalMacros, {},
                                          macro, problem)) {
        error = tr("Macro refused: %1").arg(QString::fromStdString(problem));
        return false;
    }
    std::vector<MacroDefinition> macros = options_.globalMacros;
    macros.push_back(macro);
    return commitMacros(std::move(macros), error);
}

bool NcOptionsHolder::changeGlobalMacro(int index, const QString& entry, QString& error) {
    if (index < 0 || index >= static_cast<int>(options_.globalMacros.size())) {
        error = tr("no global macro selected");
        return false;
    }
    const std::size_t at = static_cast<std::size_t>(index);
    MacroDefinition macro;
    std::string problem;
    if (!mtc::core::parseGlobalMacroEntry(entry.trimmed().toStdString(), options_.globalMacros,
                                          options_.globalMacros[at].name, macro, problem)) {
        error = tr("Macro refused: %1").arg(QString::fromStdString(problem));
        return false;
    }
    std::vector<MacroDefinition> macros = options_.globalMacros;
    macros[at] = macro;
    return commitMacros(std::move(macros), error);
}

bool NcOptionsHolder::removeGlobalMacro(int index, QString& error) {
    if (index < 0 || index >= static_cast<int>(options_.globalMacros.size())) {
        error = tr("no global macro selected");
        return false;
    }
    std::vector<MacroDefinition> macros = options_.globalMacros;
    macros.erase(macros.begin() + index);
    return commitMacros(std::move(macros), error);
}

bool NcOptionsHolder::commitMacros(std::vector<MacroDefinition> macros, QString& error) {
    if (const QString station = runningStation(); !station.isEmpty()) {
        error = tr("Global macros not changed: station %1 is running a program").arg(station);
        return false;
    }
    std::string reason;
    if (persistent() &&
        !mtc::core::writeGlobalMacroFile(directory_.toStdString(), macros, reason)) {
        error = tr("Global macros not changed, %1 not written: %2")
                    .arg(mtc::core::kGlobalMacroFileName, QString::fromStdString(reason));
        return false;
    }
    const std::vector<MacroDefinition> before = std::move(options_.globalMacros);
    options_.globalMacros = std::move(macros);
    session_->cell().setNcOptions(options_);  // programs naming a changed macro parse again
    // Seed 001 ch. 9/11: a modified global macro clears the error and object
    // files of every program whose compile can depend on the macros.
    const bool chain = !options_.userCompilers.empty();
    invalidatePrograms([&](const mtc::core::Program& program) {
        return chain || usesCompiler(program, before) ||
               usesCompiler(program, options_.globalMacros);
    });
    emit optionsChanged();
    return true;
}

template <typename Predicate>
void NcOptionsHolder::invalidatePrograms(Predicate affected) {
    for (int slot = 0; slot < session_->processCount(); ++slot) {
        QList<int> numbers;
        for (const auto& program : session_->programs(slot)) {
            if (!affected(*program)) continue;
            removeCompileFiles(directory_, program->name);
            numbers << program->number;
        }
        if (!numbers.isEmpty()) emit programsInvalidated(slot, numbers);
    }
}

}  // namespace mtc::hmi
