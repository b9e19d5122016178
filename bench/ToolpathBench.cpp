// Toolpath geometry (issue 8): 1,000,000 segments must be built in <= 1 s
// and <= 300 MB. BM_ToolpathBuilderLines feeds 1,000,000 straight moves
// (one segment each) to the ToolpathBuilder, BM_ToolpathBuilderArcs 10,000
// arcs of R20 tessellated at 0.01 mm (about 1,000,000 chords);
// BM_ToolpathFromProgram interprets a 1,000,000-block program into it (the
// whole path of the screen without the VTK part, which
// bench/toolpath/VtkToolpathBench.cpp measures). Counters: segments and the
// bytes the geometry holds.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <string>

#include "cnc_core/language/Parser.h"
#include "cnc_core/machine/MachineConfigReader.h"
#include "cnc_core/toolpath/ToolpathBuilder.h"
#include "cnc_core/toolpath/ToolpathRun.h"
#include "resources/EmbeddedResources.h"

namespace {

using namespace mtc::core;

const MachineConfig& cell() {
    static const MachineConfig config =
        readMachineConfig(mtc::resources::find(mtc::resources::kDemoCellName)).config;
    return config;
}

void report(benchmark::State& state, const ToolpathGeometry& g) {
    state.counters["segments"] = static_cast<double>(g.scene.segmentCount());
    state.counters["MB"] = static_cast<double>(g.memoryBytes()) / 1e6;
}

void BM_ToolpathBuilderLines(benchmark::State& state) {
    DiagnosticList ignored;
    const ProcessAxes axes = ProcessAxes::build(*cell().process(0), ignored);
    Motion m;
    m.axisCount = axes.count();
    m.where.program = 1;
    ToolpathGeometry last;
    for (auto _ : state) {
        ToolpathBuilder builder(axes);
        m.end = {};
        for (int i = 0; i < 1'000'000; ++i) {
            m.start = m.end;
            m.type = i % 10 == 0 ? MotionType::Rapid : MotionType::Linear;
            m.end[0] = (i % 2 ? 100.0 : 0.0) + i * 1e-4;
            m.end[1] = i * 0.001;
            m.end[2] = -(i % 7);
            m.blockIndex = static_cast<std::uint32_t>(i);
            m.where.line = i + 1;
            builder.motion(m);
        }
        last = builder.take();
    }
    report(state, last);
}

void BM_ToolpathBuilderArcs(benchmark::State& state) {
    DiagnosticList ignored;
    const ProcessAxes axes = ProcessAxes::build(*cell().process(0), ignored);
    Motion m;
    m.axisCount = axes.count();
    m.type = MotionType::ArcCCW;
    m.planeAxis1 = 0;
    m.planeAxis2 = 1;
    ToolpathGeometry last;
    for (auto _ : state) {
        ToolpathBuilder builder(axes);
        for (int i = 0; i < 10'000; ++i) {
            m.start = {};
            m.start[0] = 20.0;
            m.start[2] = -i * 0.01;
            m.end = m.start;  // full circle
            m.center1 = m.center2 = 0.0;
            m.blockIndex = static_cast<std::uint32_t>(i);
            builder.motion(m);
        }
        last = builder.take();
    }
    report(state, last);
}

std::string straightProgram(int blocks) {
    std::string text;
    text.reserve(static_cast<std::size_t>(blocks) * 28);
    char line[96];
    for (int i = 0; i < blocks; ++i) {
        const int n = std::snprintf(line, sizeof line, "N%04d G1 X%.3f Y%.3f F1000\n", i % 10000,
                                    (i % 2) ? 100.0 : 0.0, (i % 5000) * 0.01);
        text.append(line, static_cast<std::size_t>(n));
    }
    return text + "N9999 M30\n";
}

void BM_ToolpathFromProgram(benchmark::State& state) {
    ParseOptions options;
    options.programNumber = 1;
    auto program = std::make_shared<Program>(parseProgram(straightProgram(1'000'000), options));
    program->number = 1;
    ProgramStore store;
    store.put(0, 1, program);
    ToolpathRunResult last;
    for (auto _ : state)
        last = buildToolpath(*cell().process(0), store, 1, {}, 2'000'000);
    report(state, last.geometry);
    state.SetLabel(last.complete ? "complete" : "NOT complete");
}

}  // namespace

BENCHMARK(BM_ToolpathBuilderLines)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ToolpathBuilderArcs)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ToolpathFromProgram)->Unit(benchmark::kMillisecond)->Iterations(2);
