// SimulatedMachine, adaptive feed control part: moves under G26 / ITM are
// worked out by the bounded simulation of cnc_core/afc (AfcMotion.h) when
// they are queued and executed as timed moves along the controller's course
// (docs/decisions/motion.md MOT-011); under G25 the torque of the feed moves is only observed for
// the trend.
#include <algorithm>
#include <cmath>
#include <string_view>

#include "cnc_core/afc/AfcMaterial.h"
#include "cnc_core/afc/AfcMotion.h"
#include "cnc_core/interp/MotionPath.h"
#include "cnc_core/machine/SimulatedMachine.h"

namespace mtc::core {

void SimulatedMachine::attachAdaptiveFeed(AdaptiveFeedControl* afc, AfcTrendRecorder* recorder) {
    if (afc_ && afc_ != afc) afc_->setClockSync({});
    afc_ = afc;
    recorder_ = recorder;
    if (afc_ && engine_.batch() > 0) afc_->setClockSync([this] { catchUp(); });
}

double SimulatedMachine::referenceSpeedFraction(const Motion& m, double pathFeed,
                                                double length) const {
    const int significance = afc_->effectiveSettings().referenceAxis;
    const std::string_view name = afcAxisName(significance);
    for (std::size_t i = 0; i < config_.axes.size() && i < kMaxAxes; ++i) {
        const AxisConfig& axis = config_.axes[i];
        if (significance >= 10 && axis.kind == AxisKind::Spindle &&
            axis.spindleIndex == significance - 9)
            return axis.maxSpeed > 0
                       ? spindleSpeed_[static_cast<std::size_t>(axis.spindleIndex)] / axis.maxSpeed
                       : 0.0;
        if (significance < 10 && axis.name == name) {
            const double travel = std::abs(m.end[i] - m.start[i]);
            const double feed = length > 0 ? pathFeed * travel / length : 0.0;
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

double SimulatedMachine::overrideShare(const Motion& m) const {
    const double percent =
        m.type == MotionType::Rapid ? engine_.rapidOverride() : engine_.feedOverride();
    // Below 1 % the axes stand until the operator turns the switch up: the
    // course is worked out at 100 % and waits in the queue (rate 0).
    // 100 % (the usual switch) is 1 exactly, as 100 / 100 (MOT-026).
    if (percent == 100.0) return 1.0;
    return percent >= 1.0 ? percent / 100.0 : 1.0;
}

AfcMoveInput SimulatedMachine::afcInput(const Motion& m, double planned, double length) const {
    // The controller acts on the feed the axes really get: the programmed
    // one at the override in force when the move is worked out (MOT-011).
    const double atOverride = overrideShare(m);
    AfcMoveInput move;
    move.length = length;
    move.feed = (m.type == MotionType::Rapid ? lastFeed_.value() : m.feed) * atOverride;
    move.plannedSeconds = planned / atOverride;
    move.speedFraction = referenceSpeedFraction(m, move.feed, move.length);
    move.engagement = cuttingEngagement(config_);
    move.materialKnown = material_->known();
    const MaterialShare share = material_->along(m);
    move.cutFrom = share.from;
    move.cutTo = share.to;
    move.feedMove = m.type != MotionType::Rapid;
    return move;
}

void SimulatedMachine::adaptiveMove(const Motion& m, double planned, double length) {
    catchUp();  // the controller runs on the machine's time and queue now
    AfcMoveInput move = afcInput(m, planned, length);
    move.accelerationSeconds = accelerationSeconds(m, move.feed);
    // It starts when the queue before it is worked off (at the overrides in
    // force; a hold now does not move it).
    const double drain = engine_.secondsToDrain();
    move.startTime = std::max(afcClock_, seconds() + (std::isfinite(drain) ? drain : 0.0));
    const AfcMoveResult result = simulateAfcMove(*afc_, move, recorder_);
    // AFC-012: after 509 / 510 the axes stand where they stopped, on the path.
    const std::array<double, kMaxAxes> reached = motionPointAt(m, result.fraction);
    for (int i = 0; i < m.axisCount && i < kMaxAxes; ++i)
        lastEnd_[static_cast<std::size_t>(i)] = reached[static_cast<std::size_t>(i)];
    lastFeed_ = {result.meanFeed, 0.0, 0.0, false};
    lastAdapted_ = result.adapted;
    lastFraction_ = result.fraction;
    afcClock_ = move.startTime + result.seconds;
    // The engine scales a timed move by the override in force when it runs:
    // it gets the time at 100 %, so an unchanged switch gives the real time.
    engine_.pushTimedMove(m, result.seconds * overrideShare(m), result.fraction, result.course);
}

void SimulatedMachine::observeMove(const Motion& m, double planned, double length) {
    // A plain move takes its planned time at the override in force whether
    // or not its torque is observed; only the trend recorder (none in the
    // CLI, MOT-019) reads the observation.
    // x / 1 is x: at 100 % the time is the planned one without a division.
    const double share = overrideShare(m);
    const double moveSeconds = share == 1.0 ? planned : planned / share;
    lastFeed_ = {0.0, length, moveSeconds, true};
    if (!recorder_) return queueClock(moveSeconds);
    catchUp();  // the trend's samples are taken at the machine's time now
    const double startTime = std::max(afcClock_, seconds());
    AfcMoveInput move = afcInput(m, planned, length);
    move.startTime = startTime;
    simulateAfcMove(*afc_, move, recorder_);
    afcClock_ = startTime + moveSeconds;
    afc_->setClock(afcClock_);
}

}  // namespace mtc::core
