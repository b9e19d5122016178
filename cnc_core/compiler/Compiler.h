#pragma once

#include <string>
#include <string_view>

#include "cnc_core/compiler/CompilerPass.h"
#include "cnc_core/compiler/CompilerTypes.h"
#include "cnc_core/language/Program.h"

/// The INDRAMAT NC compiler (seed 001): source program (.DAT) -> object
/// program (.NCO) with enhanced block numbers N0053:0001, or a list of
/// errors for the .ERR file and the error window. Plain C++, no file access
/// (files: CompilerFiles.h).
///
/// Use:
///   Compiler compiler;                       // with the standard passes
///   CompileResult r = compiler.compile(sourceText, options);
///   if (r.status == CompileStatus::Compiled) write r.objectText (.NCO)
///   else write formatErrorFile(identification, r.errors) (.ERR)
namespace mtc::core {

class Compiler {
  public:
    /// A compiler with the standard passes (standardCompilerPasses()).
    Compiler();
    /// A compiler with exactly `passes` (tests, user configurations).
    explicit Compiler(CompilerPassList passes);

    /// Adds a pass; passes run in ascending order() (stable for equal order).
    void addPass(std::shared_ptr<const CompilerPass> pass);
    const CompilerPassList& passes() const { return passes_; }

    /// Compiles NC source text (a .DAT file or a loose file of blocks).
    /// Never throws; every problem is a CompilerError.
    CompileResult compile(std::string_view source, const CompilerOptions& options) const;
    /// Compiles a parsed program (e.g. from the ProgramStore); uses its
    /// `source`, so the result is the same as compiling that text.
    CompileResult compile(const Program& program, const CompilerOptions& options) const;

  private:
    CompilerPassList passes_;
};

/// The passes of a standard compiler: macros, modal function, chamfers and
/// roundings, plus those of the look-ahead and contour modules.
CompilerPassList standardCompilerPasses();

/// True when `program` must go through the compiler (seed 001, ch. 8): the
/// compiler is active and the program uses a compiler keyword or a global
/// macro name. (Whether it changed since the last compile is
/// CompileStatusBook's business.)
bool needsCompilation(const Program& program, const CompilerOptions& options);

}  // namespace mtc::core
