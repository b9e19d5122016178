// Parse throughput and memory of the MTC200 NC parser on a generated program
// of G1/G2/G3 moves with block numbers and feeds (issue 3, item 7).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <string>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "cnc_core/language/Parser.h"
#include "tests/support/ProgramDifference.h"

namespace {

/// Heap bytes in use (glibc), or 0 where unknown.
std::size_t heapInUse() {
#if defined(__GLIBC__)
    struct mallinfo2 info = mallinfo2();
    return info.uordblks + info.hblkhd;
#else
    return 0;
#endif
}

/// A loose file of `blocks` motion blocks: "N0123 G1 X12.345 Y-3.5 F2000",
/// arcs with I/J centres; block numbers wrap at 9999.
std::string generateMotionProgram(int blocks) {
    std::string text;
    text.reserve(static_cast<std::size_t>(blocks) * 36);
    char line[96];
    for (int i = 0; i < blocks; ++i) {
        int number = i % 10000;
        double x = (i % 2000) * 0.125 - 100.0;
        double y = ((i * 7) % 3000) * 0.01 - 15.0;
        int n = 0;
        switch (i % 4) {
            case 0:
            case 1:
                n = std::snprintf(line, sizeof line, "N%04d G1 X%.3f Y%.3f F%d\n", number, x, y,
                                  1000 + (i % 5) * 250);
                break;
            case 2:
                n = std::snprintf(line, sizeof line, "N%04d G2 X%.3f Y%.3f I%.2f J0 F1500\n",
                                  number, x, y, x / 2);
                break;
            default:
                n = std::snprintf(line, sizeof line, "N%04d G3 X%.3f Y%.3f I0 J%.2f\n", number, x,
                                  y, y / 2);
                break;
        }
        text.append(line, static_cast<std::size_t>(n));
    }
    return text;
}

/// The fast paths against the general path, once: the timed parses must
/// give exactly the program the general path gives.
bool fastPathsAgree(const std::string& source, benchmark::State& state) {
    mtc::core::ParseOptions general;
    general.plainBlockFastPath = false;
    const std::string difference = mtc::core::testing::programDifference(
        mtc::core::parseProgram(source), mtc::core::parseProgram(source, general));
    if (difference.empty()) return true;
    state.SkipWithError(("the fast path parses differently: " + difference).c_str());
    return false;
}

void BM_ParseMotionProgram(benchmark::State& state) {
    const std::string source = generateMotionProgram(static_cast<int>(state.range(0)));
    if (!fastPathsAgree(source, state)) return;
    double memoryRatio = 0.0;
    double heapRatio = 0.0;
    std::size_t blocks = 0;
    std::size_t errors = 0;
    for (auto _ : state) {  // NOLINT(clang-analyzer-deadcode.DeadStores)
        // The copy stands for reading the file; only parsing is timed.
        state.PauseTiming();
        std::string text = source;
        std::size_t heapBefore = heapInUse() - text.capacity();
        state.ResumeTiming();
        mtc::core::Program program = mtc::core::parseProgram(std::move(text));
        state.PauseTiming();
        heapRatio =
            static_cast<double>(heapInUse() - heapBefore) / static_cast<double>(source.size());
        state.ResumeTiming();
        blocks = program.blocks.size();
        errors = program.diagnostics.size();
        memoryRatio =
            static_cast<double>(program.memoryBytes()) / static_cast<double>(source.size());
        benchmark::DoNotOptimize(program);
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                            static_cast<std::int64_t>(source.size()));
    state.counters["blocks"] = static_cast<double>(blocks);
    state.counters["diagnostics"] = static_cast<double>(errors);
    state.counters["memory_x_source"] = memoryRatio;  // Program::memoryBytes()
    state.counters["heap_x_source"] = heapRatio;      // malloc'd bytes incl. the source
    state.counters["source_MB"] = static_cast<double>(source.size()) / 1e6;
    state.counters["blocks_per_s"] = benchmark::Counter(
        static_cast<double>(blocks), benchmark::Counter::kIsIterationInvariantRate);
}

}  // namespace

BENCHMARK(BM_ParseMotionProgram)->Arg(1000000)->Unit(benchmark::kMillisecond)->MinTime(2.0);
