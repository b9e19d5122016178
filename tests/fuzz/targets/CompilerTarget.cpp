// Compiler: every standard pass on the input, once on the mill without
// global macros and once on the lathe with them. The result is consistent
// (status and errors agree, message limits of seed 001 ch. 9, the .ERR text
// reads back, the line map covers the object text) and the object program
// parses without errors.
#include <string>

#include "../FuzzTargets.h"
#include "DemoCell.h"
#include "cnc_core/compiler/Compiler.h"
#include "cnc_core/compiler/CompilerFiles.h"
#include "cnc_core/compiler/CompilerText.h"
#include "cnc_core/language/Parser.h"

namespace mtc::fuzz {
namespace {

using namespace mtc::core;

void checkResult(const CompileResult& r, std::string_view input) {
    require((r.status == CompileStatus::Error) == r.hasErrors(), "status says whether errors",
            input);
    int errors = 0;
    for (const CompilerError& e : r.errors) {
        require(!e.code.empty(), "every message has a code", input);
        require(e.message.size() <= kMaxBriefMessage, "brief message <= 52 characters", input);
        require(e.details.size() <= kMaxDetailLines, "at most 14 detail lines", input);
        for (const std::string& d : e.details)
            require(d.size() <= kMaxDetailLength, "detail lines <= 65 characters", input);
        errors += e.severity == Severity::Error;
    }
    require(errors <= 40, "the compile stops after 40 errors", input);
    std::string identification;
    require(
        parseErrorFile(formatErrorFile("id", r.errors), identification).size() == r.errors.size(),
        "the .ERR text reads back", input);
    if (r.status != CompileStatus::Compiled) return;
    std::size_t lines = 0;
    for (char c : r.objectText)
        lines += c == '\n';
    require(lines == r.lineMap.size(), "one line map entry per object line", input);
    require(lines <= kMaxObjectLines + 4, "object programs are bounded", input);
    const Program object = parseProgram(r.objectText);
    require(!object.diagnostics.hasErrors(), "the object program parses", input);
}

}  // namespace

void fuzzCompiler(std::string_view input) {
    const Compiler compiler;
    CompilerOptions options;
    options.compilerActive = true;
    options.programNumber = 1;
    options.process = demoCell().process(0);
    checkResult(compiler.compile(input, options), input);

    options.process = demoCell().process(1);
    options.globalMacros = {
        {"SLOW", "G1 F200"}, {"QUICK", "G0"}, {"ANPOS", "MTD(112,1,8,1)"}, {"COOL", "M8"}};
    checkResult(compiler.compile(input, options), input);
}

}  // namespace mtc::fuzz
