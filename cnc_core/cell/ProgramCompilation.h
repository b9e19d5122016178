#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "cnc_core/compiler/Compiler.h"
#include "cnc_core/compiler/CompilerTypes.h"
#include "cnc_core/language/Diagnostic.h"
#include "cnc_core/program/ProgramStore.h"

namespace mtc::core {

class Cell;
namespace lookahead {
struct LookAheadAnalysis;
}

/// The NC programming side of one station (seed 001, ch. 7-11), without a
/// user interface: the compile status N/C/E of every program, compiling
/// (the user compilers and the INDRAMAT compiler), the .NCO/.ERR files
/// beside program files, the compiler messages of every program, and the
/// runtime program: what Start runs for a number (the source, or the
/// compiled object when the compiler is active). The Cell owns one per
/// station and makes it the station's program preparer, so the panel, the
/// CLI and the tests start programs through the same rules.
class ProgramCompilation {
  public:
    /// Compilation of station `slot` of `cell` (which must outlive it).
    ProgramCompilation(Cell& cell, int slot);
    ~ProgramCompilation();
    ProgramCompilation(const ProgramCompilation&) = delete;
    ProgramCompilation& operator=(const ProgramCompilation&) = delete;

    /// Status of program `number`: NotNeeded (no keyword, no global macro,
    /// no user compiler), N, C or E. Without a compile in this session it
    /// comes from the files: a current .NCO is C, a current .ERR with errors E.
    CompileStatus status(int number) const;
    /// The last compile of `number` in this session, nullptr when none.
    std::shared_ptr<const CompileResult> lastResult(int number) const;
    /// The compiled program: the last compile, or for status C from the
    /// files of an earlier session a compile in memory (no file written).
    std::shared_ptr<const CompileResult> runtimeResult(int number);
    /// The compile result the station runs for `number` (nullptr = source).
    std::shared_ptr<const CompileResult> running(int number) const;
    /// What the look-ahead pass planned in the last compile of `number`
    /// (nullptr before a compile).
    std::shared_ptr<const lookahead::LookAheadAnalysis> lookAhead(int number) const;
    /// The messages (errors and warnings) the error window shows for
    /// `number`: of the last compile, or of its .ERR file; empty when none.
    const std::vector<CompilerError>& messages(int number) const;

    /// Path of program `number`'s file with `extension` ("DAT", "NCO",
    /// "ERR"), "" when the program has no file (built-in programs).
    std::string filePath(int number, const std::string& extension) const;
    /// 1-based source line of block `block` ("N0030"), 0 when none.
    int sourceLineOf(int number, const std::string& block) const;

    /// Saves `text` as program `number`: the file atomically (when it has
    /// one), the parsed program in the store, status N (object and error
    /// file removed, seed 001 ch. 9/11). False with `error`: nothing changed.
    bool save(int number, const std::string& text, std::string& error);
    /// Compiles `number` with the cell's NC options: result kept, .NCO (or
    /// .ERR) written beside the program file, status C or E. False with
    /// `error` when the compiler did not run (not active, nothing to compile).
    bool compile(int number, std::string& error);
    /// Why the last compile() did not run the compiler (a screen words it
    /// in the operator's language; `error` is the English text).
    enum class Refusal { None, NoProgram, CompilerOff, NothingToCompile, UserCompilerBusy };
    Refusal lastRefusal() const { return lastRefusal_; }
    /// Makes what Start runs for `number` (and program 99, which holds the
    /// labels a program calls) ready (seed 001 ch. 10/11, C-013): with the
    /// compiler active, status N is compiled first, status C puts the object
    /// into the store; otherwise the source runs, and a compiler keyword in
    /// it refuses Start (ch. 7). Returns the alarm that refuses Start ("" =
    /// ready); the diagnostic behind it goes to `diagnostics`.
    std::string prepareRuntime(int number, DiagnosticList& diagnostics);
    /// The NC options made `numbers`' compile results stale: files gone,
    /// status N, the sources run again.
    void invalidate(const std::vector<int>& numbers);
    /// Reads the messages of the .ERR files of the programs with status E
    /// (seed 001 ch. 9: the error window shows the error file).
    void loadErrorFiles();

    // ---- user compilers run beside the station (D-019): they may take up
    // to kUserCompilerTimeoutSeconds, and the panel must not freeze. A
    // compile with user compilers (the Compile key, or Start of a program
    // with status N) starts in the background and returns at once; Start is
    // refused while it runs and goes when it is done.
    /// A background compile of `number` runs.
    bool compiling(int number) const { return background_.count(number) > 0; }
    bool anyCompiling() const { return !background_.empty(); }
    /// A user compiler chain runs on any station of the cell: another one
    /// waits (their files share the program directory, C-011).
    bool userCompilerBusy() const;
    /// Applies what the finished background compiles gave (files, status,
    /// messages; a result of a source saved or of NC options changed
    /// meanwhile is dropped). True when one finished. The panel calls it
    /// from its timer.
    bool takeFinished();
    /// Waits for every background compile and applies it (tests, the end
    /// of a run).
    void waitForCompiles();

    /// Decides whether the user compilers may run now (the panel asks the
    /// operator about commands that came with a program folder, D-010):
    /// false with the reason refuses the compile. Without one they may run.
    using UserCompilerApproval = std::function<bool(std::string& refusal)>;
    void setUserCompilerApproval(UserCompilerApproval approval) { approval_ = std::move(approval); }
    /// Called with a program number whenever its status, result or messages
    /// changed (0 = every program).
    using ChangeListener = std::function<void(int number)>;
    void setChangeListener(ChangeListener listener) { listener_ = std::move(listener); }

  private:
    struct Background;
    struct NeedsCompiling {
        std::weak_ptr<const Program> program;
        bool needed = false;
    };
    CompilerOptions compilerOptions(int number) const;
    bool needsCompiling(int number, const ProgramPtr& program) const;
    std::string prepareOne(int number, DiagnosticList& diagnostics);
    /// Compiles `number` now (INDRAMAT compiler only); the look-ahead plan of
    /// the run goes to lookAhead_[number].
    CompileResult compileNow(int number, const Program& program, const CompilerOptions& options);
    /// Starts the user compiler chain on `program` beside the caller;
    /// `keepFiles` false: a compile in memory of a program with status C.
    void startBackground(int number, const ProgramPtr& program, const CompilerOptions& options,
                         bool keepFiles);
    /// The operator refused the user compilers (D-010): the compile ends
    /// with USER_COMPILER_NOT_APPROVED; false when they may run.
    bool refusedUserCompilers(int number);
    /// Takes a finished compile: result, plan, messages, files and status.
    void apply(int number, std::shared_ptr<const CompileResult> result,
               std::shared_ptr<const lookahead::LookAheadAnalysis> plan, bool keepFiles);
    CompileStatus statusFromFiles(int number) const;
    void setStatus(int number, CompileStatus status);
    void setMessages(int number, std::vector<CompilerError> messages);
    void clearObjects(int number);
    void writeCompileFiles(int number, const CompileResult& result);
    void changed(int number) const;
    int process() const;

    Cell& cell_;
    int slot_;
    std::shared_ptr<lookahead::LookAheadAnalysis> capture_;  ///< filled by the pass
    Compiler compiler_;
    mutable std::map<int, NeedsCompiling> needsCompiling_;
    std::map<int, CompileStatus> status_;
    std::map<int, std::shared_ptr<const CompileResult>> results_;
    std::map<int, std::shared_ptr<const lookahead::LookAheadAnalysis>> lookAhead_;
    std::map<int, std::shared_ptr<const CompileResult>> running_;  ///< in the store
    std::map<int, std::vector<CompilerError>> messages_;
    std::map<int, std::shared_ptr<Background>> background_;
    std::uint64_t generation_ = 0;
    Refusal lastRefusal_ = Refusal::None;  ///< grows when the NC options invalidate compiles
    UserCompilerApproval approval_;
    ChangeListener listener_;
};

}  // namespace mtc::core
