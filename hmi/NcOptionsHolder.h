#pragma once

#include <QList>
#include <QObject>
#include <QString>
#include <functional>
#include <vector>

#include "cnc_core/compiler/NcOptions.h"

namespace mtc::hmi {

class CellSession;

/// The NC options of the cell (seed 001 ch. 4, 7, 8; decisions NO-001..):
/// one set for both stations. Every change is checked, written to the
/// program directory at once (atomically; built-in demo programs: memory
/// only) and taken only when written. A taken change clears the compile
/// files it makes stale on every station (seed 001 ch. 9, 11) and tells the
/// stations' program workspaces which programs to reset.
class NcOptionsHolder : public QObject {
    Q_OBJECT
  public:
    /// Options of `session`'s cell; presets until load() is called.
    explicit NcOptionsHolder(CellSession* session, QObject* parent = nullptr);

    const mtc::core::NcOptions& options() const { return options_; }
    bool compilerActive() const { return options_.compilerActive; }
    const mtc::core::UserCompilerSlots& userCompilers() const { return options_.userCompilers; }
    const std::vector<mtc::core::MacroDefinition>& globalMacros() const {
        return options_.globalMacros;
    }
    /// The lines of the files that load() refused.
    const std::vector<mtc::core::NcOptionsProblem>& loadProblems() const { return problems_; }
    /// True when the options are kept in files (a program directory is set).
    bool persistent() const { return !directory_.isEmpty(); }

    /// Reads the options of `directory` ("" = presets, kept in memory).
    void load(const QString& directory);

    /// True when user compiler `slot`'s command may run without asking: it
    /// was typed at this desk or approved before, or the folder is trusted
    /// (UserCompilerTrust, docs/DECISIONS.md D-010). An empty slot is true.
    bool userCompilerApproved(int slot) const;
    /// Asks the operator whether a command that came with the program folder
    /// may run: (slot, command, folder) -> yes. Without one, such commands
    /// are refused (automatic runs, screenshots).
    using UserCompilerAsker =
        std::function<bool(int slot, const QString& command, const QString& folder)>;
    void setUserCompilerAsker(UserCompilerAsker asker) { asker_ = std::move(asker); }
    /// Before the chain runs: every command that is not approved is shown to
    /// the operator (the asker); an approval is remembered, a refusal
    /// stops here. False with `refusal` (nothing may run) when the operator
    /// said no or nobody could be asked.
    bool mayRunUserCompilers(QString& refusal);

    /// Sets "Compiler active" (clears all objects, seed 001 ch. 11).
    bool setCompilerActive(bool active, QString& error);
    /// Sets the command of user compiler `slot` 1..4 ("" empties it); typed
    /// at this desk, it is approved for the folder.
    bool setUserCompiler(int slot, const QString& command, QString& error);
    /// Adds the operator's `DEFINE name AS instructions` entry.
    bool addGlobalMacro(const QString& entry, QString& error);
    /// Replaces global macro `index` by the operator's entry.
    bool changeGlobalMacro(int index, const QString& entry, QString& error);
    /// Deletes global macro `index`.
    bool removeGlobalMacro(int index, QString& error);

  signals:
    /// Something of the options changed (screens refresh).
    void optionsChanged();
    /// The compile results of these programs of station `slot` are stale:
    /// their .NCO/.ERR files are gone, their status is N again.
    void programsInvalidated(int slot, const QList<int>& numbers);

  private:
    /// Refuses changes while a station runs a program ("" = none runs).
    QString runningStation() const;
    /// Writes and takes `changed`; false with `error` when not written.
    bool commitSettings(const mtc::core::NcOptions& changed, QString& error);
    bool commitMacros(std::vector<mtc::core::MacroDefinition> macros, QString& error);
    /// Clears the compile files of the programs that `affected` selects on
    /// every station and announces them.
    template <typename Predicate>
    void invalidatePrograms(Predicate affected);

    CellSession* session_;
    QString directory_;
    mtc::core::NcOptions options_;
    std::vector<mtc::core::NcOptionsProblem> problems_;
    UserCompilerAsker asker_;
};

}  // namespace mtc::hmi
