// NC program restart, computing process (issue 4, item 6): blocks per second
// to the last block of a generated 1,000,000-block program, on process 0 of
// the demo cell. Target: >= 10,000,000 blocks/s. Two programs: plain moves
// (G1/G2/G3 cycles) and a mix with M functions of group 16 (the page 61
// buffer), Q functions, coolant M functions and variable arithmetic. The
// interpreter alone on the same program (motion off) is the reference.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <memory>
#include <string>

#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/language/Parser.h"
#include "cnc_core/machine/InMemoryMachineData.h"
#include "cnc_core/machine/MachineConfigReader.h"
#include "cnc_core/restart/ComputingProcess.h"
#include "resources/EmbeddedResources.h"

namespace {

using namespace mtc::core;

constexpr int kBlocks = 1'000'000;

/// Cycles of four closed moves: a line, a counter-clockwise and a clockwise
/// quarter circle of radius 10, a line back; `mixed` adds aux functions and
/// arithmetic to every other block.
std::string generateProgram(int blocks, bool mixed) {
    std::string text;
    text.reserve(static_cast<std::size_t>(blocks) * 48);
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
    text += "N9999 M30\n";
    return text;
}

struct Fixture {
    explicit Fixture(bool mixed) {
        cell = readMachineConfig(mtc::resources::find(mtc::resources::kDemoCellName)).config;
        ParseOptions options;
        options.programNumber = 1;
        auto parsed =
            std::make_shared<Program>(parseProgram(generateProgram(kBlocks, mixed), options));
        parsed->number = 1;
        program = parsed;
        store.put(0, 1, program);
    }
    MachineConfig cell;
    ProgramStore store;
    ProgramPtr program;
};

const Fixture& fixture(bool mixed) {
    static const Fixture plain(false);
    static const Fixture withAux(true);
    return mixed ? withAux : plain;
}

void computingProcess(benchmark::State& state, bool mixed) {
    const Fixture& f = fixture(mixed);
    const ProcessConfig& config = *f.cell.process(0);
    NullSink sps;
    InterpreterServices services{std::make_shared<InMemoryMachineData>(f.cell),
                                 std::make_shared<EventTable>(), nullptr};
    Interpreter live(config, f.store, sps, services);
    ComputingProcess computing(config, f.store, sps, services);
    RestartSelection selection;
    selection.mainProgram = 1;
    selection.target = {1, static_cast<std::uint32_t>(f.program->blocks.size() - 2)};
    std::uint64_t blocks = 0;
    std::string status;
    for (auto _ : state) {
        DiagnosticList d;
        if (!computing.begin(selection, live.state(), live.options(), kDefaultBlockBudget, d)) {
            state.SkipWithError("begin() failed");
            return;
        }
        const ComputingProgress p = computing.advance(kDefaultBlockBudget);
        blocks += p.blocksInterpreted;
        status = computingStatusName(p.status);
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(blocks));
    state.SetLabel("blocks/s = items/s; last: " + status);
}

void BM_RestartComputingProcessMoves(benchmark::State& state) {
    computingProcess(state, false);
}
void BM_RestartComputingProcessMixed(benchmark::State& state) {
    computingProcess(state, true);
}

/// Reference: the interpreter alone, motion off, on the mixed program.
void BM_RestartReferenceInterpreterMixed(benchmark::State& state) {
    const Fixture& f = fixture(true);
    NullSink sink;
    Interpreter interpreter(*f.cell.process(0), f.store, sink);
    interpreter.options().output.motion = false;
    std::uint64_t blocks = 0;
    for (auto _ : state) {
        interpreter.select(1);
        blocks += interpreter.run().blocksInterpreted;
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(blocks));
}

BENCHMARK(BM_RestartComputingProcessMoves)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RestartComputingProcessMixed)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RestartReferenceInterpreterMixed)->Unit(benchmark::kMillisecond);

}  // namespace
