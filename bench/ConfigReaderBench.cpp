// Speed of the machine configuration reader on cells with many tools (issue
// 22 §2: "a file with many tools is read in quadratic time; a 50 MB file
// takes over 10 s"). BM_ReadMachineConfigTools/N reads the demo cell with N
// tools in process 0; the time per tool must stay flat as N grows (linear).
// scripts/bench-config.sh times `mtc200-cli check` on a 50 MB file.
#include <benchmark/benchmark.h>

#include <string>

#include "cnc_core/machine/MachineConfigReader.h"
#include "resources/EmbeddedResources.h"

namespace {

/// The demo cell with its tools list replaced by `tools` generated tools.
std::string cellWithTools(int tools) {
    std::string demo(mtc::resources::find(mtc::resources::kDemoCellName));
    const std::size_t from = demo.find("T1 = ");
    const std::size_t to = demo.find("\n\n", from);
    std::string list;
    list.reserve(static_cast<std::size_t>(tools) * 48);
    for (int t = 1; t <= tools; ++t)
        list += "T" + std::to_string(t) + " = radius " + std::to_string(t % 50) + ".5 length " +
                std::to_string(60 + t % 100) + " name tool" + std::to_string(t) + "\n";
    return demo.substr(0, from) + list + demo.substr(to + 1);
}

void BM_ReadMachineConfigTools(benchmark::State& state) {
    const std::string text = cellWithTools(static_cast<int>(state.range(0)));
    mtc::core::MachineConfigReadOptions options;
    options.requireEndMarker = true;
    for (auto _ : state) {
        auto result = mtc::core::readMachineConfig(text, options);
        if (!result.ok()) state.SkipWithError("the generated cell was refused");
        benchmark::DoNotOptimize(result);
    }
    state.SetBytesProcessed(static_cast<int64_t>(state.iterations()) *
                            static_cast<int64_t>(text.size()));
    state.counters["tools"] = static_cast<double>(state.range(0));
    state.counters["ns_per_tool"] = benchmark::Counter(
        static_cast<double>(state.range(0)),
        benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_ReadMachineConfigTools)
    ->Arg(1000)
    ->Arg(10000)
    ->Arg(100000)
    ->Arg(1000000)
    ->Unit(benchmark::kMillisecond);

}  // namespace
