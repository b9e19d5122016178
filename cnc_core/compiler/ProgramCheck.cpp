#include "cnc_core/compiler/ProgramCheck.h"

#include <set>
#include <string>
#include <utility>

#include "cnc_core/compiler/CompilerText.h"

namespace mtc::core {

DiagnosticList compilerDiagnostics(const std::vector<CompilerError>& errors) {
    DiagnosticList list;
    for (const CompilerError& e : errors) {
        Diagnostic d;
        d.severity = e.severity;
        d.code = e.code;
        d.where.program = e.program;
        d.where.block = e.generalNumber > 0 ? "A" + formatFourDigits(e.generalNumber) : e.block;
        d.where.line = e.sourceLine;
        d.message = e.message;
        d.details = e.details;
        list.add(std::move(d));
    }
    return list;
}

DiagnosticList checkProgram(const Program& program, CompilerOptions options,
                            const Compiler& compiler) {
    DiagnosticList found = program.diagnostics;
    options.compilerActive = true;
    if (!needsCompilation(program, options)) return found;
    std::set<std::pair<std::string, int>> parsed;
    for (const Diagnostic& d : program.diagnostics.items())
        parsed.insert({d.code, d.where.line});
    const CompileResult result = compiler.compile(program, options);
    const DiagnosticList messages = compilerDiagnostics(result.errors);
    for (const Diagnostic& d : messages.items())
        if (!parsed.count({d.code, d.where.line})) found.add(d);
    return found;
}

}  // namespace mtc::core
