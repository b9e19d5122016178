#include "cnc_core/machine/SimulatedMachine.h"

#include <algorithm>
#include <cmath>

#include "cnc_core/afc/AfcMotion.h"

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
    const double planned = motionSeconds(m, config_);
    ++motions_;
    lastAdapted_ = false;
    lastFeed_ =
        m.type == MotionType::Rapid && planned > 0 ? pathLength(m) / planned * 60.0 : m.feed;
    const bool adaptive = afc_ && afc_->available() && planned > 0 &&
                          (m.type != MotionType::Rapid || afc_->idleMeasurementRequested());
    if (adaptive) {
        seconds_ += adaptiveMove(m, planned);
        return;
    }
    seconds_ += planned;
    for (int i = 0; i < m.axisCount && i < kMaxAxes; ++i)
        position_[i] = m.end[i];
}

void SimulatedMachine::attachAdaptiveFeed(AdaptiveFeedControl* afc, AfcTrendRecorder* recorder) {
    afc_ = afc;
    recorder_ = recorder;
}

double SimulatedMachine::referenceSpeedFraction(const Motion& m) const {
    const int significance = afc_->effectiveSettings().referenceAxis;
    const std::string name = afcAxisName(significance);
    for (std::size_t i = 0; i < config_.axes.size() && i < kMaxAxes; ++i) {
        const AxisConfig& axis = config_.axes[i];
        if (significance >= 10 && axis.kind == AxisKind::Spindle &&
            axis.spindleIndex == significance - 9)
            return axis.maxSpeed > 0
                       ? spindleSpeed_[static_cast<std::size_t>(axis.spindleIndex)] / axis.maxSpeed
                       : 0.0;
        if (significance < 10 && axis.name == name) {
            const double travel = std::abs(m.end[i] - m.start[i]);
            const double length = pathLength(m);
            const double feed = length > 0 ? lastFeed_ * travel / length : 0.0;
            return axis.maxVelocity > 0 ? feed / axis.maxVelocity : 0.0;
        }
    }
    return 0.0;
}

double SimulatedMachine::accelerationSeconds(const Motion& m, double feed) const {
    double weakest = 0.0;
    const int count = std::min<int>(m.axisCount, static_cast<int>(config_.axes.size()));
    for (int i = 0; i < count; ++i) {
        const double a = config_.axes[static_cast<std::size_t>(i)].maxAcceleration;
        if (std::abs(m.end[i] - m.start[i]) > 1e-9 && a > 0 && (weakest == 0.0 || a < weakest))
            weakest = a;
    }
    return weakest > 0 ? feed / 60.0 / weakest : 0.0;
}

double SimulatedMachine::adaptiveMove(const Motion& m, double planned) {
    AfcMoveInput move;
    move.length = pathLength(m);
    move.feed = m.type == MotionType::Rapid ? lastFeed_ : m.feed;
    move.plannedSeconds = planned;
    move.accelerationSeconds = accelerationSeconds(m, lastFeed_);
    move.speedFraction = referenceSpeedFraction(m);
    move.engagement = cuttingEngagement(config_);
    move.feedMove = m.type != MotionType::Rapid;
    move.startTime = seconds_;
    const AfcMoveResult result = simulateAfcMove(*afc_, move, recorder_);
    for (int i = 0; i < m.axisCount && i < kMaxAxes; ++i)
        position_[i] = m.start[i] + (m.end[i] - m.start[i]) * result.fraction;
    lastFeed_ = result.meanFeed;
    lastAdapted_ = result.adapted;
    return result.seconds;
}

void SimulatedMachine::auxiliary(const AuxOutput& output) {
    if (output.type == 'S' && output.spindle >= 1 && output.spindle <= 3)
        spindleSpeed_[static_cast<std::size_t>(output.spindle)] = std::abs(output.value);
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
    if (recorder_) recorder_->clear();  // a new run starts a new trend at time 0
    seconds_ = 0.0;
    motions_ = 0;
    aux_.clear();
}

}  // namespace mtc::core
