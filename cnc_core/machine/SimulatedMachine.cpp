#include "cnc_core/machine/SimulatedMachine.h"

#include <algorithm>
#include <cmath>

#include "cnc_core/afc/AfcMaterial.h"
#include "cnc_core/afc/AfcMotion.h"
#include "cnc_core/interp/MotionPath.h"

namespace mtc::core {

namespace {

constexpr std::size_t kAuxKept = 200;
constexpr double kPi = 3.14159265358979323846;

/// Under G32 the feed is a path feed on the developed cylinder surface: the
/// rotary axis of the transformed plane counts in millimetres there (angle x
/// RI, signed by the polar direction as the interpreter develops it).
Motion onDevelopedSurface(const Motion& m, const ProcessConfig& config) {
    Motion developed = m;
    for (int axis : {m.transformAxis1, m.transformAxis2}) {
        if (axis < 0 || axis >= static_cast<int>(config.axes.size())) continue;
        const AxisConfig& a = config.axes[static_cast<std::size_t>(axis)];
        if (a.kind == AxisKind::Linear) continue;
        const double factor =
            (a.polarDirection == 1 ? -1.0 : 1.0) * kPi / 180.0 * m.effectiveRadius;
        developed.start[static_cast<std::size_t>(axis)] *= factor;
        developed.end[static_cast<std::size_t>(axis)] *= factor;
    }
    return developed;
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
    if (motion.transformation == 32 && motion.effectiveRadius > 0)
        return motionPathLength(onDevelopedSurface(motion, config)) / motion.feed * 60.0;
    return motionPathLength(motion) / motion.feed * 60.0;
}

SimulatedMachine::SimulatedMachine(const ProcessConfig& config)
    : config_(config), material_(std::make_unique<AfcMaterial>(config)) {}

SimulatedMachine::~SimulatedMachine() = default;

void SimulatedMachine::motion(const Motion& m) {
    lastReportsAfc_ = afc_ && (afc_->active() || afc_->idleMeasurementRequested());
    const double planned = motionSeconds(m, config_);
    ++motions_;
    lastAdapted_ = false;
    lastFraction_ = 1.0;
    lastFeed_ =
        m.type == MotionType::Rapid && planned > 0 ? motionPathLength(m) / planned * 60.0 : m.feed;
    // G26 controls, ITM measures, the trend observes the feed moves; with
    // none of these the move is a plain one (same result, no cost).
    const bool observed = afc_ && (afc_->active() || afc_->idleMeasurementRequested() ||
                                   (recorder_ && m.type != MotionType::Rapid));
    const bool adaptive = observed && afc_->available() && planned > 0;
    current_ = m.where;
    remainingIsRapid_ = m.type == MotionType::Rapid;
    remainingIsDwell_ = false;
    if (adaptive) {
        remaining_ += adaptiveMove(m, planned);
        return;
    }
    remaining_ += planned;
    for (int i = 0; i < m.axisCount && i < kMaxAxes; ++i)
        position_[i] = m.end[i];
    if (afc_) afc_->setClock(seconds_ + remaining_);  // the end of the queued work
}

double SimulatedMachine::advance(double seconds) {
    if (seconds <= 0.0) return 0.0;
    const double percent = remainingIsDwell_   ? 100.0
                           : remainingIsRapid_ ? rapidOverride_
                                               : feedOverride_;
    if (idle() || held_ || percent <= 0.0) return seconds;  // standing: no busy time
    const double rate = percent / 100.0;
    const double needed = remaining_ / rate;
    if (needed <= seconds) {  // the queued output is done within this call
        remaining_ = 0.0;
        seconds_ += needed;
        return needed;
    }
    remaining_ -= seconds * rate;
    seconds_ += seconds;
    return seconds;
}

void SimulatedMachine::stop() {
    remaining_ = 0.0;
    held_ = false;
}

double SimulatedMachine::distanceToGo(int) const {
    return 0.0;  // the interim machine's axes are at the end point of the move
}

double SimulatedMachine::actualFeed() const {
    if (idle() || held_ || remainingIsDwell_) return 0.0;
    return lastFeed_ * (remainingIsRapid_ ? rapidOverride_ : feedOverride_) / 100.0;
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
            const double length = motionPathLength(m);
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
    move.length = motionPathLength(m);
    move.feed = m.type == MotionType::Rapid ? lastFeed_ : m.feed;
    move.plannedSeconds = planned;
    move.accelerationSeconds = accelerationSeconds(m, lastFeed_);
    move.speedFraction = referenceSpeedFraction(m);
    move.engagement = cuttingEngagement(config_);
    move.materialKnown = material_->known();
    const MaterialShare share = material_->along(m);
    move.cutFrom = share.from;
    move.cutTo = share.to;
    move.feedMove = m.type != MotionType::Rapid;
    move.startTime = seconds_ + remaining_;  // after what is queued
    const AfcMoveResult result = simulateAfcMove(*afc_, move, recorder_);
    // AFC-012: after 509 / 510 the axes stand where they stopped, on the path.
    const std::array<double, kMaxAxes> reached = motionPointAt(m, result.fraction);
    for (int i = 0; i < m.axisCount && i < kMaxAxes; ++i)
        position_[i] = reached[i];
    lastFeed_ = result.meanFeed;
    lastAdapted_ = result.adapted;
    lastFraction_ = result.fraction;
    return result.seconds;
}

void SimulatedMachine::auxiliary(const AuxOutput& output) {
    if (output.type == 'S' && output.spindle >= 1 && output.spindle <= 3)
        spindleSpeed_[static_cast<std::size_t>(output.spindle)] = std::abs(output.value);
    if (aux_.size() == kAuxKept) aux_.erase(aux_.begin());
    aux_.push_back(output);
}

void SimulatedMachine::dwell(const SourceLocation& where, double seconds) {
    current_ = where;
    if (seconds <= 0) return;
    remaining_ += seconds;
    remainingIsDwell_ = true;
    remainingIsRapid_ = false;
    if (afc_) afc_->setClock(seconds_ + remaining_);
}

void SimulatedMachine::command(const SourceLocation&, const std::string&, const std::string&) {}

double SimulatedMachine::position(int index) const {
    return index >= 0 && index < kMaxAxes ? position_[index] : 0.0;
}

void SimulatedMachine::reset() {
    if (recorder_) recorder_->clear();  // a new run starts a new trend at time 0
    seconds_ = 0.0;
    remaining_ = 0.0;
    held_ = false;
    motions_ = 0;
    aux_.clear();
    if (afc_) afc_->setClock(0.0);
    current_ = {};
}

}  // namespace mtc::core
