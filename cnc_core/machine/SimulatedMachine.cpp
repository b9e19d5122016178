#include "cnc_core/machine/SimulatedMachine.h"

#include <algorithm>
#include <cmath>

namespace mtc::core {

namespace {

constexpr std::size_t kAuxKept = 200;
constexpr double kPi = 3.14159265358979323846;

/// Sweep angle (radians, > 0) of an arc from start to end around the centre.
double sweep(const Motion& m) {
    const int a = m.planeAxis1, b = m.planeAxis2;
    const double a0 = std::atan2(m.start[b] - m.center2, m.start[a] - m.center1);
    const double a1 = std::atan2(m.end[b] - m.center2, m.end[a] - m.center1);
    double delta = m.type == MotionType::ArcCCW ? a1 - a0 : a0 - a1;
    while (delta <= 1e-12)
        delta += 2 * kPi;  // equal angles: a full circle
    return delta;
}

double pathLength(const Motion& m) {
    double other = 0.0;
    for (int i = 0; i < m.axisCount; ++i) {
        if (m.type != MotionType::Linear && m.type != MotionType::Rapid &&
            (i == m.planeAxis1 || i == m.planeAxis2))
            continue;
        const double d = m.end[i] - m.start[i];
        other += d * d;
    }
    if (m.type == MotionType::Linear || m.type == MotionType::Rapid) return std::sqrt(other);
    if (m.planeAxis1 < 0 || m.planeAxis2 < 0) return std::sqrt(other);
    const double radius =
        std::hypot(m.start[m.planeAxis1] - m.center1, m.start[m.planeAxis2] - m.center2);
    const double arc = radius * sweep(m);
    return std::sqrt(arc * arc + other);
}

}  // namespace

double motionSeconds(const Motion& motion, const ProcessConfig& config) {
    if (motion.type == MotionType::Rapid) {
        double slowest = 0.0;
        const int count = std::min<int>(motion.axisCount, static_cast<int>(config.axes.size()));
        for (int i = 0; i < count; ++i) {
            const double velocity = config.axes[static_cast<size_t>(i)].maxVelocity;
            if (velocity > 0)
                slowest =
                    std::max(slowest, std::abs(motion.end[i] - motion.start[i]) / velocity * 60.0);
        }
        return slowest;
    }
    if (motion.feed <= 0) return 0.0;
    return pathLength(motion) / motion.feed * 60.0;
}

SimulatedMachine::SimulatedMachine(const ProcessConfig& config) : config_(config) {}

void SimulatedMachine::motion(const Motion& m) {
    seconds_ += motionSeconds(m, config_);
    for (int i = 0; i < m.axisCount && i < kMaxAxes; ++i)
        position_[i] = m.end[i];
    ++motions_;
}

void SimulatedMachine::auxiliary(const AuxOutput& output) {
    if (aux_.size() == kAuxKept) aux_.erase(aux_.begin());
    aux_.push_back(output);
}

void SimulatedMachine::dwell(const SourceLocation&, double seconds) {
    if (seconds > 0) seconds_ += seconds;
}

void SimulatedMachine::command(const SourceLocation&, const std::string&, const std::string&) {}

double SimulatedMachine::position(int index) const {
    return index >= 0 && index < kMaxAxes ? position_[index] : 0.0;
}

void SimulatedMachine::reset() {
    seconds_ = 0.0;
    motions_ = 0;
    aux_.clear();
}

}  // namespace mtc::core
