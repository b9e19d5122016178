#include "cnc_core/machine/SimulatedMachine.h"

#include <algorithm>
#include <cmath>

#include "cnc_core/afc/AdaptiveFeedControl.h"
#include "cnc_core/afc/AfcMaterial.h"
#include "cnc_core/afc/AfcMotion.h"
#include "cnc_core/interp/MotionPath.h"

namespace mtc::core {

namespace {

constexpr std::size_t kAuxKept = 200;
constexpr double kPi = 3.14159265358979323846;

/// What an auxiliary function does on the machine (MOT-007): S sets a
/// spindle's speed without stopping the path; Mj03 / Mj04 start spindle j
/// (j = 0: spindle 1) and the program waits until it is at speed; Mj05 and
/// Mj19 stop it; every M, T, E and Q waits for the SPS with the axes at rest.
motion::MachineAction machineAction(const AuxOutput& output, const motion::MotionLimits& limits,
                                    std::uint32_t tag) {
    using Rotation = motion::SpindleSet::Rotation;
    motion::MachineAction action;
    action.tag = tag;
    if (output.type == 'S') {
        action.spindle = output.spindle;
        action.speed = std::abs(output.value);
        action.stopsPath = false;
        return action;
    }
    if (output.type != 'M' || !(output.value >= 0 && output.value < 1000)) return action;
    const int value = static_cast<int>(output.value);
    const int function = value % 100;
    const int spindle = value / 100 == 0 ? 1 : value / 100;
    if (spindle > 3) return action;
    const bool present = limits.spindles[static_cast<std::size_t>(spindle)].present;
    if (function == 3 || function == 4) {
        action.spindle = spindle;
        action.rotation =
            static_cast<int>(function == 3 ? Rotation::Clockwise : Rotation::CounterClockwise);
        action.waitForSpindle = present;
    } else if (function == 5 || function == 19) {
        action.spindle = spindle;
        action.rotation = static_cast<int>(Rotation::Stopped);
    }
    return action;
}

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

/// motionPathLength(m), read off the move's geometry where that worked out
/// the same figures: without transformation the geometry's plane is the
/// machine's, its line length and its arc's start radius and sweep are the
/// very expressions motionPathLength() evaluates, so the result is the same
/// to the bit without a second hypot() and arcSweep() (atan2) per arc.
double pathLength(const Motion& m, const motion::SegmentGeometry& g) {
    const bool arc = (m.type == MotionType::ArcCW || m.type == MotionType::ArcCCW) &&
                     m.planeAxis1 >= 0 && m.planeAxis2 >= 0;
    if (!g.mapping().identity() || g.axisCount() != std::min(m.axisCount, kMaxAxes) ||
        arc != g.arc())
        return motionPathLength(m);
    if (!arc) return g.length();
    double other = 0.0;
    for (int i = 0; i < g.axisCount(); ++i) {
        if (i == m.planeAxis1 || i == m.planeAxis2) continue;
        const double d = m.end[i] - m.start[i];
        other += d * d;
    }
    const double length = g.radius() * std::fabs(g.sweep());
    return std::sqrt(length * length + other);
}

/// motionSeconds() of a rapid move: as long as its slowest axis needs.
[[gnu::noinline]] double rapidSeconds(const Motion& motion, const ProcessConfig& config) {
    double slowest = 0.0;
    const int count = std::min<int>(motion.axisCount, static_cast<int>(config.axes.size()));
    for (int i = 0; i < count; ++i) {
        const double velocity = config.axes[static_cast<size_t>(i)].maxVelocity;
        if (velocity > 0)
            slowest = std::max(slowest, std::abs(motion.end[i] - motion.start[i]) / velocity * 60.0);
    }
    return slowest;
}

/// motionSeconds() of a feed move under G32: its path on the developed surface.
[[gnu::noinline]] double developedSeconds(const Motion& motion, const ProcessConfig& config) {
    return motionPathLength(onDevelopedSurface(motion, config)) / motion.feed * 60.0;
}

}  // namespace

double motionSeconds(const Motion& motion, const ProcessConfig& config) {
    return motionSeconds(motion, config, motionPathLength(motion));
}

double motionSeconds(const Motion& motion, const ProcessConfig& config, double length) {
    // The usual feed move in line, the rare kinds out of line: the machine
    // asks this for every move (MOT-028).
    if (motion.type == MotionType::Rapid) return rapidSeconds(motion, config);
    if (motion.feed <= 0) return 0.0;
    if (motion.transformation == 32 && motion.effectiveRadius > 0)
        return developedSeconds(motion, config);
    return length / motion.feed * 60.0;
}

SimulatedMachine::SimulatedMachine(const ProcessConfig& config)
    : config_(config),
      engine_(motion::MotionLimits::fromConfig(config)),
      material_(std::make_unique<AfcMaterial>(config)) {}

SimulatedMachine::~SimulatedMachine() {
    if (afc_ && engine_.batch() > 0) afc_->setClockSync({});  // catchUp() goes with this machine
}

void SimulatedMachine::motion(const Motion& m) {
    ++motions_;
    lastReportsAfc_ = afc_ && (afc_->active() || afc_->idleMeasurementRequested());
    // The geometry goes where the engine queues the move (pushMove() below).
    const double length = pathLength(m, engine_.prepareMove(m));
    const double planned = motionSeconds(m, config_, length);
    lastAdapted_ = false;
    lastFraction_ = 1.0;
    if (m.type == MotionType::Rapid && planned > 0)
        lastFeed_ = {0.0, length, planned, true};
    else
        lastFeed_ = {m.feed, 0.0, 0.0, false};
    const int axes = std::min(m.axisCount, kMaxAxes);
    for (int i = 0; i < axes; ++i)
        lastEnd_[static_cast<std::size_t>(i)] = m.end[static_cast<std::size_t>(i)];
    const bool afcOn = afc_ && afc_->available() && planned > 0;
    // G26 controls and ITM measures: the move's course is theirs
    // (lastReportsAfc_: G26 on or ITM requested, as asked above).
    if (afcOn && lastReportsAfc_) return adaptiveMove(m, planned, length);
    if (afcOn && m.type != MotionType::Rapid) {
        observeMove(m, planned, length);  // the trend observes the torque; the move is a plain one
    } else {
        queueClock(planned);  // the end of the queued work
    }
    engine_.pushMove(m, {m.exactStop, m.blendCorners});
}

double SimulatedMachine::advance(double seconds) {
    if (!(seconds > 0.0)) return 0.0;
    // The station filled the queue as far as it could: with room left it
    // has nothing to give until the queue runs empty. Without room: on
    // until the look-ahead of the next move is no longer full (with a batch
    // many entries, else one).
    const bool hadRoom = engine_.wantsMore();
    const std::uint64_t doneBefore = engine_.itemsDone();
    finishedAt_.clear();
    const double used =
        engine_.advanceOver(seconds, hadRoom ? 0 : engine_.lookAhead(), finishedAt_);
    collectReached();
    applyClockStepsAfter(doneBefore);
    return used;
}

void SimulatedMachine::moveReachedAux() {
    for (std::uint32_t tag : engine_.takeReached()) {
        if (tag == 0 || pendingAux_.empty()) continue;  // a command, no auxiliary function
        if (aux_.size() == kAuxKept) aux_.erase(aux_.begin());
        aux_.push_back(pendingAux_.front());
        pendingAux_.pop_front();
    }
}

void SimulatedMachine::stop() {
    engine_.stop();
    standWhereStopped();
    clockSteps_.clear();
    clockStepsDone_ = 0;
    afcClock_ = seconds();
}

void SimulatedMachine::standWhereStopped() {
    for (int i = 0; i < kMaxAxes; ++i)  // the axes stand where they stopped
        lastEnd_[static_cast<std::size_t>(i)] = engine_.position(i);
    pendingAux_.clear();
}

bool SimulatedMachine::discardAtRest() {
    if (!engine_.discardAtRest()) return false;
    standWhereStopped();
    return true;
}

void SimulatedMachine::auxiliary(const AuxOutput& output) {
    if (output.type == 'S' && output.spindle >= 1 && output.spindle <= 3)
        spindleSpeed_[static_cast<std::size_t>(output.spindle)] = std::abs(output.value);
    pendingAux_.push_back(output);
    engine_.pushAction(output.where, machineAction(output, engine_.limits(), ++nextTag_));
}

void SimulatedMachine::dwell(const SourceLocation& where, double seconds) {
    if (!(seconds > 0)) return;
    engine_.pushDwell(where, seconds);
    queueClock(seconds);
}

void SimulatedMachine::command(const MachineCommand& command) {
    // AXD, MTP, TCH, GAX ...: the axes come to rest before it (MOT-007).
    engine_.pushAction(command.where, motion::MachineAction{});
}

void SimulatedMachine::reset() {
    if (recorder_) recorder_->clear();  // a new run starts a new trend at time 0
    engine_.resetClock();
    engine_.clearLocation();
    motions_ = 0;
    aux_.clear();
    clockSteps_.clear();
    clockStepsDone_ = 0;
    afcClock_ = 0.0;
    if (afc_) afc_->setClock(0.0);
}

}  // namespace mtc::core
