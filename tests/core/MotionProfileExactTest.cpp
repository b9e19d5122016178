// The machine's per-move shortcuts of MOT-026 give the bits of the former
// code: a velocity profile whose phase starts are worked out when sampled
// (not when planned), and spindles that skip their ramps while at speed.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "MotionTestSupport.h"
#include "cnc_core/motion/SegmentProfile.h"
#include "cnc_core/motion/SpindleSet.h"

namespace {

using namespace mtc::core;
using namespace mtc::core::motion;

/// SegmentProfile as it was before MOT-026: every phase stores its start
/// position and velocity when it is added.
class FormerProfile {
  public:
    void plan(double s0, double v0, double length, double cap, double vEnd, double a) {
        count_ = 0;
        duration_ = 0.0;
        s0_ = s0;
        v0_ = std::max(0.0, v0);
        v0 = v0_;
        const double end = s0 + std::max(0.0, length);
        if (!(length > 0.0)) return finish(end, v0, true);
        if (!(a > 0.0)) a = 1e-9;
        const double twoA = 2.0 * a;
        if (!(cap > 0.0)) {
            if (v0 * v0 >= twoA * length) {
                const double v = std::sqrt(std::max(0.0, v0 * v0 - twoA * length));
                addPhase((v0 - v) / a, -a);
                return finish(end, v, true);
            }
            addPhase(v0 / a, -a);
            return finish(s0 + v0 * v0 / twoA, 0.0, false);
        }
        const double v1 = std::clamp(vEnd, 0.0, cap);
        const double d1 = std::fabs(cap * cap - v0 * v0) / twoA;
        const double d3 = (cap * cap - v1 * v1) / twoA;
        if (v0 * v0 - v1 * v1 >= twoA * length) {
            const double v = std::sqrt(std::max(0.0, v0 * v0 - twoA * length));
            addPhase((v0 - v) / a, -a);
            return finish(end, v, true);
        }
        if (d1 + d3 <= length) {
            addPhase(std::fabs(cap - v0) / a, v0 <= cap ? a : -a);
            addPhase((length - d1 - d3) / cap, 0.0);
            addPhase((cap - v1) / a, -a);
            return finish(end, v1, true);
        }
        if (v1 * v1 - v0 * v0 >= twoA * length) {
            const double v = std::sqrt(v0 * v0 + twoA * length);
            addPhase((v - v0) / a, a);
            return finish(end, v, true);
        }
        const double peak = std::sqrt((twoA * length + v0 * v0 + v1 * v1) / 2.0);
        addPhase((peak - v0) / a, a);
        addPhase((peak - v1) / a, -a);
        finish(end, v1, true);
    }
    void sample(double t, double& s, double& v) const {
        if (!(t < duration_)) {
            s = endPosition_;
            v = reachesEnd_ ? endVelocity_ : 0.0;
            return;
        }
        double start = 0.0;
        for (int i = 0; i < count_; ++i) {
            const Phase& p = phases_[static_cast<std::size_t>(i)];
            if (t < start + p.duration || i == count_ - 1) {
                const double dt = std::min(t - start, p.duration);
                s = p.s + p.v * dt + 0.5 * p.acceleration * dt * dt;
                v = std::max(0.0, p.v + p.acceleration * dt);
                s = std::min(s, endPosition_);
                return;
            }
            start += p.duration;
        }
        s = s0_;
        v = v0_;
    }
    double duration_ = 0.0, endVelocity_ = 0.0, endPosition_ = 0.0;
    bool reachesEnd_ = true;

  private:
    struct Phase {
        double duration = 0.0, acceleration = 0.0, s = 0.0, v = 0.0;
    };
    void addPhase(double duration, double acceleration) {
        if (!(duration > 0.0)) return;
        Phase& p = phases_[static_cast<std::size_t>(count_)];
        if (count_ == 0) {
            p.s = s0_;
            p.v = v0_;
        } else {
            const Phase& q = phases_[static_cast<std::size_t>(count_ - 1)];
            p.s = q.s + q.v * q.duration + 0.5 * q.acceleration * q.duration * q.duration;
            p.v = std::max(0.0, q.v + q.acceleration * q.duration);
        }
        p.duration = duration;
        p.acceleration = acceleration;
        duration_ += duration;
        ++count_;
    }
    void finish(double endPosition, double endVelocity, bool reachesEnd) {
        endPosition_ = endPosition;
        endVelocity_ = endVelocity;
        reachesEnd_ = reachesEnd;
    }
    std::array<Phase, 3> phases_{};
    int count_ = 0;
    double s0_ = 0.0, v0_ = 0.0;
};

TEST(SegmentProfileExact, SampledPhaseStartsGiveTheBitsOfStoredOnes) {
    std::mt19937_64 random(26);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int plan = 0; plan < 20000; ++plan) {
        // Trapezoids, triangles, braking from above the cap, cap 0 (hold),
        // starts mid-segment, the end velocity above and below the cap.
        const double s0 = plan % 3 == 0 ? 0.0 : 50.0 * unit(random);
        const double v0 = plan % 4 == 0 ? 0.0 : 300.0 * unit(random);
        const double length = plan % 17 == 0 ? 0.0 : 0.001 + 80.0 * unit(random);
        const double cap = plan % 11 == 0 ? 0.0 : 1.0 + 250.0 * unit(random);
        const double vEnd = plan % 5 == 0 ? 0.0 : 300.0 * unit(random);
        const double a = 100.0 + 5000.0 * unit(random);
        SegmentProfile now;
        FormerProfile former;
        now.plan(s0, v0, length, cap, vEnd, a);
        former.plan(s0, v0, length, cap, vEnd, a);
        ASSERT_EQ(now.duration(), former.duration_) << plan;
        ASSERT_EQ(now.endVelocity(), former.endVelocity_) << plan;
        ASSERT_EQ(now.endPosition(), former.endPosition_) << plan;
        ASSERT_EQ(now.reachesEnd(), former.reachesEnd_) << plan;
        for (int k = 0; k <= 40; ++k) {
            const double t = now.duration() * k / 37.0;  // beyond the end too
            double s = -1.0, v = -1.0, fs = -2.0, fv = -2.0;
            now.sample(t, s, v);
            former.sample(t, fs, fv);
            ASSERT_EQ(s, fs) << plan << " " << t;
            ASSERT_EQ(v, fv) << plan << " " << t;
        }
    }
}

MotionLimits withSpindles() {
    MotionLimits limits = mtc::test::threeAxes();
    for (std::size_t i = 1; i <= 3; ++i)
        limits.spindles[i] = {true, 4000.0, 500.0 * static_cast<double>(i)};
    return limits;
}

/// The former SpindleSet::advance(): every spindle's ramp every time.
struct FormerSpindle {
    double commanded = 0.0, actual = 0.0;
    int rotation = 0;  // 0 stopped, 1 cw, -1 ccw
    void advance(double seconds, double rate) {
        if (!(seconds > 0.0)) return;
        const double goal = rotation * commanded;
        if (actual == goal) return;
        const double step = rate > 0.0 ? rate * seconds : std::fabs(goal - actual);
        actual = goal > actual ? std::min(goal, actual + step) : std::max(goal, actual - step);
        if (std::fabs(goal - actual) <= 1e-9 * std::max(1.0, std::fabs(goal))) actual = goal;
    }
};

TEST(SpindleSetExact, RampsSkippedAtSpeedGiveTheSameSpeeds) {
    const MotionLimits limits = withSpindles();
    SpindleSet spindles(limits);
    std::array<FormerSpindle, 4> former{};
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int step = 0; step < 20000; ++step) {
        const int spindle = 1 + static_cast<int>(random() % 3);
        auto& f = former[static_cast<std::size_t>(spindle)];
        switch (random() % 40) {  // mostly time passing, now and then a command
            case 0:
                spindles.setSpeed(spindle, 3000.0 * unit(random));
                f.commanded = spindles.commandedSpeed(spindle);
                break;
            case 1:
                spindles.setRotation(spindle, SpindleSet::Rotation::Clockwise);
                f.rotation = 1;
                break;
            case 2:
                spindles.setRotation(spindle, SpindleSet::Rotation::CounterClockwise);
                f.rotation = -1;
                break;
            case 3:
                spindles.setRotation(spindle, SpindleSet::Rotation::Stopped);
                f.rotation = 0;
                break;
            case 4:
                spindles.stopAll();
                for (auto& g : former)
                    g.rotation = 0;
                break;
            default:
                break;
        }
        const double seconds = step % 7 == 0 ? 0.0 : 0.5 * unit(random);
        spindles.advance(seconds);
        for (std::size_t i = 1; i <= 3; ++i) {
            former[i].advance(seconds, limits.spindles[i].acceleration);
            ASSERT_EQ(spindles.actualSpeed(static_cast<int>(i)), former[i].actual)
                << step << " S" << i;
            ASSERT_EQ(spindles.atSpeed(static_cast<int>(i)),
                      former[i].actual == former[i].rotation * former[i].commanded);
        }
    }
}

}  // namespace
