// Restart target-path resolver (CLI-CONTRACT.md "Target path"): the first
// line of the input is the path, the rest holds programs 1, 99, 7 and 5 of
// process 0, separated by form feeds. Every other input resolves with the
// variables of an interpreter state holding extreme numbers (a program
// number in a variable). A result is either ok with its target in a stored
// program or a refusal with a code.
#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "../FuzzTargets.h"
#include "cnc_core/language/Parser.h"
#include "cnc_core/restart/TargetPath.h"

namespace mtc::fuzz {
namespace {

using namespace mtc::core;

/// The variables: @n holds kValues[n % count].
const InterpreterState& extremeState() {
    static const std::unique_ptr<InterpreterState> state = [] {
        const double kValues[] = {7,
                                  5,
                                  99,
                                  1,
                                  -1,
                                  1e308,
                                  -1e308,
                                  1e-300,
                                  2.5,
                                  4294967297.0,
                                  std::numeric_limits<double>::quiet_NaN(),
                                  std::numeric_limits<double>::infinity(),
                                  0,
                                  65537};
        auto s = std::make_unique<InterpreterState>();
        for (std::size_t i = 0; i < s->variables.values.size(); ++i)
            s->variables.values[i] = kValues[i % std::size(kValues)];
        return s;
    }();
    return *state;
}

}  // namespace

void fuzzTargetPath(std::string_view input) {
    const std::size_t lineEnd = std::min(input.find('\n'), input.size());
    const std::string_view path = input.substr(0, lineEnd);
    std::string_view rest = input.substr(std::min(lineEnd + 1, input.size()));
    ProgramStore store;
    for (int number : {1, 99, 7, 5}) {
        const std::size_t end = std::min(rest.find('\f'), rest.size());
        ParseOptions options;
        options.programNumber = number;
        auto program =
            std::make_shared<Program>(parseProgram(std::string(rest.substr(0, end)), options));
        program->number = number;
        store.put(0, number, program);
        rest = rest.substr(std::min(end + 1, rest.size()));
    }
    const InterpreterState* state = input.size() % 2 ? &extremeState() : nullptr;
    const TargetPathResult r = resolveTargetPath(path, store, 0, 1, state);
    require(r.ok == !r.diagnostics.hasErrors(), "ok means no error", input);
    for (const Diagnostic& d : r.diagnostics.items())
        require(!d.code.empty() && !d.message.empty(), "refusals say what", input);
    if (!r.ok) return;
    const ProgramPtr target = store.find(0, r.selection.target.program);
    require(target && r.selection.target.block < target->blocks.size(),
            "the target is a block of a stored program", input);
    require(r.selection.path.size() < kMaxSearchLevels, "at most 9 levels above the target", input);
    for (const BlockRef& step : r.selection.path) {
        const ProgramPtr program = store.find(0, step.program);
        require(program && step.block < program->blocks.size(),
                "every path step is a block of a stored program", input);
    }
}

}  // namespace mtc::fuzz
