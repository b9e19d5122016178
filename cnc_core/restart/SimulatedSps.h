#pragma once

#include "cnc_core/interp/MachineSink.h"
#include "cnc_core/machine/ProcessControl.h"

namespace mtc::core {

/// The part of the SPS program that NC program restart needs, after the
/// commissioning examples of seed 000 (6.3, 7.1): it works only on the
/// process's interface signals (names PxxNAME, docs/DECISIONS.md D-004).
///  - Start of the computing process: PxxCBPSTR follows PxxSBPACT (the SPS
///    sets it as soon as the NC reports "NC program restart active" and drops
///    it when that ends; step 3 of Fig. 6-8).
///  - Multi-block retrace: when the NC reports "multi-block retrace possible"
///    (PxxSREPOS rising) the SPS remembers "REPOS after NC program restart
///    required" and sets PxxCREPOS (step 5); PxxCREPOS holds while retrace is
///    possible and the state is not yet re-established (PxxSCREST), so it
///    drops after step 9. The REPOS M key (flag mREPOS) sets it too.
///  - Operating mode: Q9500 selects manual mode, Q9501 automatic mode
///    (QMANUAL / QAUTO); the Manual / Automatic keys reach the NC the same way
///    while a restart is active.
class SimulatedSps {
  public:
    /// Works on `control`'s signals and mode (not owned, must outlive this).
    explicit SimulatedSps(ProcessControl& control) : control_(control) {}

    /// One scan of the SPS program (evaluates the rungs above once).
    void cycle();
    /// An auxiliary function that reached the SPS; Q9500 / Q9501 change the mode.
    void auxiliary(const AuxOutput& output);
    /// QMANUAL / QAUTO: selects the operating mode of the process.
    void requestMode(OperatingMode mode) { control_.setModeBySps(mode); }
    /// False: PxxCBPSTR is not set automatically but by startComputing()
    /// (the "separate M key" variant of seed 000, 2.7). Default true.
    void setAutomaticStart(bool automatic) { automaticStart_ = automatic; }
    bool automaticStart() const { return automaticStart_; }
    /// The M key that starts the computing process (automaticStart() false):
    /// sets PxxCBPSTR while PxxSBPACT is 1. Returns false otherwise.
    bool startComputing();

  private:
    int get(const char* name) const;
    void set(const char* name, int value);

    ProcessControl& control_;
    bool automaticStart_ = true;
    bool reposAfterRestart_ = false;  ///< mREPOS2 of the seed's ladder
    bool retraceWasPossible_ = false;
};

}  // namespace mtc::core
