#pragma once

#include <array>

#include "cnc_core/motion/MotionLimits.h"

namespace mtc::core::motion {

/// The spindles S1..S3 of a process in spindle mode: each runs clockwise,
/// counter-clockwise or stands, and ramps its speed towards the commanded
/// one with its acceleration (max_acceleration of the spindle, deg/s^2 = 1/6 rpm/s).
class SpindleSet {
  public:
    enum class Rotation { Stopped, Clockwise, CounterClockwise };

    explicit SpindleSet(const MotionLimits& limits);

    /// S: the commanded speed (rpm, >= 0; clamped to max_speed).
    void setSpeed(int spindle, double rpm);
    /// M3/M4/M5 (Mj03/Mj04/Mj05), M19 stops as M5 does.
    void setRotation(int spindle, Rotation rotation);
    /// Every spindle ramps down to a stop (Control reset).
    void stopAll();
    /// Moves every ramp on by `seconds`.
    void advance(double seconds) {
        // Inline for the usual case: the machine calls it for every queue
        // entry, and the spindles mostly stand or run at speed (MOT-026).
        if (ramping_) advanceRamps(seconds);
    }

    /// Signed actual speed, rpm (> 0 clockwise).
    double actualSpeed(int spindle) const;
    /// Commanded speed (rpm, >= 0) and rotation.
    double commandedSpeed(int spindle) const;
    Rotation rotation(int spindle) const;
    /// True when the actual speed equals the signed target (running or stopped).
    bool atSpeed(int spindle) const;
    /// Seconds until `spindle` reaches its target speed (0 when it has).
    double secondsToSpeed(int spindle) const;

  private:
    struct State {
        double commanded = 0.0;  ///< rpm
        double actual = 0.0;     ///< signed rpm
        Rotation rotation = Rotation::Stopped;
    };
    double target(int spindle) const;
    void advanceRamps(double seconds);
    bool valid(int spindle) const { return spindle >= 1 && spindle <= 3; }

    std::array<SpindleLimit, 4> limits_{};
    std::array<State, 4> state_{};
    /// False while every spindle is at its target speed (advance() has
    /// nothing to do); true after any change of a target.
    bool ramping_ = false;
};

}  // namespace mtc::core::motion
