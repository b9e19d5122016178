#include "cnc_core/removal/RemovalRun.h"

#include "cnc_core/compensation/ToolData.h"
#include "cnc_core/toolpath/ToolpathRun.h"

namespace mtc::core::removal {

RemovalRunResult simulateRemoval(const ProcessConfig& config, const ProgramStore& programs,
                                 int number, const RemovalSettings& settings,
                                 std::shared_ptr<const ToolList> tools, std::uint64_t blockBudget) {
    RemovalRunResult result;
    std::string problem;
    result.part =
        PartModel::create(stockOf(config), settings, config.defaultPlane() == 18, problem);
    if (!result.part) {
        result.diagnostics.error("REMOVAL_STOCK", {}, problem);  // the configuration's
        return result;
    }
    DiagnosticList axisProblems;
    RemovalSink sink(ProcessAxes::build(config, axisProblems), *result.part);
    InterpreterServices services;
    services.tools = std::move(tools);
    Interpreter interpreter(config, programs, sink, services);
    interpreter.options().continueAfterError = true;
    // The tool in working position when the move reaches the sink (TC-009).
    sink.setToolSource(
        [&interpreter] { return activeToolData(interpreter.tools(), interpreter.state().modal); });
    if (interpreter.select(number, 0, &result.diagnostics))
        result.complete =
            runToProgramEnd(interpreter, blockBudget, result.diagnostics, result.blocks);
    result.diagnostics.append(sink.notes());
    result.counts = sink.counts();
    // Reported as the program's blocks are (a loose file keeps program 0).
    const ProgramPtr selected = programs.find(config.index, number);
    const SourceLocation program{selected ? selected->number : number, "", 0, 0};
    if (result.counts.transformedMoves > 0)
        result.diagnostics.warning(
            "REMOVAL_NOT_SIMULATED", program,
            std::to_string(result.counts.transformedMoves) +
                " moves under G31/G32 were not cut (the part model has no developed surface)");
    if (result.counts.insideToolMoves > 0)
        result.diagnostics.warning("REMOVAL_NOT_SIMULATED", program,
                                   std::to_string(result.counts.insideToolMoves) +
                                       " moves of an inside tool were not cut (the turned "
                                       "profile has no bores)");
    return result;
}

}  // namespace mtc::core::removal
