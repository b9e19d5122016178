// Interpretation throughput (blocks/s) of an already-parsed 1,000,000-block
// program of G1/G2/G3 moves with block numbers and feeds, on process 0 of the
// demo cell (issue 3, item 7). Two variants: motions handed to a NullSink,
// and motion output switched off (the restart computing process, --no-motion).
#include <benchmark/benchmark.h>

#include <cstdint>
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

/// Folds every field of every move into one number (FNV-1a): the check
/// run's moves against the measured path's, without keeping a million.
class HashSink : public NullSink {
  public:
    void motion(const Motion& m) override {
        add(m.where.program);
        for (char c : m.where.block)
            add(c);
        add(m.where.line, m.type, m.axisCount, m.start, m.end, m.planeAxis1, m.planeAxis2);
        add(m.center1, m.center2, m.fullCircle, m.feed, m.transformation, m.effectiveRadius);
        add(m.transformAxis1, m.transformAxis2, m.blockIndex, m.compensated, m.inserted);
        add(m.programmedEnd, m.toolOffset, m.exactStop, m.blendCorners, m.zeroOffset);
        add(m.zeroOffsetValues, m.radialAxis, m.diameter);
    }
    std::uint64_t hash = 14695981039346656037ull;

  private:
    template <typename... T>
    void add(const T&... values) {
        (bytes(&values, sizeof values), ...);
    }
    void bytes(const void* data, std::size_t size) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i)
            hash = (hash ^ p[i]) * 1099511628211ull;
    }
};

/// One run of the program: its moves' hash and the final modal state (G
/// groups, positions, feed, time) as text.
std::string checkRun(const Fixture& f, bool shortcuts) {
    HashSink sink;
    Interpreter interpreter(*f.cell.process(0), f.store, sink);
    interpreter.options().shortcuts = shortcuts;
    interpreter.select(1);
    const RunResult result = interpreter.run();
    const ModalState& m = interpreter.state().modal;
    std::string text = std::to_string(sink.hash) + " " + std::to_string(result.blocksInterpreted);
    for (auto g : m.g)
        text += " " + std::to_string(g);
    for (int a = 0; a < kMaxAxes; ++a)
        text += " " + std::to_string(m.work[static_cast<std::size_t>(a)]) + " " +
                std::to_string(m.machine[static_cast<std::size_t>(a)]);
    return text + " " + std::to_string(m.feed) + " " + std::to_string(m.time);
}

void interpret(benchmark::State& state, bool motion) {
    const Fixture& f = fixture();
    // Once: the measured path (shortcuts of the usual block, I-022) gives
    // the general path's moves and state on this program.
    if (checkRun(f, true) != checkRun(f, false)) {
        state.SkipWithError("the shortcuts change the run");
        return;
    }
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
