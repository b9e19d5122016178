// Cost of the trajectory engine (issue 16 §2): one panel tick of 20 ms of
// simulated time with the look-ahead queue kept full of short moves (lines
// and tangent arcs of 0.3 ... 1 mm at F6000 ... F12000, so a tick crosses
// several blocks), and the throughput of a run as fast as possible (moves per
// second through push + advance, what the CLI pays per block).
// Target: two stations at 50 Hz under 1 % of one core, i.e. one tick of one
// station under 100 us (report: real_time per tick x 100 ticks/s).
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "cnc_core/motion/TrajectoryEngine.h"

namespace {

using namespace mtc::core;
using namespace mtc::core::motion;

MotionLimits millLimits() {
    ProcessConfig process;
    const char* names[] = {"X", "Y", "Z"};
    for (int i = 0; i < 3; ++i) {
        AxisConfig axis;
        axis.name = names[i];
        axis.definitions = {names[i]};
        axis.maxVelocity = i == 2 ? 20000 : 30000;
        axis.maxAcceleration = i == 2 ? 2000 : 2500;
        process.axes.push_back(axis);
    }
    return MotionLimits::fromConfig(process);
}

/// Short moves along a smooth curve (0.5 degree turns: tangential, so the
/// path keeps its feed and a tick crosses many blocks), every 8th a tangent
/// arc, every 97th a corner of 90 degrees, feeds changing every 11 blocks.
std::vector<Motion> shortMoves() {
    std::vector<Motion> moves;
    double x = 0, y = 0, heading = 0;
    constexpr double kDegree = 3.14159265358979323846 / 180.0;
    for (int i = 0; i < 4000; ++i) {
        Motion m;
        m.axisCount = 3;
        m.start = {x, y, 0};
        const double step = 0.3 + (i % 8) * 0.1;
        m.feed = 6000 + 1000 * ((i / 11) % 7);
        heading += (i % 97 == 96) ? 90 * kDegree : 0.5 * kDegree;
        if (i % 8 == 7) {  // a tangent arc of 5 degrees to the left, radius 5 mm
            m.type = MotionType::ArcCCW;
            m.planeAxis1 = 0;
            m.planeAxis2 = 1;
            m.center1 = x - 5.0 * std::sin(heading);
            m.center2 = y + 5.0 * std::cos(heading);
            heading += 5 * kDegree;
            x = m.center1 + 5.0 * std::sin(heading);
            y = m.center2 - 5.0 * std::cos(heading);
        } else {
            m.type = MotionType::Linear;
            x += step * std::cos(heading);
            y += step * std::sin(heading);
        }
        m.end = {x, y, 0};
        m.blockIndex = static_cast<std::uint32_t>(i);
        moves.push_back(m);
    }
    return moves;
}

/// Pushes the moves over and over; each round continues where the last ended.
struct Feeder {
    const std::vector<Motion>& moves;
    std::size_t next = 0;
    std::uint64_t pushed = 0;
    double dx = 0.0, dy = 0.0;  ///< shift of the current round
    void refill(TrajectoryEngine& engine) {
        while (engine.wantsMore()) {
            Motion m = moves[next];
            for (auto* p : {&m.start, &m.end}) {
                (*p)[0] += dx;
                (*p)[1] += dy;
            }
            m.center1 += dx;
            m.center2 += dy;
            engine.pushMove(m, {});
            if (++next == moves.size()) {
                next = 0;
                dx = m.end[0];
                dy = m.end[1];
            }
            ++pushed;
        }
    }
};

/// One 20 ms tick of one station, queue refilled as the station does.
void BM_MotionTick20ms(benchmark::State& state) {
    static const std::vector<Motion> moves = shortMoves();
    TrajectoryEngine engine(millLimits());
    Feeder feeder{moves};
    feeder.refill(engine);
    for (int i = 0; i < 100; ++i) {  // steady state
        double left = 0.02;
        while (left > 0) {
            feeder.refill(engine);
            left -= engine.advance(left);
        }
    }
    const std::uint64_t startPushed = feeder.pushed;
    for (auto _ : state) {
        double left = 0.02;
        while (left > 0) {
            feeder.refill(engine);
            left -= engine.advance(left);
        }
        benchmark::DoNotOptimize(engine.position(0));
    }
    state.counters["blocks_per_tick"] =
        static_cast<double>(feeder.pushed - startPushed) / static_cast<double>(state.iterations());
    state.counters["core_share_2x50Hz_pct"] = benchmark::Counter(
        static_cast<double>(state.iterations()) / 1e4,  // time per tick x 100 ticks/s x 100 %
        benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_MotionTick20ms);

/// As fast as possible: every move pushed and run to its end (CLI-like).
void BM_MotionThroughput(benchmark::State& state) {
    static const std::vector<Motion> moves = shortMoves();
    TrajectoryEngine engine(millLimits());
    Feeder feeder{moves};
    for (auto _ : state) {
        feeder.refill(engine);
        engine.advance(1e6);  // returns when the front move is finished
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
    state.SetLabel("items/s = moves/s");
}
BENCHMARK(BM_MotionThroughput);

}  // namespace
