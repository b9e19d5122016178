// Cost of the time-based machine through the core's Station (issue 16 §2):
// both demo stations run endless programs of short moves (0.13 mm chords of
// a circle at F6000: about 15 blocks per 20 ms tick, the mill with its
// adaptive feed trend observing every feed move, as in the panel), and
//  - BM_CellTick20ms: one panel tick, Cell::advance(0.02) of both stations.
//    Target: under 1 % of one core at 50 Hz, i.e. one tick under 200 us
//    (counter core_share_50Hz_pct);
//  - BM_StationRunShortMoves: a program of 20,000 short moves on the mill
//    run as fast as possible (the CLI's loop): blocks/s through
//    interpreter + Station + SimulatedMachine + TrajectoryEngine.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "cnc_core/cell/Cell.h"
#include "cnc_core/machine/MachineConfigReader.h"
#include "resources/EmbeddedResources.h"

namespace {

using namespace mtc::core;

MachineConfig demo() {
    return readMachineConfig(mtc::resources::find(mtc::resources::kDemoCellName)).config;
}

/// `chords` G1 blocks around a circle of radius 20 mm in the plane of
/// `axis1` / `axis2` at F6000; `endless`: BRA back to the start, else M30.
std::string circleOfChords(int chords, const char* axis1, const char* axis2, bool endless) {
    std::string text = "N0001 G90 G1 " + std::string(axis1) + "20 " + axis2 + "0 F6000\n";
    if (endless) text += "N0002 .LOOP\n";
    char line[96];
    for (int i = 1; i <= chords; ++i) {
        const double angle = 2 * 3.14159265358979323846 * i / chords;
        std::snprintf(line, sizeof line, "N%04d %s%.4f %s%.4f\n", (i % 9000) + 3, axis1,
                      20 * std::cos(angle), axis2, 20 * std::sin(angle));
        text += line;
    }
    text += endless ? "N9998 BRA .LOOP\n" : "N9999 M30\n";
    return text;
}

/// Starts program 1 (`source`) on station `slot`.
void start(Cell& cell, int slot, const std::string& source) {
    cell.addProgram(slot, 1, "bench.nc", source);
    Station& station = cell.station(slot);
    if (!station.selectProgram(1) || !station.press(ControlKey::Start))
        std::fprintf(stderr, "bench: station %d did not start: %s\n", slot,
                     station.control().alarm().c_str());
}

void BM_CellTick20ms(benchmark::State& state) {
    Cell cell(demo());
    start(cell, 0, circleOfChords(1000, "X", "Y", true));
    start(cell, 1, circleOfChords(1000, "X", "Z", true));
    for (int i = 0; i < 200; ++i)  // steady state: queues full, trend filling
        cell.advance(0.02);
    const std::uint64_t before = cell.station(0).runBlocks() + cell.station(1).runBlocks();
    for (auto _ : state) {
        cell.advance(0.02);
        benchmark::DoNotOptimize(cell.station(0).machine().position(0));
    }
    const std::uint64_t blocks = cell.station(0).runBlocks() + cell.station(1).runBlocks() - before;
    state.counters["blocks_per_tick"] =
        static_cast<double>(blocks) / static_cast<double>(state.iterations());
    state.counters["core_share_50Hz_pct"] = benchmark::Counter(
        static_cast<double>(state.iterations()) / 5e3,  // time per tick x 50 ticks/s x 100 %
        benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    if (!cell.station(0).running() || !cell.station(1).running())
        state.SkipWithError("a station stopped");
}
BENCHMARK(BM_CellTick20ms)->Unit(benchmark::kMicrosecond);

void BM_StationRunShortMoves(benchmark::State& state) {
    const std::string source = circleOfChords(20000, "X", "Y", false);
    const MachineConfig config = demo();
    std::uint64_t blocks = 0;
    for (auto _ : state) {
        state.PauseTiming();
        Cell cell(config);
        start(cell, 0, source);
        state.ResumeTiming();
        Station& mill = cell.station(0);
        while (mill.busy())
            mill.advance(1e9, std::uint64_t{1} << 20);
        blocks += mill.runBlocks();
        benchmark::DoNotOptimize(mill.machine().seconds());
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(blocks));
    state.SetLabel("items/s = blocks/s");
}
BENCHMARK(BM_StationRunShortMoves)->Unit(benchmark::kMillisecond);

}  // namespace
