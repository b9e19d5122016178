#pragma once

#include <QObject>
#include <QString>
#include <QTimer>
#include <cstdint>
#include <memory>

#include "cnc_core/cell/DiagnosticLog.h"
#include "cnc_core/cell/ProgramCompilation.h"
#include "cnc_core/compiler/CompilerTypes.h"
#include "hmi/ErrorLog.h"
#include "hmi/VelocityProfile.h"

namespace mtc::hmi {

class CellSession;
class NcOptionsHolder;

/// The panel's view of the NC programming side of one station (seed 001,
/// ch. 7-11). What the compiler does, the N/C/E status, the .NCO/.ERR files
/// and the runtime program live in the core (core::ProgramCompilation, the
/// cell's); this adds what a screen needs: Qt types, a signal when a
/// program changed, the operator's question before a user compiler from the
/// program folder runs, and the station's error log (compiler, runtime and
/// restart errors) the error window shows. The program directory, editor,
/// error window and runtime view share it.
class ProgramWorkspace : public QObject {
    Q_OBJECT
  public:
    /// Workspace of station `slot`; `session` must outlive it.
    ProgramWorkspace(CellSession* session, int slot, QObject* parent = nullptr);
    ~ProgramWorkspace() override;

    CellSession* session() const { return session_; }
    int slot() const { return slot_; }
    ErrorLog& errors() { return errors_; }

    /// NC option "Compiler active" of the cell (seed 001 ch. 7; preset No;
    /// CellSession::ncOptions()). Changing it clears every object file and
    /// compile result of both stations (ch. 11).
    bool compilerActive() const;
    /// Sets "Compiler active" in the cell's NC options; false with `error`
    /// when it was refused (a station runs, the file was not written).
    bool setCompilerActive(bool active, QString& error);
    /// As above, the refusal is dropped (the option stays as it was).
    void setCompilerActive(bool active);
    /// The cell's global macros of the NC options (valid in every program
    /// and in MDI, seed 001 ch. 4).
    const std::vector<mtc::core::MacroDefinition>& globalMacros() const;

    /// Status bit of program `number`: ' ' (no keyword), N, C or E.
    mtc::core::CompileStatus status(int number) const;
    /// The last compile of `number` in this session, nullptr when none.
    std::shared_ptr<const mtc::core::CompileResult> lastResult(int number) const;
    /// The compiled program for the runtime view (core::ProgramCompilation).
    std::shared_ptr<const mtc::core::CompileResult> runtimeResult(int number);
    /// The look-ahead velocity profile of the last compile of `number`
    /// (empty without LA_ON segments or before a compile).
    VelocityProfile velocityProfile(int number) const;

    /// Path of program `number`'s file with `extension` ("DAT", "NCO",
    /// "ERR"), or "" when the program has no file (built-in programs).
    QString filePath(int number, const QString& extension) const;

    /// Saves `text` as program `number` (core::ProgramCompilation::save).
    bool save(int number, const QString& text, QString& error);
    /// Compiles program `number` (core::ProgramCompilation::compile). With
    /// user compilers it runs in the background (compiling()); the panel
    /// stays usable and programChanged() tells when it is done (D-019).
    bool compile(int number, QString& error);
    /// A background compile of `number` (user compilers) runs.
    bool compiling(int number) const;
    /// The compile result the station runs for `number` (nullptr = source).
    std::shared_ptr<const mtc::core::CompileResult> running(int number) const;

    /// 1-based source line of block `block` ("N0030") of program `number`,
    /// 0 when it has no such block.
    int sourceLineOf(int number, const QString& block) const;

    /// Asks the editor to show `number` at source line `line` (error window
    /// Enter, program directory): the editor takes it when it is activated.
    void requestEdit(int number, int line = 0);
    int editProgram() const { return editProgram_; }
    int editLine() const { return editLine_; }
    /// The editor took the request (line 0 from now on).
    void takeEditLine() { editLine_ = 0; }

  signals:
    /// Status, result or files of `number` changed (number 0 = all programs).
    void programChanged(int number);

  private:
    mtc::core::ProgramCompilation& compilation() const;
    /// Puts the program loader's problems (CellSession::loadProblems) into
    /// the error window.
    void reportLoadProblems();
    /// The lines of the NC options files (GLOBAL_MACROS.MAC, NC_OPTIONS.CFG)
    /// that were refused go to the error window (GM-005, NO-002).
    void reportOptionProblems();
    /// The compilation changed `number` (0 = all): its messages go to the
    /// error window, the screens hear of it.
    void compilationChanged(int number);
    void showCompilerMessages(int number);
    void watchRuntime();
    void mapToSource(ErrorEntry& entry) const;

    CellSession* session_;
    int slot_;
    ErrorLog errors_;
    QTimer backgroundPoll_;             ///< takes the results of background compiles
    NcOptionsHolder* options_;          ///< the cell's NC options (owned by the session)
    std::uint64_t seenDiagnostic_ = 0;  ///< serial of the station log read last
    int editProgram_ = 0;
    int editLine_ = 0;
};

/// The error-window entry of a compiler error.
ErrorEntry entryFromCompilerError(const mtc::core::CompilerError& error);
/// The error-window origin of a station diagnostic's source.
ErrorOrigin originOf(mtc::core::DiagnosticSource source);

}  // namespace mtc::hmi
