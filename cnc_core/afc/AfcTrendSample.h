#pragma once

namespace mtc::core {

/// One point of the adaptive feed trend (seed 002 Fig. 2-1): the actual and
/// machining torque of the reference axis, the limits in force at that
/// moment and the feed reduction. Torques in % of the nominal drive torque.
struct AfcTrendSample {
    double time = 0.0;               ///< simulated machine time, s
    double torqueActual = 0.0;       ///< S-0-0084
    double machiningTorque = 0.0;    ///< 007 (also computed while G25)
    double idleTorque = 0.0;         ///< 005
    double limitingTorque = 0.0;     ///< 010 / Bxx.064
    double minimumTorque = 0.0;      ///< 009 / Bxx.065
    double maximumIdleTorque = 0.0;  ///< 006 / Bxx.066
    double feedReduction = 0.0;      ///< 011, %
    double peakReduction = 0.0;      ///< highest 011 since G26, %
    double maximumReduction = 0.0;   ///< 013 / Bxx.067, %
    double effectiveFeed = 0.0;      ///< mm/min the axes get
    double stallTorque = 0.0;        ///< 014
    bool active = false;             ///< G26 in force
    bool measuringIdle = false;      ///< inside the measuring period of ITM
    bool excessiveThrust = false;    ///< PxxS.EXCTH
    bool thrustMissing = false;      ///< PxxS.THMIS
};

}  // namespace mtc::core
