#pragma once

#include <array>
#include <string>
#include <string_view>

#include "cnc_core/compiler/Compiler.h"

/// User-related compilers (seed 001, ch. 8): up to two external programs
/// before and two after the INDRAMAT compiler. See docs/decisions/compiler.md
/// (C-011) for the calling convention.
namespace mtc::core {

/// The compiler chain of the NC options: commands ("" = slot empty).
struct UserCompilerSlots {
    std::array<std::string, 2> before;  ///< user-related compilers 1 and 2
    std::array<std::string, 2> after;   ///< user-related compilers 3 and 4
    bool empty() const {
        return before[0].empty() && before[1].empty() && after[0].empty() && after[1].empty();
    }
};

/// Longest time a user compiler may run before it is stopped (an error).
inline constexpr double kUserCompilerTimeoutSeconds = 60.0;

/// Runs user compiler 1, 2 on the source text, the INDRAMAT compiler, then
/// user compiler 3, 4 on the object text. Each command is split into words
/// (splitCommandLine) and run without a shell (D-010) as `COMMAND...
/// INPUT OUTPUT ERRORS` with three file paths in `workDirectory`: it reads
/// INPUT, writes the changed program to OUTPUT (no OUTPUT: unchanged) and
/// its messages in the .ERR format to ERRORS; exit status 0 means compiled,
/// anything else (or more than kUserCompilerTimeoutSeconds) an error. The
/// chain stops at the first stage with an error (seed 001 ch. 9). Whether a
/// command may run at all is the caller's decision (the panel asks the
/// operator about commands that came with a program folder). Never throws.
CompileResult compileWithUserCompilers(const Compiler& compiler, std::string_view source,
                                       const CompilerOptions& options,
                                       const UserCompilerSlots& slots,
                                       const std::string& workDirectory);

}  // namespace mtc::core
