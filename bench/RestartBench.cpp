// NC program restart, computing process (issue 4, item 6): blocks per second
// to the last block of a generated 1,000,000-block program, on process 0 of
// the demo cell. Target: >= 10,000,000 blocks/s. Two programs: plain moves
// (G1/G2/G3 cycles) and a mix with M functions of group 16 (the page 61
// buffer), Q functions, coolant M functions and variable arithmetic. The
// interpreter alone on the same program (motion off) is the reference.
#include <benchmark/benchmark.h>

#include <memory>
#include <string>

#include "bench/BenchPrograms.h"
#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/restart/ComputingProcess.h"

namespace {

using namespace mtc::core;

constexpr int kBlocks = 1'000'000;

using Fixture = mtc::bench::BenchProgramFixture;

/// The moves program and the mixed one (aux functions and arithmetic on every
/// other block), each ending with M30.
const Fixture& fixture(bool mixed) {
    static const Fixture plain(kBlocks, {false, true});
    static const Fixture withAux(kBlocks, {true, true});
    return mixed ? withAux : plain;
}

void computingProcess(benchmark::State& state, bool mixed) {
    mtc::bench::ComputingProcessRun run(fixture(mixed));
    std::uint64_t blocks = 0;
    std::string status;
    for (auto _ : state) {  // NOLINT(clang-analyzer-deadcode.DeadStores)
        DiagnosticList d;
        if (!run.begin(d)) {
            state.SkipWithError("begin() failed");
            return;
        }
        const ComputingProgress p = run.computing.advance(kDefaultBlockBudget);
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
    for (auto _ : state) {  // NOLINT(clang-analyzer-deadcode.DeadStores)
        interpreter.select(1);
        blocks += interpreter.run().blocksInterpreted;
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(blocks));
}

BENCHMARK(BM_RestartComputingProcessMoves)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RestartComputingProcessMixed)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RestartReferenceInterpreterMixed)->Unit(benchmark::kMillisecond);

}  // namespace
