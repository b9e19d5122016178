#include "cnc_core/motion/SegmentProfile.h"

#include <algorithm>
#include <cmath>

namespace mtc::core::motion {

void SegmentProfile::finish(double endPosition, double endVelocity, bool reachesEnd) {
    endPosition_ = endPosition;
    endVelocity_ = endVelocity;
    reachesEnd_ = reachesEnd;
}

void SegmentProfile::plan(double s0, double v0, double length, double cap, double vEnd, double a) {
    count_ = 0;
    duration_ = 0.0;
    s0_ = s0;
    v0_ = std::max(0.0, v0);
    v0 = v0_;
    const double end = s0 + std::max(0.0, length);
    if (!(length > 0.0)) return finish(end, v0, true);
    if (!(a > 0.0)) a = 1e-9;  // cannot happen for a moving axis; never divide by 0
    const double twoA = 2.0 * a;
    if (!(cap > 0.0)) {  // come to rest as soon as possible
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
    if (v0 * v0 - v1 * v1 >= twoA * length) {  // cannot even brake to v1 in time
        const double v = std::sqrt(std::max(0.0, v0 * v0 - twoA * length));
        addPhase((v0 - v) / a, -a);
        return finish(end, v, true);
    }
    if (d1 + d3 <= length) {  // trapezoid: reaches the cruise velocity
        addPhase(std::fabs(cap - v0) / a, v0 <= cap ? a : -a);
        addPhase((length - d1 - d3) / cap, 0.0);
        addPhase((cap - v1) / a, -a);
        return finish(end, v1, true);
    }
    // v0 <= cap here (from above the cap the braking distance check covers it).
    if (v1 * v1 - v0 * v0 >= twoA * length) {  // accelerates all the way, short of v1
        const double v = std::sqrt(v0 * v0 + twoA * length);
        addPhase((v - v0) / a, a);
        return finish(end, v, true);
    }
    const double peak = std::sqrt((twoA * length + v0 * v0 + v1 * v1) / 2.0);  // triangle
    addPhase((peak - v0) / a, a);
    addPhase((peak - v1) / a, -a);
    finish(end, v1, true);
}

void SegmentProfile::sample(double t, double& s, double& v) const {
    if (!(t < duration_)) {
        s = endPosition_;
        v = reachesEnd_ ? endVelocity_ : 0.0;
        return;
    }
    double start = 0.0;
    double ps = s0_, pv = v0_;  // where phase i starts
    for (int i = 0; i < count_; ++i) {
        const Phase& p = phases_[static_cast<std::size_t>(i)];
        if (t < start + p.duration || i == count_ - 1) {
            const double dt = std::min(t - start, p.duration);
            s = ps + pv * dt + 0.5 * p.acceleration * dt * dt;
            v = std::max(0.0, pv + p.acceleration * dt);
            s = std::min(s, endPosition_);
            return;
        }
        start += p.duration;
        // The next phase starts where this one ends (the same expressions
        // the plan used to store per phase).
        ps = ps + pv * p.duration + 0.5 * p.acceleration * p.duration * p.duration;
        pv = std::max(0.0, pv + p.acceleration * p.duration);
    }
    s = s0_;
    v = v0_;
}

}  // namespace mtc::core::motion
