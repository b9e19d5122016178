// NC compiler speed (issue 6): a 10,000-block program with a chamfer or
// rounding on every second block and a macro in every block (target: under
// 20 ms for the whole compile, object text and line map included).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <string>

#include "cnc_core/compiler/Compiler.h"

namespace {

/// A zig-zag contour: X and Y moves alternate (every corner bends by 90
/// degrees), RD or CF on every second block, the local macro FEED and the
/// global macro COOL in every block. A loose file (no .DAT line limit).
std::string generateCornerProgram(int blocks) {
    std::string text = "N0000 DEFINE FEED AS F1200\nN0001 G1 X0 Y0 FEED COOL\n";
    text.reserve(static_cast<std::size_t>(blocks) * 40);
    char line[96];
    double x = 0.0, y = 0.0;
    for (int i = 2; i < blocks; ++i) {
        const bool corner = i % 2 == 0 && i + 1 < blocks;
        if (i % 2)
            y += (i % 4 == 1 ? 8.0 : -6.0);
        else
            x += 10.0 + (i % 7);
        std::snprintf(line, sizeof line, "N%04d X%.3f Y%.3f FEED COOL%s\n", i % 10000, x, y,
                      !corner ? "" : (i % 4 == 0 ? " RD1.5" : " CF0.8"));
        text += line;
    }
    return text;
}

void BM_CompileCornersAndMacros(benchmark::State& state) {
    const std::string source = generateCornerProgram(static_cast<int>(state.range(0)));
    mtc::core::CompilerOptions options;
    options.compilerActive = true;
    options.globalMacros = {{"COOL", "M8"}};
    const mtc::core::Compiler compiler;
    std::size_t inserted = 0;
    for (auto _ : state) {
        mtc::core::CompileResult result = compiler.compile(source, options);
        if (result.status != mtc::core::CompileStatus::Compiled) {
            state.SkipWithError("the benchmark program did not compile");
            return;
        }
        inserted = result.objectBlocks;
        benchmark::DoNotOptimize(result.objectText.data());
    }
    state.counters["object_blocks"] = static_cast<double>(inserted);
    state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_CompileCornersAndMacros)->Arg(10000)->Unit(benchmark::kMillisecond);

}  // namespace
