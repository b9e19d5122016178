#pragma once

#include <cstddef>
#include <memory>

#include "cnc_core/afc/AdaptiveFeedControl.h"
#include "cnc_core/afc/AfcTrendRecorder.h"
#include "cnc_core/machine/MachineConfig.h"
#include "cnc_core/motion/TimedCourse.h"

namespace mtc::core {

/// One move as the simulated machine hands it to adaptive feed control.
/// This is the whole interface between a machine and the control: "this
/// path, at this feed, starting at this moment, cutting material between
/// these shares of the path" in, "this far, in this time" out
/// (simulateAfcMove, for a machine that executes a move at once). A machine
/// that moves in time steps drives the same controller per step instead:
/// AdaptiveFeedControl::advance (one 2 ms cycle: the feed the axes get) or
/// advanceSpan (a long step), with setClock at the start of the move and
/// requestIdleMeasurement/measureIdleTorque for ITM.
struct AfcMoveInput {
    double length = 0.0;               ///< path length, mm (degrees for rotary axes)
    double feed = 0.0;                 ///< programmed path feed, mm/min
    double plannedSeconds = 0.0;       ///< duration at the programmed feed
    double accelerationSeconds = 0.0;  ///< acceleration phase (ITM measures after it)
    double speedFraction = 0.0;        ///< speed of the reference axis / its maximum
    double engagement = 0.0;           ///< tool engagement where the tool is in the material
    /// Share of the path (0..1) where the tool is in the material: from
    /// cutFrom to cutTo; outside it cuts air. cutFrom >= cutTo: all in air.
    double cutFrom = 0.0;
    double cutTo = 1.0;
    /// True when cutFrom/cutTo come from the raw part (stock); false: the
    /// process has none, every feed move cuts except an ITM block, which
    /// moves in air (with G26 in the block: until its measurement ends).
    bool materialKnown = false;
    bool feedMove = true;    ///< G1/G2/G3 (false: G0, never reduced, always in air)
    double startTime = 0.0;  ///< machine clock at the start of the move, s
};

/// What became of the move.
struct AfcMoveResult {
    double seconds = 0.0;   ///< how long it took
    double fraction = 1.0;  ///< share of the path travelled (< 1: stopped by an error)
    double meanFeed = 0.0;  ///< path length travelled / time, mm/min
    bool adapted = false;   ///< G26 acted on the move
    std::size_t steps = 0;  ///< controller steps simulated (bounded per move)
    /// Under G26: the distance over time, for the axes to follow (MOT-011).
    std::shared_ptr<const motion::TimedCourse> course;
};

/// Cycle of the simulated I controller, s.
inline constexpr double kAfcCycleSeconds = 0.002;
/// Longest time the axes may stand at 100 % reduction (013 = 100 %) before
/// the simulation gives up with AFC_FEED_STOPPED, s.
inline constexpr double kAfcStandstillLimitSeconds = 60.0;
/// Longest simulated time of one move under G26 (AFC_MOVE_TOO_LONG), s.
inline constexpr double kAfcMaxMoveSeconds = 3600.0;
/// Most controller steps simulated for one move: 2 ms cycles while the
/// controller reacts, then spans (AdaptiveFeedControl::advanceSpan); a
/// settled controller is carried to the end of the cut in one span.
inline constexpr std::size_t kAfcMaxStepsPerMove = 20000;

/// Runs one move under adaptive feed control: a requested ITM first (errors
/// 508/509 become runtime errors of `afc`; 509 stops the move after the
/// measurement, the measuring period runs in air), then, with G26 on a feed
/// move, the I controller until the path is travelled, error 510 occurs, the
/// axes stood still for kAfcStandstillLimitSeconds or the move lasted
/// kAfcMaxMoveSeconds; without G26 the torque is only observed (trend). The
/// cost is bounded by kAfcMaxStepsPerMove whatever the length and feed.
/// Records trend samples into `recorder` (may be null: the results are the
/// same). Sets the clock of `afc`, reports the extra time (addExtraSeconds)
/// and, when stopped, the share of the path (setStopFraction).
AfcMoveResult simulateAfcMove(AdaptiveFeedControl& afc, const AfcMoveInput& move,
                              AfcTrendRecorder* recorder);

/// The torque model constants of `process` (`[process N torque-model]`,
/// defaults of TorqueModelParameters where absent).
TorqueModelParameters torqueModelFromConfig(const ProcessConfig& process);

/// Tool engagement of feed moves of `process` (torque-model `engagement`, default 1).
double cuttingEngagement(const ProcessConfig& process);

}  // namespace mtc::core
