#include "cnc_core/removal/RemovalRun.h"

#include <algorithm>

#include "cnc_core/compensation/ToolData.h"
#include "cnc_core/toolpath/ToolpathRun.h"

namespace mtc::core::removal {

namespace {

/// Runs `interpreter` to the `stop.runs`-th counted arrival at the stop's
/// target (true) or to the program end, an error or the budget (false).
bool runToStop(Interpreter& interpreter, const RemovalStop& stop, std::uint64_t blockBudget,
               DiagnosticList& diagnostics, std::uint64_t& blocks) {
    const StopTarget target{stop.target.program, stop.target.block, 1};
    interpreter.setStopTarget(target);
    std::uint32_t arrivals = 0;
    while (blocks < blockBudget) {
        RunResult run = interpreter.run(std::min<std::uint64_t>(blockBudget - blocks, 65536));
        blocks += std::max<std::uint64_t>(run.blocksInterpreted, 1);  // progress, whatever it says
        for (const Diagnostic& d : run.diagnostics.items())
            if (d.code != "BLOCK_BUDGET" && diagnostics.items().size() < 100) diagnostics.add(d);
        if (run.status == RunStatus::TargetReached) {
            if ((!stop.counts || stop.counts(interpreter.state())) && ++arrivals >= stop.runs)
                return true;
            interpreter.setStopTarget(std::nullopt);  // this arrival does not count: run the block
            run = interpreter.step();
            blocks += run.blocksInterpreted;
            interpreter.setStopTarget(target);
        }
        if (run.status != RunStatus::Running && run.status != RunStatus::BudgetExceeded &&
            run.status != RunStatus::Stopped && run.status != RunStatus::TargetReached)
            return false;
    }
    diagnostics.error("BLOCK_BUDGET", {},
                      "the removal run was stopped after " + std::to_string(blockBudget) +
                          " interpreted blocks (block budget)");
    return false;
}

}  // namespace

std::optional<PartModel> blankPart(const ProcessConfig& config, const ProgramStock& stock,
                                   const RemovalSettings& settings, DiagnosticList& diagnostics) {
    diagnostics.append(stock.diagnostics);
    if (stock.diagnostics.hasErrors()) return std::nullopt;  // a window that cannot be the blank
    std::string problem;
    std::optional<PartModel> part =
        PartModel::create(stock.stock, settings, config.defaultPlane() == 18, problem);
    if (part) return part;
    if (stock.origin.fromWindow)
        diagnostics.error("REMOVAL_STOCK", stock.origin.where,
                          stock.origin.keyword + ": " + problem);
    else
        diagnostics.error("REMOVAL_STOCK", {}, problem);  // the configuration's
    return std::nullopt;
}

RemovalRunResult simulateRemoval(const ProcessConfig& config, const ProgramStore& programs,
                                 int number, const RemovalSettings& settings,
                                 std::shared_ptr<const ToolList> tools, std::uint64_t blockBudget,
                                 const RemovalStop* stop) {
    const ProgramStock stock = programStock(
        config, programs, number, stop != nullptr ? stop->zeroOffsets : nullptr, blockBudget);
    return simulateRemoval(config, programs, number, stock, settings, std::move(tools), blockBudget,
                           stop);
}

RemovalRunResult simulateRemoval(const ProcessConfig& config, const ProgramStore& programs,
                                 int number, const ProgramStock& stock,
                                 const RemovalSettings& settings,
                                 std::shared_ptr<const ToolList> tools, std::uint64_t blockBudget,
                                 const RemovalStop* stop) {
    RemovalRunResult result;
    result.stock = stock.origin;
    result.part = blankPart(config, stock, settings, result.diagnostics);
    if (!result.part) return result;
    DiagnosticList axisProblems;
    RemovalSink sink(ProcessAxes::build(config, axisProblems), *result.part);
    InterpreterServices services;
    services.tools = std::move(tools);
    if (stop != nullptr) services.zeroOffsets = stop->zeroOffsets;
    Interpreter interpreter(config, programs, sink, services);
    interpreter.options().continueAfterError = true;
    // The tool in working position when the move reaches the sink (TC-009).
    sink.setToolSource(
        [&interpreter] { return activeToolData(interpreter.tools(), interpreter.state().modal); });
    if (interpreter.select(number, 0, &result.diagnostics)) {
        if (stop == nullptr) {
            result.complete =
                runToProgramEnd(interpreter, blockBudget, result.diagnostics, result.blocks);
        } else {
            if (stop->prepare) stop->prepare(interpreter);
            result.complete =
                runToStop(interpreter, *stop, blockBudget, result.diagnostics, result.blocks);
            if (!result.complete)
                result.diagnostics.warning(
                    "REMOVAL_STOP_NOT_REACHED", {stop->target.program, "", 0, 0},
                    "the removal run did not reach the target block: the part there is unknown");
        }
    }
    result.diagnostics.append(sink.notes());
    result.counts = sink.counts();
    // Reported as the program's blocks are (a loose file keeps program 0).
    const ProgramPtr selected = programs.find(config.index, number);
    const SourceLocation program{selected ? selected->number : number, "", 0, 0};
    if (result.counts.transformedMoves > 0)
        result.diagnostics.warning(
            "REMOVAL_NOT_SIMULATED", program,
            std::to_string(result.counts.transformedMoves) +
                " moves under G31/G32 were not cut (facing is not simulated; G32 only on a "
                "turned part's jacket, D-027)");
    if (result.counts.insideToolMoves > 0)
        result.diagnostics.warning("REMOVAL_NOT_SIMULATED", program,
                                   std::to_string(result.counts.insideToolMoves) +
                                       " moves of an inside tool were not cut (the turned "
                                       "profile has no bores)");
    return result;
}

}  // namespace mtc::core::removal
