// The engine's run over several entries (docs/decisions/motion.md MOT-027):
// TrajectoryEngine::advanceOver gives, bit for bit, what a driver gets that
// calls advance() again after every finished entry; the queue's locations
// come back as they were queued.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "MotionTestSupport.h"

namespace {

using namespace mtc::core;
using namespace mtc::core::motion;
using namespace mtc::test;

/// A spindle on top of the three axes, for actions that wait for it.
MotionLimits limitsWithSpindle() {
    MotionLimits limits = threeAxes();
    limits.spindles[1].present = true;
    limits.spindles[1].maxSpeed = 6000.0;
    limits.spindles[1].acceleration = 3000.0;
    return limits;
}

/// The same random mix of lines, arcs, corners, dwells and actions every
/// time for `seed`; `entries` numbers the entries' blocks (and lines).
struct QueueFiller {
    explicit QueueFiller(unsigned seed) : random(seed) {}

    void push(TrajectoryEngine& engine) {
        const std::uint64_t before = engine.itemsQueued();
        pushOne(engine);
        if (engine.itemsQueued() > before) queuedBlocks.push_back("N" + std::to_string(entries));
    }

    /// The block the engine shows (currentLocation): the entry being
    /// executed, or the last one finished while it stands or waits.
    std::string shownBlock(const TrajectoryEngine& engine) const {
        const std::uint64_t done = engine.itemsDone();
        if (!engine.idle() && !engine.atBlockStop()) return queuedBlocks[done];
        return done > 0 ? queuedBlocks[done - 1] : std::string();
    }

    void pushOne(TrajectoryEngine& engine) {
        ++entries;
        const int kind = static_cast<int>(random() % 10);
        SourceLocation where{1, "N" + std::to_string(entries), entries, 0};
        if (kind == 0) return engine.pushDwell(where, 0.01 * static_cast<double>(random() % 5));
        if (kind == 1) {
            MachineAction action;
            action.spindle = 1;
            action.speed = static_cast<double>(random() % 4000);
            action.rotation = 0;
            action.waitForSpindle = random() % 2 == 0;
            action.stopsPath = random() % 2 == 0;
            action.tag = static_cast<std::uint32_t>(entries);
            return engine.pushAction(where, action);
        }
        const double x = x0 + static_cast<double>(random() % 200) / 10.0 - 10.0;
        const bool isArc = kind < 4;  // a half circle to (x, y0)
        const double y = isArc ? y0 : y0 + static_cast<double>(random() % 200) / 10.0 - 10.0;
        const double feed = 200.0 + static_cast<double>(random() % 20000);
        Motion m = isArc ? arc({x0, y0, 0}, {x, y, 0}, (x0 + x) / 2, y0, kind == 2, feed)
                         : line({x0, y0, 0}, {x, y, 0}, feed, kind == 9);
        m.where = where;
        engine.pushMove(m, {kind == 5, false});
        x0 = x;
        y0 = y;
    }

    std::mt19937 random;
    int entries = 0;
    std::vector<std::string> queuedBlocks;  ///< by queue item number
    double x0 = 0.0, y0 = 0.0;
};

/// What a driver sees of the engine after a call.
struct Seen {
    double used = 0.0;
    std::vector<double> finishedAt;
    double busy = 0.0, seconds = 0.0, velocity = 0.0, x = 0.0, y = 0.0;
    std::uint64_t done = 0;
    std::vector<std::uint32_t> reached;
    bool operator==(const Seen& o) const {
        return used == o.used && finishedAt == o.finishedAt && busy == o.busy &&
               seconds == o.seconds && velocity == o.velocity && x == o.x && y == o.y &&
               done == o.done && reached == o.reached;
    }
};

void look(TrajectoryEngine& engine, Seen& seen) {
    seen.busy = engine.busySeconds();
    seen.seconds = engine.seconds();
    seen.velocity = engine.velocity();
    seen.x = engine.position(0);
    seen.y = engine.position(1);
    seen.done = engine.itemsDone();
    seen.reached = engine.takeReached();
}

/// The driver's loop advanceOver replaces (SimulatedMachine::advance before MOT-027).
Seen loopOfAdvance(TrajectoryEngine& engine, double seconds, std::size_t keep) {
    Seen seen;
    double left = seconds;
    while (left > 0.0) {
        const std::uint64_t before = engine.itemsDone();
        const double used = engine.advance(left);
        left = used >= left ? 0.0 : left - used;
        if (engine.itemsDone() != before) seen.finishedAt.push_back(engine.busySeconds());
        if (engine.idle() || engine.queuedCount() < keep) break;
    }
    seen.used = seconds - left;
    look(engine, seen);
    return seen;
}

Seen overEntries(TrajectoryEngine& engine, double seconds, std::size_t keep) {
    Seen seen;
    seen.used = engine.advanceOver(seconds, keep, seen.finishedAt);
    look(engine, seen);
    return seen;
}

TEST(MotionAdvanceOver, GivesTheDriversLoopBitForBit) {
    std::uint64_t finished = 0, queued = 0, callsOverSeveral = 0;
    for (unsigned seed = 1; seed <= 40; ++seed) {
        TrajectoryEngine a(limitsWithSpindle()), b(limitsWithSpindle());
        a.setBatch(seed % 2 == 0 ? 16 : 0);
        b.setBatch(a.batch());
        QueueFiller fillA(seed), fillB(seed);
        const double ticks[] = {1e9, 0.02, 0.3};  // the CLI's call, panel ticks
        const double tick = ticks[seed % 3];
        for (int call = 0; call < 100000; ++call) {
            while (a.wantsMore() && fillA.entries < 300) {
                a.beginBlock();
                fillA.push(a);
                b.beginBlock();
                fillB.push(b);
            }
            const std::size_t keep = a.wantsMore() ? 0 : a.lookAhead();
            if (call == 20) {  // the operator: overrides and single block
                a.setFeedOverride(70);
                b.setFeedOverride(70);
                a.setStopAtBlockEnds(seed % 4 == 1);
                b.setStopAtBlockEnds(seed % 4 == 1);
            }
            if (a.atBlockStop()) {
                a.continueAfterBlockStop();
                b.continueAfterBlockStop();
            }
            const Seen expected = loopOfAdvance(a, tick, keep);
            const Seen got = overEntries(b, tick, keep);
            ASSERT_TRUE(expected == got) << "seed " << seed << " call " << call;
            ASSERT_EQ(a.currentLocation().block, b.currentLocation().block);
            ASSERT_EQ(b.currentLocation().block, fillB.shownBlock(b)) << seed << " " << call;
            finished += got.finishedAt.size();
            callsOverSeveral += got.finishedAt.size() > 1;
            if (a.idle() && fillA.entries >= 300) break;
        }
        EXPECT_TRUE(a.idle() && b.idle()) << "seed " << seed;
        queued += a.itemsQueued();
    }
    EXPECT_EQ(finished, queued) << "every entry of every run finished";
    EXPECT_GT(queued, 11000u) << "of 12,000 (moves of length 0 are not queued)";
    EXPECT_GT(callsOverSeveral, 100u);
}

TEST(MotionAdvanceOver, StopsOnceFewerThanKeepAreQueued) {
    TrajectoryEngine engine(threeAxes());
    for (int i = 0; i < 10; ++i)
        engine.pushMove(line({10.0 * i, 0, 0}, {10.0 * (i + 1), 0, 0}, 6000, false), {});
    std::vector<double> finishedAt;
    engine.advanceOver(1e9, 7, finishedAt);
    EXPECT_EQ(engine.queuedCount(), 6u);
    EXPECT_EQ(finishedAt.size(), 4u);
    EXPECT_EQ(finishedAt.back(), engine.busySeconds());
    engine.advanceOver(1e9, 0, finishedAt);
    EXPECT_TRUE(engine.idle());
    EXPECT_EQ(finishedAt.size(), 10u);
}

TEST(QueuedLocation, GivesBackWhatItWasAssigned) {
    const std::string texts[] = {"",
                                 "N0012",
                                 "N0012:0001",
                                 "N2147483647:2147483647",
                                 "N2147483647:21474836470",
                                 std::string(300, 'x'),
                                 "N0003"};
    QueuedLocation location;
    int n = 0;
    for (const std::string& text : texts) {
        const SourceLocation where{++n, text, 10 * n, n % 3};
        location.assign(where);
        const QueuedLocation copy = location;
        for (const QueuedLocation& l : {location, copy}) {
            const SourceLocation back = l.location();
            EXPECT_EQ(back.program, where.program);
            EXPECT_EQ(back.block, text);
            EXPECT_EQ(back.line, where.line);
            EXPECT_EQ(back.column, where.column);
        }
    }
    QueuedLocation other;
    other.assign({1, "N0001", 30, 0});
    EXPECT_TRUE(other.sameBlock(location) == (location.program() == 1 && location.line() == 30));
}

}  // namespace
