#pragma once

#include "cnc_core/language/Diagnostic.h"
#include "cnc_core/machine/MachineConfig.h"
#include "cnc_core/machine_data/MachineDataStore.h"

namespace mtc::core {

/// The limits the adaptive feed control works with (seed 002, Fig. 5-1):
/// process parameters Bxx.063..069 or the elements of page 30 that
/// correspond to them.
struct AfcSettings {
    int referenceAxis = 0;            ///< Bxx.063 / 002: axis significance 1..12, 0 = none
    double limitingTorque = 50.0;     ///< Bxx.064 / 010, % of nominal torque
    double minimumTorque = 10.0;      ///< Bxx.065 / 009, %; 0 = THMIS not monitored
    double maximumIdleTorque = 30.0;  ///< Bxx.066 / 006, %; 0 = idling torque not monitored
    double maximumReduction = 70.0;   ///< Bxx.067 / 013, %
    double amplification = 1.0;       ///< Bxx.068 / 003, 1/s (reciprocal integral-action time)
    double measuringPeriodMs = 200;   ///< Bxx.069 / 004, ms
};

/// The process parameters of adaptive feed control of one process.
struct AfcParameters {
    bool available = false;  ///< Bxx.062 adaptive feed control yes/no (default no)
    AfcSettings settings;    ///< Bxx.063..069 (seed 002, 4.2 defaults where absent)
};

/// Reads Bxx.062..069 ("B062".."B069") of `process`. A value outside the
/// range of seed 002 4.2 (or not a number) is a diagnostic AFC_PARAMETER and
/// the default is used instead. Never throws.
AfcParameters readAfcParameters(const ProcessConfig& process, DiagnosticList& diagnostics);

/// Page 30 of `process` as settings (elements 002, 003, 004, 006, 009, 010, 013).
AfcSettings settingsFromPage30(const MachineDataStore& store, int process);

/// Writes `settings` into page 30 of `process` (what G26 does while 002 = 0:
/// the process parameters replace the page's limits, 002 becomes Bxx.063).
void copySettingsToPage30(const AfcSettings& settings, MachineDataStore& store, int process);

/// The axis letter of significance 1..12 ("X".."C", "S1".."S3"); "" otherwise.
const char* afcAxisName(int significance);

}  // namespace mtc::core
