#include "bench/BenchPrograms.h"

#include <cstdio>
#include <memory>

#include "cnc_core/language/Parser.h"
#include "cnc_core/machine/InMemoryMachineData.h"
#include "cnc_core/machine/MachineConfigReader.h"
#include "resources/EmbeddedResources.h"

namespace mtc::bench {

using namespace mtc::core;

std::string generateClosedMotionProgram(int blocks, GeneratedProgramOptions options) {
    const bool mixed = options.mixed;
    std::string text;
    text.reserve(static_cast<std::size_t>(blocks) * (mixed ? 48 : 40));
    char line[160];
    for (int i = 0; i < blocks; ++i) {
        const int number = i % 10000;
        const double x0 = 10.0 + (i / 4 % 50) * 0.5;
        int n = 0;
        switch (i % 4) {
            case 0:
                n = std::snprintf(line, sizeof line, "N%04d G1 X%.3f Y0 F%d%s\n", number, x0,
                                  1000 + (i % 5) * 250, mixed ? " M108 Q17" : "");
                break;
            case 1:
                n = std::snprintf(line, sizeof line, "N%04d G3 X%.3f Y10 I%.3f J0\n", number,
                                  x0 + 10.0, x0 + 10.0);
                break;
            case 2:
                n = std::snprintf(line, sizeof line, "N%04d G2 X%.3f Y0 I%.3f J0 F1500%s\n", number,
                                  x0 + 20.0, x0 + 10.0, mixed ? " M62 @1=@1+1" : "");
                break;
            default:
                n = std::snprintf(line, sizeof line, "N%04d G1 X0 Y0%s\n", number,
                                  mixed ? " M109 M63" : "");
                break;
        }
        text.append(line, static_cast<std::size_t>(n));
    }
    if (options.endWithM30) text += "N9999 M30\n";
    return text;
}

BenchProgramFixture::BenchProgramFixture(int blocks, GeneratedProgramOptions options) {
    cell = readMachineConfig(mtc::resources::find(mtc::resources::kDemoCellName)).config;
    ParseOptions parse;
    parse.programNumber = 1;
    auto parsed = std::make_shared<Program>(
        parseProgram(generateClosedMotionProgram(blocks, options), parse));
    parsed->number = 1;
    program = parsed;
    store.put(0, 1, program);
}

namespace {

InterpreterServices computingServices(const BenchProgramFixture& fixture) {
    InterpreterServices services;
    services.machineData = std::make_shared<InMemoryMachineData>(fixture.cell);
    services.events = std::make_shared<EventTable>();
    return services;
}

}  // namespace

ComputingProcessRun::ComputingProcessRun(const BenchProgramFixture& fixture)
    : services(computingServices(fixture)),
      live(*fixture.cell.process(0), fixture.store, sps, services),
      computing(*fixture.cell.process(0), fixture.store, sps, services) {
    selection.mainProgram = 1;
    selection.target = {1, static_cast<std::uint32_t>(fixture.program->blocks.size() - 2)};
}

bool ComputingProcessRun::begin(DiagnosticList& diagnostics) {
    return computing.begin(selection, live.state(), live.options(), kDefaultBlockBudget,
                           diagnostics);
}

}  // namespace mtc::bench
