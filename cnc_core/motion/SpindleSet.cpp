#include "cnc_core/motion/SpindleSet.h"

#include <algorithm>
#include <cmath>

namespace mtc::core::motion {

SpindleSet::SpindleSet(const MotionLimits& limits) : limits_(limits.spindles) {}

void SpindleSet::setSpeed(int spindle, double rpm) {
    if (!valid(spindle)) return;
    const SpindleLimit& l = limits_[static_cast<std::size_t>(spindle)];
    double speed = std::isfinite(rpm) ? std::fabs(rpm) : 0.0;
    if (l.maxSpeed > 0.0) speed = std::min(speed, l.maxSpeed);
    state_[static_cast<std::size_t>(spindle)].commanded = speed;
    ramping_ = true;
}

void SpindleSet::setRotation(int spindle, Rotation rotation) {
    if (!valid(spindle)) return;
    state_[static_cast<std::size_t>(spindle)].rotation = rotation;
    ramping_ = true;
}

void SpindleSet::stopAll() {
    for (State& s : state_)
        s.rotation = Rotation::Stopped;
    ramping_ = true;
}

double SpindleSet::target(int spindle) const {
    const State& s = state_[static_cast<std::size_t>(spindle)];
    switch (s.rotation) {
        case Rotation::Clockwise:
            return s.commanded;
        case Rotation::CounterClockwise:
            return -s.commanded;
        case Rotation::Stopped:
            break;
    }
    return 0.0;
}

void SpindleSet::advanceRamps(double seconds) {
    if (!(seconds > 0.0)) return;
    bool ramping = false;
    for (int i = 1; i <= 3; ++i) {
        State& s = state_[static_cast<std::size_t>(i)];
        const double goal = target(i);
        if (s.actual == goal) continue;
        const double rate = limits_[static_cast<std::size_t>(i)].acceleration;
        const double step = rate > 0.0 ? rate * seconds : std::fabs(goal - s.actual);
        s.actual =
            goal > s.actual ? std::min(goal, s.actual + step) : std::max(goal, s.actual - step);
        if (std::fabs(goal - s.actual) <= 1e-9 * std::max(1.0, std::fabs(goal))) s.actual = goal;
        ramping = ramping || s.actual != goal;
    }
    ramping_ = ramping;
}

double SpindleSet::actualSpeed(int spindle) const {
    return valid(spindle) ? state_[static_cast<std::size_t>(spindle)].actual : 0.0;
}

double SpindleSet::commandedSpeed(int spindle) const {
    return valid(spindle) ? state_[static_cast<std::size_t>(spindle)].commanded : 0.0;
}

SpindleSet::Rotation SpindleSet::rotation(int spindle) const {
    return valid(spindle) ? state_[static_cast<std::size_t>(spindle)].rotation : Rotation::Stopped;
}

bool SpindleSet::atSpeed(int spindle) const {
    return !valid(spindle) || state_[static_cast<std::size_t>(spindle)].actual == target(spindle);
}

double SpindleSet::secondsToSpeed(int spindle) const {
    if (atSpeed(spindle)) return 0.0;
    const double rate = limits_[static_cast<std::size_t>(spindle)].acceleration;
    const double gap =
        std::fabs(target(spindle) - state_[static_cast<std::size_t>(spindle)].actual);
    return rate > 0.0 ? gap / rate : 0.0;
}

}  // namespace mtc::core::motion
