// Interpretation throughput (blocks/s) of an already-parsed 1,000,000-block
// program of G1/G2/G3 moves with block numbers and feeds, on process 0 of the
// demo cell (issue 3, item 7). Two variants: motions handed to a NullSink,
// and motion output switched off (the restart computing process, --no-motion).
#include <benchmark/benchmark.h>

#include <string>

#include "bench/BenchPrograms.h"
#include "cnc_core/interp/Interpreter.h"

namespace {

using namespace mtc::core;

using Fixture = mtc::bench::BenchProgramFixture;

/// The generated moves program (no M30: the run ends at its last block).
const Fixture& fixture() {
    static const Fixture f(1'000'000, {false, false});
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
