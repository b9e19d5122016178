#pragma once

#include <QMap>
#include <QObject>
#include <QString>
#include <cstdint>
#include <memory>

#include "cnc_core/compiler/Compiler.h"
#include "cnc_core/cell/DiagnosticLog.h"
#include "cnc_core/compiler/CompilerTypes.h"
#include "hmi/ErrorLog.h"
#include "hmi/VelocityProfile.h"

namespace mtc::core::lookahead {
struct LookAheadAnalysis;
}

namespace mtc::hmi {

class CellSession;
class NcOptionsHolder;

/// The NC programming side of one station (seed 001, ch. 7-11): saving
/// edited programs, the NC options of the compiler, compiling, the N/C/E
/// status bit of every program, the .NCO/.ERR files beside program files,
/// and the station's error log (compiler, runtime and restart errors). The
/// program directory, editor, error window and runtime view share it.
class ProgramWorkspace : public QObject {
    Q_OBJECT
  public:
    /// Workspace of station `slot`; `session` must outlive it. It installs
    /// itself as the station's program preparer (prepareRuntime()).
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
    /// The compiler options for program `number` (the cell's process, macros).
    mtc::core::CompilerOptions compilerOptions(int number) const;
    /// The cell's global macros of the NC options (valid in every program
    /// and in MDI, seed 001 ch. 4).
    const std::vector<mtc::core::MacroDefinition>& globalMacros() const;

    /// Status bit of program `number`: ' ' (no keyword), N, C or E.
    mtc::core::CompileStatus status(int number) const;
    /// The last compile of `number` in this session, nullptr when none.
    std::shared_ptr<const mtc::core::CompileResult> lastResult(int number) const;
    /// The compiled program for the runtime view: the last compile, or for a
    /// program whose status is C from its files (an .NCO of an earlier
    /// session) a compile in memory (nothing written, the log unchanged).
    std::shared_ptr<const mtc::core::CompileResult> runtimeResult(int number);
    /// The look-ahead velocity profile of the last compile of `number`
    /// (empty without LA_ON segments or before a compile).
    VelocityProfile velocityProfile(int number) const { return profiles_.value(number); }

    /// Path of program `number`'s file with `extension` ("DAT", "NCO",
    /// "ERR"), or "" when the program has no file (built-in programs).
    QString filePath(int number, const QString& extension) const;

    /// Saves `text` as program `number`: the file atomically (when the
    /// program has one), the parsed program in the cell session, the status
    /// reset to N (object and error file cleared, seed 001 ch. 9/11).
    /// False with `error` when nothing was changed.
    bool save(int number, const QString& text, QString& error);

    /// Compiles program `number` with the station's options: result kept,
    /// .NCO (or .ERR) written beside the program file, status C or E, the
    /// compiler errors in the error log. False with `error` when the
    /// compiler did not run (not active, no keyword, no program).
    bool compile(int number, QString& error);

    /// Makes the program the station runs for `number` (and its program 99)
    /// the runtime program (seed 001 ch. 10/11, C-013): with the compiler
    /// active and compiler keywords, status N is compiled first, status C
    /// puts the compiled object into the store; otherwise the source runs.
    /// Returns the alarm that refuses Start (status E), "" when ready; the
    /// diagnostic behind a refusal (a compiler keyword with the compiler
    /// off) goes to `diagnostics`.
    std::string prepareRuntime(int number, mtc::core::DiagnosticList& diagnostics);
    /// The compile result the station runs for `number` (nullptr = source).
    std::shared_ptr<const mtc::core::CompileResult> running(int number) const {
        return running_.value(number);
    }

    /// 1-based source line of block `block` ("N0030") of program `number`,
    /// 0 when it has no such block.
    int sourceLineOf(int number, const QString& block) const;
    /// Puts the messages of the .ERR files of the station's programs with
    /// status E into the error log (seed 001 ch. 9: the window shows the
    /// error file). Called once when the workspace is created.
    void loadErrorFiles();

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
    /// The lines of the NC options files (GLOBAL_MACROS.MAC, NC_OPTIONS.CFG)
    /// that were refused go to the error window (GM-005, NO-002).
    /// Puts the program loader's problems (CellSession::loadProblems) into
    /// the error window.
    void reportLoadProblems();
    void reportOptionProblems();
    /// The NC options made the compile results of `numbers` stale: their
    /// files are gone (NcOptionsHolder), status N, the sources run again.
    void invalidate(const QList<int>& numbers);
    /// Runs the compiler chain (user compilers 1, 2, INDRAMAT, 3, 4).
    mtc::core::CompileResult runCompilers(const mtc::core::Program& program,
                                          const mtc::core::CompilerOptions& options) const;
    /// Compiler keywords or a global macro in `program` (cached per version).
    bool needsCompiling(int number, const mtc::core::ProgramPtr& program) const;
    void watchRuntime();
    std::string prepareOne(int number, mtc::core::DiagnosticList& diagnostics);
    void mapToSource(ErrorEntry& entry) const;
    void setStatus(int number, mtc::core::CompileStatus status);
    void clearObjects(int number);
    void writeCompileFiles(int number, const mtc::core::CompileResult& result);
    /// The messages of a compile of `number` (errors and warnings) replace
    /// its compiler entries in the error window.
    void showCompilerMessages(int number, const mtc::core::CompileResult& result);
    mtc::core::CompileStatus statusFromFiles(int number) const;

    CellSession* session_;
    int slot_;
    ErrorLog errors_;
    std::shared_ptr<mtc::core::lookahead::LookAheadAnalysis> lookAhead_;  ///< filled by the pass
    mtc::core::Compiler compiler_;
    NcOptionsHolder* options_;  ///< the cell's NC options (owned by the session)
    struct NeedsCompiling {
        std::weak_ptr<const mtc::core::Program> program;
        bool needed = false;
    };
    mutable QMap<int, NeedsCompiling> needsCompiling_;
    QMap<int, mtc::core::CompileStatus> status_;
    QMap<int, std::shared_ptr<const mtc::core::CompileResult>> results_;
    QMap<int, VelocityProfile> profiles_;
    QMap<int, std::shared_ptr<const mtc::core::CompileResult>> running_;  ///< in the store
    std::uint64_t seenDiagnostic_ = 0;  ///< serial of the station log read last
    int editProgram_ = 0;
    int editLine_ = 0;
};

/// The error-window entry of a compiler error.
ErrorEntry entryFromCompilerError(const mtc::core::CompilerError& error);
/// The error-window origin of a station diagnostic's source.
ErrorOrigin originOf(mtc::core::DiagnosticSource source);

}  // namespace mtc::hmi
