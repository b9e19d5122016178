// MDI entry: the operator's input checked, its global macros expanded and
// parsed (prepareMdiEntry); a runnable entry runs on a station's interpreter
// from the station's state (MdiRun), bounded by a block budget. Every
// diagnostic names a line of the input; what leaves the interpreter is finite.
#include <string>

#include "../FuzzTargets.h"
#include "DemoCell.h"
#include "FuzzStation.h"
#include "cnc_core/mdi/MdiEntry.h"
#include "cnc_core/mdi/MdiRun.h"

namespace mtc::fuzz {

void fuzzMdiEntry(std::string_view input) {
    static const std::vector<core::MacroDefinition> kGlobals = {
        {"FAST", "G1 F4000"}, {"COOLANT", "M8"}, {"HOME", "G0 G53 Z0"}, {"PARK", "X=@5 Y=@6"}};
    const core::MdiEntry entry = core::prepareMdiEntry(std::string(input), kGlobals);
    for (const core::Diagnostic& d : entry.diagnostics.items())
        require(d.where.line >= 1 && !d.code.empty(), "MDI diagnostics name a line of the input",
                input);
    require(!entry.program || entry.expanded.size() == entry.lines.size(),
            "a parsed entry has one expanded line per line", input);
    if (!entry.runnable()) return;
    // the process follows the input's length: both the mill and the lathe get inputs
    FuzzStation station(*demoCell().process(static_cast<int>(input.size() % 2)), input);
    core::MdiRun run;
    if (!run.begin(*station.interpreter, entry.program)) return;
    const core::RunResult result = run.run(5'000);
    for (const core::Diagnostic& d : result.diagnostics.items())
        require(!d.code.empty() && !d.message.empty(), "run diagnostics say what", input);
    // a second entry continues from the state the first one left
    if (run.active()) run.abandon();
    if (run.begin(*station.interpreter, entry.program)) run.run(5'000);
}

}  // namespace mtc::fuzz
