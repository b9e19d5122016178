#include "cnc_core/toolpath/ToolpathRun.h"

#include <algorithm>

namespace mtc::core {

namespace {
constexpr std::uint64_t kChunk = 65536;       ///< blocks per interpreter call
constexpr std::size_t kMaxDiagnostics = 100;  ///< kept of a run (the first ones)

/// Keeps the first kMaxDiagnostics of `from` (the chunk-end budget notes dropped).
void keep(DiagnosticList& into, const DiagnosticList& from, bool chunkEnd) {
    for (const Diagnostic& d : from.items()) {
        if (into.items().size() >= kMaxDiagnostics) return;
        if (chunkEnd && d.code == "BLOCK_BUDGET") continue;
        into.add(d);
    }
}
}  // namespace

bool runToProgramEnd(Interpreter& interpreter, std::uint64_t blockBudget,
                     DiagnosticList& diagnostics, std::uint64_t& blocks) {
    for (;;) {
        const std::uint64_t left = blockBudget - blocks;
        const std::uint64_t slice = std::min(left, kChunk);
        RunResult run = interpreter.run(slice);
        blocks += run.blocksInterpreted;
        const bool chunkEnd = run.status == RunStatus::BudgetExceeded && slice < left;
        keep(diagnostics, run.diagnostics, chunkEnd);
        if ((chunkEnd || run.status == RunStatus::Stopped) && blocks < blockBudget) continue;
        return run.status == RunStatus::Ended;
    }
}

ToolpathRunResult buildToolpath(const ProcessConfig& config, const ProgramStore& programs,
                                int number, const ToolpathSettings& settings,
                                std::uint64_t blockBudget) {
    ToolpathRunResult result;
    DiagnosticList axisProblems;
    ToolpathBuilder builder(ProcessAxes::build(config, axisProblems), settings);
    Interpreter interpreter(config, programs, builder);
    interpreter.options().continueAfterError = true;
    if (!interpreter.select(number, 0, &result.diagnostics)) return result;
    result.complete = runToProgramEnd(interpreter, blockBudget, result.diagnostics, result.blocks);
    result.geometry = builder.take();
    return result;
}

}  // namespace mtc::core
