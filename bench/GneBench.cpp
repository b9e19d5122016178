// GNE core timings: solving a long partly specified contour, roughing a
// shaft in fine passes, compiling the GNE demo program.
#include <benchmark/benchmark.h>

#include <string>

#include "cnc_core/compiler/Compiler.h"
#include "cnc_core/contour/ContourSolver.h"
#include "cnc_core/contour/GneExpansion.h"
#include "cnc_core/contour/GneText.h"
#include "resources/EmbeddedResources.h"

namespace {

using namespace mtc::core::gne;

/// A saw-tooth contour of `teeth` teeth: every rising line is given by its
/// angle only, its end comes from the next line's end point and angle.
std::string sawContour(int teeth) {
    std::string text = "WINDOW_02 (-10, -10, 100000, 100)\nCONT (1)\nSTART X0 Y0\n";
    for (int i = 0; i < teeth; ++i) {
        const double x = 10.0 * (i + 1);
        text += "LINE A45\nRD 0.5\n";
        text += "LINE X" + formatValue(x) + " Y0 A-45\n";
    }
    return text + "END_CONT\n";
}

void BM_GneSolveSawContour(benchmark::State& state) {
    const GneDocument doc = readGne(sawContour(static_cast<int>(state.range(0))));
    for (auto _ : state) {
        ContourSolution s = solveContour(doc.items[1].contour);
        if (!s.complete()) state.SkipWithError("contour not solved");
        benchmark::DoNotOptimize(s);
    }
    state.SetItemsProcessed(state.iterations() * state.range(0) * 3);
}
BENCHMARK(BM_GneSolveSawContour)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

const char* kShaft =
    "WINDOW_01 (-48, 2, 40)\nCONT (1)\nSTART Z0 X0\nLINE Z0 X15\nCF 1\nLINE Z-12 X15\n"
    "RELIEF E R0.6 T0.2\nLINE Z-12 X25\nRD 2\nLINE A180 L6\nCW Z-28 X35 R10 TAN\n"
    "CCW Z-36 X35 K-32 I35\nLINE Z-40 X38.5\nLINE Z-45 X38.5\nEND_CONT\n";

void BM_GneRoughingFinePasses(benchmark::State& state) {
    const GneDocument doc =
        readGne(std::string(kShaft) + "CYCLE_11 (1, 1, 0.3, , 3, 0.8, , , 1, 0.5, 0.5, 0.2)\n");
    for (auto _ : state) {
        GneExpansion e = expandGne(doc);
        if (!e.ok()) state.SkipWithError("expansion failed");
        benchmark::DoNotOptimize(e);
    }
}
BENCHMARK(BM_GneRoughingFinePasses)->Unit(benchmark::kMillisecond);

void BM_GneCompileDemo(benchmark::State& state) {
    const std::string source(mtc::resources::find("programs/N1011002.DAT"));
    mtc::core::CompilerOptions options;
    options.compilerActive = true;
    for (auto _ : state) {
        auto r = mtc::core::Compiler().compile(source, options);
        if (!r.errors.empty()) state.SkipWithError("compile failed");
        benchmark::DoNotOptimize(r);
    }
}
BENCHMARK(BM_GneCompileDemo)->Unit(benchmark::kMillisecond);

}  // namespace
