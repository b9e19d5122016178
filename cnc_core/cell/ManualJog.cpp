#include "cnc_core/cell/ManualJog.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/machine/ProcessControl.h"
#include "cnc_core/machine/SimulatedMachine.h"

namespace mtc::core {

namespace {

/// Jog feed as a share of max_velocity (MOT-017).
constexpr double kJogFeedShare = 0.2;
/// How far a continuous jog of an axis without travel limits goes at most
/// (a rotary table: 10 turns); release() ends it long before.
constexpr double kEndlessJogReach = 3600.0;

std::string format(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", value);
    return text;
}

}  // namespace

ManualJog::ManualJog(ProcessControl& control, Interpreter& interpreter, SimulatedMachine& machine)
    : control_(control), interpreter_(interpreter), machine_(machine) {}

std::string ManualJog::check(int axis) const {
    if (control_.mode() != OperatingMode::Manual)
        return refusal("ALARM_JOG_NOT_MANUAL", "Jogging needs manual mode (M key Manual)");
    if (control_.programActive())
        return refusal("ALARM_JOG_PROGRAM_ACTIVE", "Jogging is refused while a program is active");
    if (axis < 0 || axis >= interpreter_.axes().count())
        return refusal("ALARM_JOG_NO_AXIS", "No such axis to jog");
    const AxisModel& model = interpreter_.axes().axis(axis);
    if (model.spindle && !model.rotary)
        return refusal("ALARM_JOG_SPINDLE", "A spindle is not jogged; it turns with M3/M4");
    if (releasing_) return refusal("ALARM_JOG_BRAKING", "The axis is still braking");
    return {};
}

std::string ManualJog::moveBy(int axis, double distance, bool rapid) {
    if (std::string refused = check(axis); !refused.empty()) return refused;
    if (!std::isfinite(distance) || distance == 0.0)
        return refusal("ALARM_JOG_NO_DISTANCE", "No jog distance");
    // From where the previous jog goes (the axis may still be on its way).
    const double from = machine_.idle() ? machine_.position(axis)
                                        : machine_.lastMoveEnd()[static_cast<std::size_t>(axis)];
    return queue(axis, from + distance, rapid);
}

std::string ManualJog::start(int axis, int direction, bool rapid) {
    if (std::string refused = check(axis); !refused.empty()) return refused;
    if (!machine_.idle()) return refusal("ALARM_JOG_AXES_MOVING", "The axes are still moving");
    const AxisModel& model = interpreter_.axes().axis(axis);
    const double from = machine_.position(axis);
    double target = direction > 0 ? from + kEndlessJogReach : from - kEndlessJogReach;
    if (model.limited()) target = direction > 0 ? model.maxPosition : model.minPosition;
    return queue(axis, target, rapid);
}

std::string ManualJog::refusal(const char* code, const char* english,
                               const std::vector<std::string>& values) const {
    return alarmText(code, english, control_.language(), values);
}

std::string ManualJog::queue(int axis, double target, bool rapid) {
    const AxisModel& model = interpreter_.axes().axis(axis);
    const std::string name = interpreter_.programmedAxisName(axis);
    if (model.limited() && (target < model.minPosition - 1e-9 || target > model.maxPosition + 1e-9))
        return refusal(
            "ALARM_JOG_TRAVEL_LIMIT", "Travel limit: %1 may move from %2 to %3 (jog to %4 refused)",
            {name, format(model.minPosition), format(model.maxPosition), format(target)});
    if (std::abs(target - machine_.position(axis)) < 1e-9 && machine_.idle())
        return refusal("ALARM_JOG_AT_LIMIT", "%1 is at its travel limit", {name});
    Motion move;
    move.type = rapid ? MotionType::Rapid : MotionType::Linear;
    move.axisCount = interpreter_.axes().count();
    for (int a = 0; a < move.axisCount && a < kMaxAxes; ++a)
        move.start[static_cast<std::size_t>(a)] =
            machine_.idle() ? machine_.position(a)
                            : machine_.lastMoveEnd()[static_cast<std::size_t>(a)];
    move.end = move.start;
    move.end[static_cast<std::size_t>(axis)] = target;
    move.programmedEnd = move.end;
    move.feed = rapid ? 0.0 : model.maxVelocity * kJogFeedShare;
    move.exactStop = true;
    machine_.motion(move);
    lastMove_ = move;
    moving_ = true;
    return {};
}

std::string ManualJog::spindle(int spindle, int rotation, double rpm) {
    if (control_.mode() != OperatingMode::Manual)
        return refusal("ALARM_SPINDLE_NOT_MANUAL",
                       "The spindle keys need manual mode (M key Manual)");
    if (control_.programActive())
        return refusal("ALARM_SPINDLE_PROGRAM_ACTIVE",
                       "The spindle keys are refused while a program is active");
    if (spindle < 1 || spindle > 3 || !machine_.hasSpindle(spindle))
        return refusal("ALARM_SPINDLE_NONE", "No such spindle");
    told_[static_cast<std::size_t>(spindle)] = {rotation,
                                                rpm >= 0.0 ? rpm : commandOf(spindle).rpm};
    const SourceLocation manual;  // no block: the operator's keys
    if (rpm >= 0.0) machine_.auxiliary({manual, 'S', spindle, rpm});
    const int function = rotation > 0 ? 3 : rotation < 0 ? 4 : 5;
    machine_.auxiliary(
        {manual, 'M', spindle, spindle == 1 ? function : spindle * 100.0 + function});
    return {};
}

ManualJog::SpindleCommand ManualJog::commandOf(int spindle) const {
    if (!machine_.idle()) return told_[static_cast<std::size_t>(spindle)];
    using Rotation = motion::SpindleSet::Rotation;
    const motion::SpindleSet& spindles = machine_.spindles();
    const Rotation rotation = spindles.rotation(spindle);
    return {rotation == Rotation::Clockwise          ? 1
            : rotation == Rotation::CounterClockwise ? -1
                                                     : 0,
            spindles.commandedSpeed(spindle)};
}

std::string ManualJog::spindleKey(int spindle, SpindleKey key) {
    if (spindle < 1 || spindle > 3) return refusal("ALARM_SPINDLE_NONE", "No such spindle");
    SpindleCommand next = commandOf(spindle);
    switch (key) {
        case SpindleKey::Clockwise:
        case SpindleKey::CounterClockwise:
            next.rotation = key == SpindleKey::Clockwise ? 1 : -1;
            if (next.rpm <= 0.0) next.rpm = kManualSpindleStart;
            break;
        case SpindleKey::Stop:
            next.rotation = 0;
            break;
        case SpindleKey::Faster:
        case SpindleKey::Slower:
            next.rpm = std::max(0.0, next.rpm + (key == SpindleKey::Faster ? kManualSpindleStep
                                                                           : -kManualSpindleStep));
            break;
    }
    return this->spindle(spindle, next.rotation, next.rpm);
}

void ManualJog::release() {
    if (!moving_ || releasing_) return;
    releasing_ = true;
    machine_.hold();  // brakes on the path, at the axis's acceleration
}

bool ManualJog::settle() {
    if (!moving_) return false;
    const bool dropped = releasing_;
    if (releasing_) {
        if (!machine_.discardAtRest()) return false;  // still braking
        releasing_ = false;
    } else if (!machine_.idle()) {
        return false;
    }
    moving_ = false;
    std::array<double, kMaxAxes> positions{};
    for (int a = 0; a < interpreter_.axes().count() && a < kMaxAxes; ++a)
        positions[static_cast<std::size_t>(a)] = machine_.position(a);
    interpreter_.manualJogPerformed();  // Bxx.036 = Yes: the program's state is cancelled
    interpreter_.takeMachinePositions(positions);
    return dropped;
}

}  // namespace mtc::core
