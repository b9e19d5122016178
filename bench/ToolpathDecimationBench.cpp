// Coarse copy of the toolpath view (TP-010): decimateLayer on 1,000,000
// segments down to the 40,000-cell budget, starting at 1/1000 of the
// extent. BM_DecimateFinishingPasses: 0.1 mm moves in 100 mm passes, every
// 100th a rapid (runs of one kind collapse to a cell); BM_DecimateHelix: a
// helix of 1,000,000 chords (every vertex off the chord, the tolerance has
// to grow); BM_PickThroughCoarseCopy: one click resolved through that copy.
// Counters: cells and the final tolerance.
#include <benchmark/benchmark.h>

#include <cmath>

#include "cnc_core/toolpath/ToolpathDecimation.h"
#include "cnc_core/toolpath/ToolpathPick.h"

namespace {

using namespace mtc::core;

ToolpathGeometry passes() {
    ToolpathGeometry g;
    std::array<double, 3> from{0, 0, 0};
    for (int i = 0; i < 1'000'000; ++i) {
        const int pass = i / 1000, step = i % 1000 + 1;
        const std::array<double, 3> to{pass % 2 ? 100.0 - step * 0.1 : step * 0.1, pass * 0.06,
                                       -(pass / 100) * 0.5};
        g.moves.push_back({0, static_cast<std::uint32_t>(i), 0,
                           i % 100 == 0 ? ToolpathKind::Rapid : ToolpathKind::Feed, 30, 0,
                           static_cast<std::uint32_t>(i), 0});
        g.scene.addSegment(from, to);
        from = to;
    }
    return g;
}

ToolpathGeometry helix() {
    ToolpathGeometry g;
    g.moves.push_back({0, 0, 0, ToolpathKind::Arc, 30, 0, 0, 0});
    std::array<double, 3> from{20, 0, 0};
    for (int i = 1; i <= 1'000'000; ++i) {
        const double a = i * 0.01;  // 0.2 mm chords on R20, 0.0005 mm pitch per chord
        const std::array<double, 3> to{20 * std::cos(a), 20 * std::sin(a), -i * 0.0005};
        g.scene.addSegment(from, to);
        from = to;
    }
    return g;
}

void decimate(benchmark::State& state, const ToolpathGeometry& g) {
    DecimatedLayer d;
    for (auto _ : state) {
        d = decimateLayer(g, false, g.scene.bounds.size() / 1000, 40000);
        benchmark::DoNotOptimize(d.ends.data());
    }
    state.counters["cells"] = static_cast<double>(d.cellCount());
    state.counters["tolerance"] = d.tolerance;
}

void BM_DecimateFinishingPasses(benchmark::State& state) {
    decimate(state, passes());
}

void BM_DecimateHelix(benchmark::State& state) {
    decimate(state, helix());
}

void BM_PickThroughCoarseCopy(benchmark::State& state) {
    const ToolpathGeometry g = passes();
    const DecimatedLayer d = decimateLayer(g, false, 0.1, 40000);
    ScreenProjection view;  // top view of 0..100 mm onto 1000 x 1000 pixels
    view.toNdc = {0.02, 0, 0, -1, 0, 0.02, 0, -1, 0, 0, 0.02, 0, 0, 0, 0, 1};
    view.width = view.height = 1000;
    for (auto _ : state)
        benchmark::DoNotOptimize(pickSegment(g.scene, d, view, 503.0, 301.0, 6.0));
    state.counters["cells"] = static_cast<double>(d.cellCount());
}

BENCHMARK(BM_DecimateFinishingPasses)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DecimateHelix)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PickThroughCoarseCopy)->Unit(benchmark::kMillisecond);

}  // namespace
