#pragma once

#include <QObject>
#include <cstdint>

#include "cnc_core/interp/InterpreterState.h"
#include "cnc_core/restart/RestartSequence.h"

namespace mtc::core {
class Station;
}
namespace mtc::hmi {
class CellSession;
}

namespace mtc::screens {

/// The restart screens' view of one station's NC program restart. The
/// restart itself (simulated SPS, RestartSequence, computing process, ADJUST,
/// REPOS) lives in the core's Station and runs whether or not a screen
/// exists; this object only forwards the screens' requests to it and turns
/// the session's change notices into progressed / phaseChanged signals.
class RestartRun : public QObject {
    Q_OBJECT
  public:
    /// The restart of station `slot`; `session` must outlive it.
    RestartRun(mtc::hmi::CellSession* session, int slot, QObject* parent = nullptr);
    ~RestartRun() override;

    /// Hands the accepted selection to the station (Station::acceptRestart).
    bool start(const mtc::core::RestartSelection& selection,
               mtc::core::DiagnosticList& diagnostics);
    /// Abort button: ends the computing process (or ADJUST/REPOS) as Control
    /// reset does; every restart signal goes back to 0.
    void abort();

    mtc::core::RestartPhase phase() const { return sequence().phase(); }
    bool active() const { return sequence().active(); }
    bool held() const { return sequence().held(); }
    /// The sequence has started since the station came up.
    bool started() const;
    const mtc::core::RestartSequence& sequence() const;
    /// Blocks the computing process has interpreted.
    std::uint64_t computedBlocks() const { return sequence().computing().blocksSoFar(); }
    /// Milliseconds the computing process took (0 while it runs).
    double computingMs() const;
    /// The station's interpreter state when the restart was accepted: the
    /// "machine now" column of the result review.
    const mtc::core::InterpreterState& before() const;
    /// Machine position of every axis (the simulated machine, live).
    double actualPosition(int axis) const;
    /// Jogs axis `axis` by `distance` in manual mode between the subroutines
    /// (seed 000, 2.9). False when the sequence refuses it.
    bool jog(int axis, double distance);

  signals:
    /// Progress of the current phase (blocks, positions).
    void progressed();
    /// The phase changed (also after keys the sequence handled).
    void phaseChanged(mtc::core::RestartPhase phase);

  private:
    void follow();
    mtc::core::Station& station() const;

    mtc::hmi::CellSession* session_;
    int slot_;
    mtc::core::RestartPhase lastPhase_ = mtc::core::RestartPhase::Idle;
};

}  // namespace mtc::screens
