#pragma once

#include <cstddef>
#include <map>
#include <utility>

#include "cnc_core/compiler/Compiler.h"

namespace mtc::core {

/// The N/C/E status bits of the program directory (seed 001, ch. 7 and 8):
/// remembers, per (process, program number), which source text was compiled
/// with which outcome. A program whose text changed is 'N' again; a program
/// that needs no compiler is ' '. "Compile only when needed" is
/// `mustCompile`: compiler active, keyword or global macro present, and not
/// yet compiled in this version.
class CompileStatusBook {
  public:
    /// ' ' / N / C / E for `program` stored as (process, number).
    CompileStatus status(int process, int number, const Program& program,
                         const CompilerOptions& options) const;
    /// True when the compiler must run for `program` (status N).
    bool mustCompile(int process, int number, const Program& program,
                     const CompilerOptions& options) const {
        return status(process, number, program, options) == CompileStatus::NotCompiled;
    }
    /// Notes the outcome of a compile of `program`.
    void record(int process, int number, const Program& program, const CompileResult& result);
    /// Forgets every outcome (a global macro or a compiler setting changed:
    /// seed 001 ch. 9/11 clear all objects and error files then).
    void invalidateAll() { entries_.clear(); }

  private:
    struct Entry {
        std::size_t sourceHash = 0;
        CompileStatus status = CompileStatus::NotCompiled;
    };
    std::map<std::pair<int, int>, Entry> entries_;
};

}  // namespace mtc::core
