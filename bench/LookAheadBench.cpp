// Enhanced look-ahead planner (seed 001 ch. 6) on a polygon of 10,000 short
// blocks: lines and arcs in G17 with a Z lead, mixed feeds (issue 6).
#include <benchmark/benchmark.h>

#include <cmath>

#include <cstdio>
#include <string>

#include "cnc_core/compiler/Compiler.h"
#include "cnc_core/compiler/lookahead/VelocityPlanner.h"

namespace {

using namespace mtc::core::lookahead;

AxisVector xyz(double x, double y, double z) {
    AxisVector p = AxisVector::Zero(3);
    p << x, y, z;
    return p;
}

AxisLimits demoMillLimits() {
    AxisLimits limits;
    limits.names = {"X", "Y", "Z"};
    limits.maxVelocity = xyz(30000, 30000, 20000);
    limits.maxAcceleration = xyz(2500, 2500, 2000);
    return limits;
}

/// `count` contiguous elements: every fourth an arc (half circle of 0.4 mm
/// diameter), the rest 0.2 .. 1.0 mm lines along a wavy path.
std::vector<PathElement> wavyPolygon(int count) {
    std::vector<PathElement> elements;
    elements.reserve(static_cast<size_t>(count));
    AxisVector at = xyz(0, 0, 0);
    for (int i = 0; i < count; ++i) {
        PathElement e;
        e.start = at;
        e.axisFeed = AxisVector::Zero(3);
        e.feed = 4000.0 + (i % 7) * 1500.0;
        if (i % 4 == 3) {
            e.kind = i % 8 == 3 ? ElementKind::ArcCcw : ElementKind::ArcCw;
            e.center = at + xyz(0.2, 0, 0);
            e.end = at + xyz(0.4, 0, 0.01);
        } else {
            e.kind = ElementKind::Line;
            e.center = AxisVector::Zero(3);
            e.end = at + xyz(0.2 + 0.1 * (i % 9), 0.3 * std::sin(i * 0.37), 0.0);
        }
        at = e.end;
        elements.push_back(e);
    }
    return elements;
}

void BM_LookAheadPlan(benchmark::State& state) {
    const auto elements = wavyPolygon(static_cast<int>(state.range(0)));
    const AxisLimits limits = demoMillLimits();
    const LookAheadParameters parameters;
    size_t blocks = 0;
    for (auto _ : state) {
        const LookAheadPlan plan = planVelocityProfile(elements, limits, parameters);
        blocks = plan.blocks.size();
        benchmark::DoNotOptimize(plan.totalTime);
    }
    state.counters["emitted_blocks"] = static_cast<double>(blocks);
    state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_LookAheadPlan)->Arg(10000)->Unit(benchmark::kMillisecond);

/// A loose program: one LA_ON ... LA_OFF segment of `count` short G1/G3 blocks.
std::string laProgram(int count) {
    std::string text = "N0000 G0 G17 G90 X0 Y0 Z0\nN0001 F6000 METB=4\nN0002 LA_ON\n";
    char line[96];
    double x = 0.0;
    for (int i = 0; i < count; ++i) {
        const int n = (i + 3) % 10000;
        if (i % 4 == 3) {
            std::snprintf(line, sizeof line, "N%04d G3 X%.3f Y0 I%.3f J0\n", n, x + 0.4, x + 0.2);
            x += 0.4;
        } else {
            x += 0.3;
            std::snprintf(line, sizeof line, "N%04d G1 X%.3f Y0\n", n, x);
        }
        text += line;
    }
    return text + "N9999 LA_OFF\n";
}

/// The whole compiler (standard passes) on a program whose blocks are all
/// inside one look-ahead segment.
void BM_LookAheadCompile(benchmark::State& state) {
    const std::string source = laProgram(static_cast<int>(state.range(0)));
    mtc::core::CompilerOptions options;
    options.compilerActive = true;
    const mtc::core::Compiler compiler;
    std::size_t blocks = 0;
    for (auto _ : state) {
        const mtc::core::CompileResult r = compiler.compile(source, options);
        blocks = r.objectBlocks;
        benchmark::DoNotOptimize(r.objectText.data());
    }
    state.counters["object_blocks"] = static_cast<double>(blocks);
    state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_LookAheadCompile)->Arg(5000)->Unit(benchmark::kMillisecond);

}  // namespace
