// Material removal (issue 19 §3, D-020): a 10,000-block mill program must be
// simulated to the finished part in under 2 s at 0.2 mm resolution on one
// core. BM_RemovalMill10k interprets and cuts a roughing program of 10,000
// blocks (zig-zag lines across the demo stock joined by half circles, 0.5 mm
// deeper each layer, cutter T10 of radius 8) into the 100 x 60 mm block;
// BM_RemovalMillArcs10k every block cutting: the generated closed-motion
// program (lines and R10 quarter circles, bench/BenchPrograms.h) 1 mm deep
// with the R8 cutter, so each block sweeps about 16 mm wide through the
// part; BM_RemovalStl writes the roughed part's binary STL into memory;
// BM_RemovalLathe10k turns 10,000 blocks of passes on the demo bar;
// BM_RemovalCylinderG32_10k mills a helical groove of 10,000 G32 blocks into
// the bar's developed jacket (D-027).
// Counters: cells, removed mm^3.
// The restart's way back against the part (D-021): BM_ReentryCheckMill10k*
// time checkRestartReentry at 0.2 mm for a restart of the 10,000-block
// roughing program at its block 9,000 (the part cut up to there, then the
// ADJUST / REPOS moves swept through it): Clear goes over the top (no
// collision), Through straight through the last layer (one collision,
// located by bisection). Counters: blocks, moves, collisions, removed mm^3.
// The part cut live (TP-027): BM_StationMill10k runs the roughing program on
// a station in simulated time (ticks of 10 s) without, BM_LiveCutMill10k
// with the live cut (the difference is its cost); BM_LiveCutStart1M is the
// blank a Start makes of the 1,000,000-block closed-motion program (no
// window: the scan of its text and the configuration's block).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <optional>
#include <string>

#include "BenchPrograms.h"
#include "cnc_core/cell/Cell.h"
#include "cnc_core/language/Parser.h"
#include "cnc_core/machine/MachineConfigReader.h"
#include "cnc_core/removal/LiveCut.h"
#include "cnc_core/removal/PartStl.h"
#include "cnc_core/removal/ReentryCollisions.h"
#include "cnc_core/removal/RemovalRun.h"
#include "cnc_core/restart/RestartSequence.h"
#include "resources/EmbeddedResources.h"

namespace {

using namespace mtc::core;
using namespace mtc::core::removal;

const MachineConfig& cell() {
    static const MachineConfig config =
        readMachineConfig(mtc::resources::find(mtc::resources::kDemoCellName)).config;
    return config;
}

/// Roughing of the demo mill's stock (G54: X0..100, Y0..60, Z-12..0).
std::string millProgram(int blocks) {
    std::string text = "N0001 T10 G17 G90 G54 G0 X-10 Y0 Z2\nN0002 S3000 M3\n";
    char line[96];
    int n = 3;
    const auto add = [&](const char* format, double a, double b) {
        const int size = std::snprintf(line, sizeof line, format, n++ % 10000, a, b);
        text.append(line, static_cast<std::size_t>(size));
    };
    for (int layer = 0; n < blocks; ++layer) {
        const double z = -std::min(0.5 * (layer + 1), 11.5);
        add("N%04d G1 X%.3f Z%.3f F2000\n", -10.0, z);
        for (int row = 0; row < 12 && n < blocks; ++row) {
            const bool right = row % 2 == 0;
            add("N%04d G1 X%.3f Y%.3f\n", right ? 110.0 : -10.0, row * 5.0);
            if (n >= blocks) break;
            // A half circle to the next row (centre absolute, I J).
            const int size = std::snprintf(line, sizeof line, "N%04d G%d X%.3f Y%.3f I%.3f J%.3f\n",
                                           n++ % 10000, right ? 3 : 2, right ? 110.0 : -10.0,
                                           row * 5.0 + 5.0, right ? 110.0 : -10.0, row * 5.0 + 2.5);
            text.append(line, static_cast<std::size_t>(size));
        }
    }
    return text + "N9999 M30\n";
}

/// Passes along the demo bar (G54 Z255.5: Z-115..2, radius 40): 0.5 mm
/// deeper each pass, back out with a rapid.
std::string latheProgram(int blocks) {
    std::string text = "N0001 T1 G18 G90 G54 G0 X45 Z3\n";
    char line[96];
    for (int n = 2, pass = 0; n + 3 < blocks; ++pass) {
        const double x = 39.5 - 0.5 * (pass % 60);
        const double z = -10.0 - (pass % 100);
        const int size = std::snprintf(
            line, sizeof line, "N%04d G1 X%.3f F300\nN%04d Z%.3f\nN%04d X45\nN%04d G0 Z3\n",
            n % 10000, x, (n + 1) % 10000, z, (n + 2) % 10000, (n + 3) % 10000);
        text.append(line, static_cast<std::size_t>(size));
        n += 4;
    }
    return text + "N9999 M30\n";
}

/// A helical groove on the demo bar under G32 (D-027): T9 (R4.85) 2 mm
/// deep, 0.5 mm of circumference and 0.03 mm along the axis per block,
/// every tenth block a 0.2 mm step round only (about 3.5 turns per 2,000
/// blocks, the axial position kept on the bar).
std::string cylinderProgram(int blocks) {
    std::string text =
        "N0001 T9 G18 G90 G54 G0 X45 Z-30\nN0002 G0 C0\nN0003 G20 Z0 C0 X0\nN0004 G32 RI 40\n"
        "N0005 G0 G56 Y1 0 Z1 250\nN0006 G1 X38 F300\n";
    char line[96];
    double y = 0.0, z = 250.0;
    for (int n = 7; n < blocks - 4; ++n) {
        if (n % 10 == 9) {
            y += 0.2;
        } else {
            y += 0.5;
            z -= 0.03;
            if (z < 150.0) z = 250.0;
        }
        const int size =
            std::snprintf(line, sizeof line, "N%04d G1 Y1 %.3f Z1 %.3f\n", n % 10000, y, z);
        text.append(line, static_cast<std::size_t>(size));
    }
    return text + "N9996 G0 X45\nN9997 G30\nN9998 G18\nN9999 M30\n";
}

ProgramStore storeWith(int process, const std::string& source) {
    ParseOptions options;
    options.programNumber = 1;
    auto program = std::make_shared<Program>(parseProgram(source, options));
    program->number = 1;
    ProgramStore store;
    store.put(process, 1, program);
    return store;
}

void report(benchmark::State& state, const RemovalRunResult& r) {
    state.counters["cells"] = r.part ? static_cast<double>(r.part->cells()) : 0.0;
    state.counters["removed_mm3"] = r.part ? r.part->removedVolume() : 0.0;
    state.counters["blocks"] = static_cast<double>(r.blocks);
    state.SetLabel(r.complete && !r.diagnostics.hasErrors()
                       ? "complete"
                       : "NOT complete: " + (r.diagnostics.empty()
                                                 ? std::string()
                                                 : r.diagnostics.items().front().message));
}

/// Simulates program 1 of `process` at 0.2 mm once per iteration.
void simulateEach(benchmark::State& state, const ProgramStore& store, int process = 0) {
    RemovalSettings settings;
    settings.resolution = 0.2;
    RemovalRunResult last;
    for (auto _ : state)
        last = simulateRemoval(*cell().process(process), store, 1, settings);
    report(state, last);
}

void BM_RemovalMill10k(benchmark::State& state) {
    simulateEach(state, storeWith(0, millProgram(10'000)));
}

void BM_RemovalMillArcs10k(benchmark::State& state) {
    const ProgramStore store =
        storeWith(0, "N0001 T10 G17 G90 G54 G0 X0 Y0 Z2\nN0002 G1 Z-1 F100\n" +
                         mtc::bench::generateClosedMotionProgram(10'000));
    simulateEach(state, store);
}

void BM_RemovalCylinderG32_10k(benchmark::State& state) {
    simulateEach(state, storeWith(1, cylinderProgram(10'000)), 1);
}

void BM_RemovalStl(benchmark::State& state) {
    const ProgramStore store = storeWith(0, millProgram(10'000));
    RemovalSettings settings;
    settings.resolution = 0.2;
    const RemovalRunResult r = simulateRemoval(*cell().process(0), store, 1, settings);
    std::size_t bytes = 0;
    for (auto _ : state)
        bytes = partStl(*r.part).size();
    state.counters["MB"] = static_cast<double>(bytes) / 1e6;
}

/// A restart of the 10,000-block roughing program at its block 9,000 on the
/// demo mill's station, the computing process run to the target; program
/// 99's ADJUST / REPOS take the tool from beside the part (work X50 Y70,
/// `depth`) back to the re-entry point: over the top (`overTheTop`) or
/// straight through what is left of the part.
struct ReentryFixture {
    ReentryFixture(bool overTheTop, double depth)
        : restartCell(cell()), station(restartCell.station(restartCell.slotOfProcess(0))) {
        restartCell.store().put(0, 1, storeWith(0, millProgram(10'000)).find(0, 1));
        const std::string library = std::string("N0000 M30\nN0001 .ADJUST ") +
                                    (overTheTop ? "G0 G54 Z20\n" : "@150=0\n") +
                                    "N0002 .REPOS G77 X0 Y0 F2000\nN0003 G77 Z0 F500 RTS\n";
        ParseOptions options;
        options.programNumber = 99;
        auto adjust = std::make_shared<Program>(parseProgram(library, options));
        adjust->number = 99;
        restartCell.store().put(0, 99, adjust);
        // G54 of the demo mill: machine = work - (150, 80, 120).
        station.interpreter().takeMachinePositions({50.0 - 150.0, 70.0 - 80.0, depth - 120.0});
        RestartSelection selection;
        selection.mainProgram = 1;
        selection.target = {1, 9'000};
        DiagnosticList refused;
        ready = station.restartSequence().accept(selection, refused, 100'000'000);
        while (ready && station.restartSequence().phase() != RestartPhase::TargetReached)
            ready = station.restartSequence().advance(1'000'000) == RestartPhase::TargetReached ||
                    station.restartSequence().active();
    }
    Cell restartCell;
    Station& station;
    bool ready = false;
};

/// checkRestartReentry at 0.2 mm once per iteration: the part cut up to
/// the target, then every ADJUST / REPOS move swept through it.
void checkEach(benchmark::State& state, bool overTheTop, double depth) {
    ReentryFixture f(overTheTop, depth);
    if (!f.ready) {
        state.SkipWithError("the restart does not reach its target");
        return;
    }
    RemovalSettings settings;
    settings.resolution = 0.2;
    std::optional<ReentryCheck> check;
    for (auto _ : state)
        check = checkRestartReentry(f.station.restart(), f.station.interpreter(),
                                    f.restartCell.store(), settings);
    if (!check || !check->checked) {
        state.SkipWithError("the way back was not checked");
        return;
    }
    state.counters["blocks"] = static_cast<double>(check->blocks);
    state.counters["moves"] = static_cast<double>(check->moves);
    state.counters["collisions"] = static_cast<double>(check->collisions.size());
    state.counters["removed_mm3"] = check->removedVolume;
}

void BM_ReentryCheckMill10kClear(benchmark::State& state) {
    checkEach(state, true, -2.0);
}

void BM_ReentryCheckMill10kThrough(benchmark::State& state) {
    checkEach(state, false, -11.8);
}

void BM_RemovalLathe10k(benchmark::State& state) {
    const ProgramStore store = storeWith(1, latheProgram(10'000));
    simulateEach(state, store, 1);
}

}  // namespace

/// Runs program 1 of the mill to its end on a fresh cell per iteration.
void runOnStation(benchmark::State& state, const std::string& text, bool live) {
    double removed = 0.0;
    bool ended = true;
    for (auto _ : state) {
        state.PauseTiming();
        Cell station(cell());
        station.addProgram(0, 1, "bench.nc", text);
        Station& mill = station.station(0);
        mill.setLiveCutting(live);
        mill.selectProgram(1);
        state.ResumeTiming();
        mill.press(ControlKey::Start);
        for (int tick = 0; tick < 100'000 && mill.busy(); ++tick)
            mill.advance(10.0);
        ended = ended && mill.runStatus() == RunStatus::Ended;
        removed = mill.liveCut().part() ? mill.liveCut().part()->removedVolume() : 0.0;
    }
    state.counters["removed_mm3"] = removed;
    state.SetLabel(ended ? "ended" : "NOT ended");
}

void BM_StationMill10k(benchmark::State& state) {
    runOnStation(state, millProgram(10'000), false);
}

void BM_LiveCutMill10k(benchmark::State& state) {
    runOnStation(state, millProgram(10'000), true);
}

void BM_LiveCutStart1M(benchmark::State& state) {
    const ProgramStore store = storeWith(0, mtc::bench::generateClosedMotionProgram(1'000'000));
    DiagnosticList ignored;
    LiveCut cut(ProcessAxes::build(*cell().process(0), ignored));
    for (auto _ : state)
        cut.begin(*cell().process(0), store, 1, nullptr);
    state.counters["cells"] = cut.part() ? static_cast<double>(cut.part()->cells()) : 0.0;
}

BENCHMARK(BM_RemovalMill10k)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RemovalMillArcs10k)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RemovalCylinderG32_10k)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RemovalStl)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RemovalLathe10k)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReentryCheckMill10kClear)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReentryCheckMill10kThrough)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StationMill10k)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LiveCutMill10k)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LiveCutStart1M)->Unit(benchmark::kMillisecond);
