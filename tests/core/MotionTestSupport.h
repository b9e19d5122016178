#pragma once
// Helpers of the trajectory engine tests: a three-axis machine with known
// limits, moves built by hand, the closed-form trapezoid / triangle profile
// the engine must match, and a driver loop that refills like the station.

#include <algorithm>
#include <cmath>
#include <functional>
#include <initializer_list>

#include "cnc_core/motion/TrajectoryEngine.h"

namespace mtc::test {

/// X, Y, Z linear: velocities in mm/min, accelerations in mm/s^2.
inline core::motion::MotionLimits threeAxes(double vx = 30000, double vy = 30000, double vz = 20000,
                                            double ax = 2500, double ay = 2500, double az = 2000) {
    core::ProcessConfig process;
    const char* names[] = {"X", "Y", "Z"};
    const double v[] = {vx, vy, vz}, a[] = {ax, ay, az};
    for (int i = 0; i < 3; ++i) {
        core::AxisConfig axis;
        axis.name = names[i];
        axis.definitions = {names[i]};
        axis.maxVelocity = v[i];
        axis.maxAcceleration = a[i];
        process.axes.push_back(axis);
    }
    return core::motion::MotionLimits::fromConfig(process);
}

inline core::Motion line(std::initializer_list<double> from, std::initializer_list<double> to,
                         double feed, bool rapid = false, const char* block = "N0001") {
    core::Motion m;
    m.type = rapid ? core::MotionType::Rapid : core::MotionType::Linear;
    m.axisCount = 3;
    std::copy(from.begin(), from.end(), m.start.begin());
    std::copy(to.begin(), to.end(), m.end.begin());
    m.feed = rapid ? 0.0 : feed;
    m.where.block = block;
    return m;
}

/// Arc in the X-Y plane around (cx, cy) from `from` to `to`.
inline core::Motion arc(std::initializer_list<double> from, std::initializer_list<double> to,
                        double cx, double cy, bool clockwise, double feed) {
    core::Motion m = line(from, to, feed);
    m.type = clockwise ? core::MotionType::ArcCW : core::MotionType::ArcCCW;
    m.planeAxis1 = 0;
    m.planeAxis2 = 1;
    m.center1 = cx;
    m.center2 = cy;
    return m;
}

/// Distance travelled after `t` seconds on a path of `length` from rest to
/// rest with cruise velocity `v` and acceleration `a` (trapezoid, or
/// triangle when the path is too short), written independently of the engine.
inline double closedFormDistance(double length, double v, double a, double t) {
    double peak = v, ta = v / a;
    if (v * v / a > length) {  // triangle
        peak = std::sqrt(length * a);
        ta = peak / a;
    }
    const double da = 0.5 * a * ta * ta;
    const double cruise = (length - 2 * da) / peak;
    const double total = 2 * ta + cruise;
    if (t <= 0) return 0.0;
    if (t <= ta) return 0.5 * a * t * t;
    if (t <= ta + cruise) return da + peak * (t - ta);
    if (t < total) {
        const double r = total - t;
        return length - 0.5 * a * r * r;
    }
    return length;
}

inline double closedFormDuration(double length, double v, double a) {
    if (v * v / a > length) return 2 * std::sqrt(length / a);
    return length / v + v / a;
}

/// Advances `engine` by `seconds` the way a station does: before every
/// advance (and whenever it returns early) `refill` may push more input.
inline void drive(core::motion::TrajectoryEngine& engine, double seconds,
                  const std::function<void()>& refill = {}) {
    double left = seconds;
    int guard = 0;
    while (left > 0 && ++guard < 10000000) {
        if (refill) refill();
        left -= engine.advance(left);
    }
}

/// Runs until the queue is empty (refilling as a station does); returns
/// the engine's time at the moment the last entry finished.
inline double runToIdle(core::motion::TrajectoryEngine& engine,
                        const std::function<void()>& refill = {}) {
    for (int guard = 0; guard < 10000000; ++guard) {
        if (refill) refill();
        if (engine.idle()) break;
        engine.advance(1e6);  // returns when an entry finishes
    }
    return engine.seconds();
}

}  // namespace mtc::test
