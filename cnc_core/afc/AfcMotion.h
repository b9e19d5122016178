#pragma once

#include "cnc_core/afc/AdaptiveFeedControl.h"
#include "cnc_core/afc/AfcTrendRecorder.h"
#include "cnc_core/machine/MachineConfig.h"

namespace mtc::core {

/// One move as the simulated machine hands it to adaptive feed control.
struct AfcMoveInput {
    double length = 0.0;               ///< path length, mm (degrees for rotary axes)
    double feed = 0.0;                 ///< programmed path feed, mm/min
    double plannedSeconds = 0.0;       ///< duration at the programmed feed
    double accelerationSeconds = 0.0;  ///< acceleration phase (ITM measures after it)
    double speedFraction = 0.0;        ///< speed of the reference axis / its maximum
    double engagement = 0.0;           ///< tool engagement of the cut (0 = air)
    bool feedMove = true;              ///< G1/G2/G3 (false: G0, never reduced)
    double startTime = 0.0;            ///< machine clock at the start of the move, s
};

/// What became of the move.
struct AfcMoveResult {
    double seconds = 0.0;   ///< how long it took
    double fraction = 1.0;  ///< share of the path travelled (< 1: stopped by an error)
    double meanFeed = 0.0;  ///< path length travelled / time, mm/min
    bool adapted = false;   ///< G26 acted on the move
};

/// Cycle of the simulated I controller, s.
inline constexpr double kAfcCycleSeconds = 0.002;
/// Longest time the axes may stand at 100 % reduction (013 = 100 %) before
/// the simulation gives up with AFC_FEED_STOPPED, s.
inline constexpr double kAfcStandstillLimitSeconds = 60.0;

/// Runs one move under adaptive feed control: a requested ITM first (errors
/// 508/509 become runtime errors of `afc`; 509 stops the move after the
/// measurement), then, with G26 on a feed move, the I controller every
/// kAfcCycleSeconds until the path is travelled, error 510 occurs or the
/// axes stood still for kAfcStandstillLimitSeconds. Records a trend sample
/// every 10 ms into `recorder` (may be null). The extra time is reported to
/// `afc` (addExtraSeconds).
AfcMoveResult simulateAfcMove(AdaptiveFeedControl& afc, const AfcMoveInput& move,
                              AfcTrendRecorder* recorder);

/// The torque model constants of `process` (`[process N torque-model]`,
/// defaults of TorqueModelParameters where absent).
TorqueModelParameters torqueModelFromConfig(const ProcessConfig& process);

/// Tool engagement of feed moves of `process` (torque-model `engagement`, default 1).
double cuttingEngagement(const ProcessConfig& process);

}  // namespace mtc::core
