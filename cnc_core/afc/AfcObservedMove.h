#pragma once

#include "cnc_core/afc/AfcTrendSample.h"
#include "cnc_core/afc/TorqueModel.h"

namespace mtc::core {

/// True when `share` of the path (0..1) lies in the material between
/// `cutFrom` and `cutTo` (AfcMoveInput); cutFrom >= cutTo: never.
inline bool withinCut(double share, double cutFrom, double cutTo) {
    return share >= cutFrom && share < cutTo;
}

/// The trend of a move without G26, where the torque is only observed: every
/// sample follows from the move, the torque model and the page 30 values in
/// force at its start (which a plain move does not change), so the trend
/// keeps this one record and makes the samples when they are read. A move
/// then costs the same whatever its length (the observation was most of a
/// headless run when every 10 ms of every feed move was computed and stored).
struct AfcObservedMove {
    /// The sample's fields that stay during the move: limits, idle and stall
    /// torque, reduction, effective feed, flags. time, torqueActual,
    /// machiningTorque and measuringIdle are per sample.
    AfcTrendSample constant;
    TorqueModel model;
    double startTime = 0.0;       ///< machine clock at the start of the move, s
    double plannedSeconds = 0.0;  ///< duration of the move
    int count = 1;                ///< samples, the last at the end of the move
    double feed = 0.0;            ///< mm/min
    double speedFraction = 0.0;
    double engagement = 0.0;  ///< inside [cutFrom, cutTo) of the path share
    double cutFrom = 0.0;
    double cutTo = 1.0;
    bool itmMeasured = false;  ///< the move measures the idling torque (ITM)
    double itmFrom = 0.0;      ///< measuring period, s after the start
    double itmTo = 0.0;
    double idleTorque = 0.0;  ///< 005, subtracted from the actual torque
    double stallCompensation = 0.0;

    /// Sample `k`, 1 .. count: `k` steps of plannedSeconds / count into the move.
    AfcTrendSample sample(int k) const;
    /// The actual torque (S-0-0084) and the machining torque (007) of sample `k`.
    void torquesAt(int k, double& actual, double& machining) const;
};

}  // namespace mtc::core
