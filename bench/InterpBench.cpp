// Interpretation throughput (blocks/s) of an already-parsed 1,000,000-block
// program of G1/G2/G3 moves with block numbers and feeds, on process 0 of the
// demo cell (issue 3, item 7). Two variants: motions handed to a NullSink,
// and motion output switched off (the restart computing process, --no-motion).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <memory>
#include <string>

#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/language/Parser.h"
#include "cnc_core/machine/MachineConfigReader.h"
#include "resources/EmbeddedResources.h"

namespace {

using namespace mtc::core;

/// `blocks` blocks in cycles of four that always close: a line to the start
/// of a quarter circle, a counter-clockwise and a clockwise quarter circle
/// (radius 10, centre absolute), a line back. The square's size varies so the
/// numbers differ from cycle to cycle.
std::string generateClosedMotionProgram(int blocks) {
    std::string text;
    text.reserve(static_cast<std::size_t>(blocks) * 40);
    char line[128];
    for (int i = 0; i < blocks; ++i) {
        const int number = i % 10000;
        const double x0 = 10.0 + (i / 4 % 50) * 0.5;
        int n = 0;
        switch (i % 4) {
            case 0:
                n = std::snprintf(line, sizeof line, "N%04d G1 X%.3f Y0 F%d\n", number, x0,
                                  1000 + (i % 5) * 250);
                break;
            case 1:
                n = std::snprintf(line, sizeof line, "N%04d G3 X%.3f Y10 I%.3f J0\n", number,
                                  x0 + 10.0, x0 + 10.0);
                break;
            case 2:
                n = std::snprintf(line, sizeof line, "N%04d G2 X%.3f Y0 I%.3f J0 F1500\n", number,
                                  x0 + 20.0, x0 + 10.0);
                break;
            default:
                n = std::snprintf(line, sizeof line, "N%04d G1 X0 Y0\n", number);
                break;
        }
        text.append(line, static_cast<std::size_t>(n));
    }
    return text;
}

struct Fixture {
    Fixture() {
        auto read = readMachineConfig(mtc::resources::find(mtc::resources::kDemoCellName));
        cell = read.config;
        ParseOptions options;
        options.programNumber = 1;
        auto parsed = std::make_shared<Program>(
            parseProgram(generateClosedMotionProgram(1'000'000), options));
        parsed->number = 1;
        program = parsed;
        store.put(0, 1, program);
    }
    MachineConfig cell;
    ProgramStore store;
    ProgramPtr program;
};

const Fixture& fixture() {
    static const Fixture f;
    return f;
}

void interpret(benchmark::State& state, bool motion) {
    const Fixture& f = fixture();
    NullSink sink;
    Interpreter interpreter(*f.cell.process(0), f.store, sink);
    interpreter.options().output.motion = motion;
    std::uint64_t blocks = 0;
    std::string status;
    for (auto _ : state) {
        interpreter.select(1);
        RunResult result = interpreter.run();
        blocks += result.blocksInterpreted;
        status = runStatusName(result.status);
        if (!result.diagnostics.empty()) status += " " + result.diagnostics.items().front().code;
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(blocks));
    state.SetLabel("blocks/s = items/s; last run: " + status);
}

/// Reference: only reading every block and word of the program (the floor
/// that the AST access sets for any interpreter built on it).
void BM_ReadProgramOnly(benchmark::State& state) {
    const Fixture& f = fixture();
    std::uint64_t blocks = 0;
    for (auto _ : state) {
        double sum = 0.0;
        const Program& p = *f.program;
        for (std::size_t i = 0; i < p.blocks.size(); ++i) {
            const Block b = p.blocks[i];
            for (std::uint32_t w = b.firstWord; w < b.firstWord + b.wordCount; ++w)
                sum += p.words[w].number;
        }
        benchmark::DoNotOptimize(sum);
        blocks += p.blocks.size();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(blocks));
}

void BM_InterpretNullSink(benchmark::State& state) {
    interpret(state, true);
}
void BM_InterpretNoMotion(benchmark::State& state) {
    interpret(state, false);
}

BENCHMARK(BM_ReadProgramOnly)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_InterpretNullSink)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_InterpretNoMotion)->Unit(benchmark::kMillisecond);

}  // namespace
