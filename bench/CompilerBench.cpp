// NC compiler speed (issue 6, issue 21): a 10,000-block program with a
// chamfer or rounding on every second block and a macro in every block
// (targets: under 20 ms, then at most 5 ms for the whole compile, object
// text and line map included; figures in docs/decisions/compiler.md C-012).
#include <benchmark/benchmark.h>

#include <cstdint>
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

/// FNV-1a over the object text, the line map and the messages of `result`.
std::uint64_t fingerprint(const mtc::core::CompileResult& result) {
    std::uint64_t hash = 14695981039346656037ull;
    const auto mix = [&hash](std::uint64_t value) {
        hash ^= value;
        hash *= 1099511628211ull;
    };
    for (char c : result.objectText)
        mix(static_cast<unsigned char>(c));
    for (const mtc::core::ObjectLine& line : result.lineMap) {
        mix(static_cast<std::uint64_t>(line.kind));
        mix(line.sourceLine);
        mix(static_cast<std::uint32_t>(line.sourceNumber));
        mix(static_cast<std::uint32_t>(line.subNumber));
        mix(line.intermediate);
    }
    mix(result.errors.size());
    return hash;
}

/// The fingerprint of the 10,000-block program's result as the compiler gave
/// it before the speed work of issue 21 (main f6666e3): the optimised passes
/// must give exactly the same object program.
constexpr std::uint64_t kReferenceFingerprint10k = 15138944916475083740ull;

void BM_CompileCornersAndMacros(benchmark::State& state) {
    const std::string source = generateCornerProgram(static_cast<int>(state.range(0)));
    mtc::core::CompilerOptions options;
    options.compilerActive = true;
    options.globalMacros = {{"COOL", "M8"}};
    const mtc::core::Compiler compiler;
    if (state.range(0) == 10000) {  // checked once, outside the timing
        const std::uint64_t found = fingerprint(compiler.compile(source, options));
        if (found != kReferenceFingerprint10k) {
            std::fprintf(stderr, "fingerprint %llu\n", static_cast<unsigned long long>(found));
            state.SkipWithError("the object program differs from the reference");
            return;
        }
    }
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
