#pragma once

#include <array>

#include "cnc_core/interp/MachineSink.h"
#include "cnc_core/machine/MachineConfig.h"

/// The trajectory engine of the simulated machine (docs/decisions/motion.md):
/// every motion is interpolated in time under the velocity and acceleration
/// limits of the machine configuration. Plain C++17, no allocation per tick.
namespace mtc::core::motion {

/// Limits of one machine axis, in units per second (mm or degrees).
struct AxisLimit {
    double velocity = 0.0;      ///< max_velocity / 60 (> 0)
    double acceleration = 0.0;  ///< max_acceleration (> 0)
    double velocityStep = 0.0;  ///< largest velocity jump at a block transition (MOT-004)
    bool rotary = false;        ///< degrees (rotary axis or spindle in rotary axis mode)
    int polarDirection = 0;     ///< Cxx.076: 1 reverses the rotary sense under G31/G32
};

/// Limits of one spindle in spindle mode.
struct SpindleLimit {
    bool present = false;
    double maxSpeed = 0.0;      ///< rpm (max_speed)
    double acceleration = 0.0;  ///< rpm/s (max_acceleration deg/s^2 / 6)
};

/// Everything the engine needs from the machine configuration, by machine
/// axis index (the order of ProcessConfig::axes and Motion::end).
struct MotionLimits {
    int axisCount = 0;
    std::array<AxisLimit, kMaxAxes> axes{};
    std::array<SpindleLimit, 4> spindles{};            ///< index 1..3
    std::array<int, 4> spindleAxis{{-1, -1, -1, -1}};  ///< machine axis of spindle 1..3
    double feedOverrideMax = 150.0;   ///< %, `feed_override_max` of the process (MOT-006)
    double rapidOverrideMax = 100.0;  ///< %, rapid traverse override never exceeds 100 %

    /// Reads the limits of `process`: each axis's max_velocity (mm/min or
    /// deg/min) and max_acceleration (mm/s^2 or deg/s^2), the block
    /// transition parameters VFBT (B071, default 1) and NC block cycle time
    /// (B073 ms, default 2) that give each axis's velocity step 2 * a * VFBT
    /// * cycle (seed 001 ch. 6), spindle speeds and ramps.
    static MotionLimits fromConfig(const ProcessConfig& process);
};

}  // namespace mtc::core::motion
