#pragma once

#include <vector>

#include "cnc_core/compiler/Compiler.h"
#include "cnc_core/language/Diagnostic.h"

/// One rule for "is this program good?" shared by `mtc200-cli check` and
/// `compile` (issue 15 §4): a program that needs the NC compiler is checked
/// by compiling it, so check finds an error exactly when compile does.
namespace mtc::core {

/// The compiler's messages as diagnostics: program, block ("N0053",
/// "N0053:0001", "A0001" for a general error), source line, code, message.
DiagnosticList compilerDiagnostics(const std::vector<CompilerError>& errors);

/// What a check of `program` reports: its parse diagnostics and, when it
/// uses a compiler keyword or a global macro of `options`, every message of
/// compiling it (GNE, look-ahead, CF/RD, macro errors, syntax errors of the
/// object program and warnings) that the parse has not reported already
/// (same code at the same line). `options.compilerActive` is ignored: a
/// check asks what the compiler would say.
DiagnosticList checkProgram(const Program& program, CompilerOptions options,
                            const Compiler& compiler = Compiler());

}  // namespace mtc::core
