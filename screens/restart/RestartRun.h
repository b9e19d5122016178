#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>
#include <array>
#include <memory>

#include "cnc_core/interp/InterpreterState.h"
#include "cnc_core/restart/RestartSequence.h"
#include "cnc_core/restart/SimulatedSps.h"

namespace mtc::hmi {
class CellSession;
}

namespace mtc::screens {

/// Runs the NC program restart of one station in the panel: the station's
/// simulated SPS and the core's RestartSequence (computing process, signals
/// of seed 000 Fig. 6-8, ADJUST, REPOS), advanced by a timer in slices of a
/// few milliseconds so the panel stays responsive on a 1,000,000-block
/// program. Keeps what the machine looked like when the restart was
/// accepted, for the result review.
class RestartRun : public QObject {
    Q_OBJECT
  public:
    /// The restart of station `slot`; `session` must outlive it.
    RestartRun(mtc::hmi::CellSession* session, int slot, QObject* parent = nullptr);
    ~RestartRun() override;

    /// Hands the accepted selection to the sequence (PxxSBPACT; the SPS starts
    /// the computing process). False with the reasons in `diagnostics` when
    /// the NC refuses it; then nothing changed.
    bool start(const mtc::core::RestartSelection& selection,
               mtc::core::DiagnosticList& diagnostics);
    /// Abort button: stops the computing process (or ADJUST/REPOS) at its next
    /// check, as Control reset does; every restart signal goes back to 0.
    void abort();

    mtc::core::RestartPhase phase() const { return sequence_->phase(); }
    bool active() const { return sequence_->active(); }
    bool held() const { return sequence_->held(); }
    /// The sequence has started since the station's panel came up.
    bool started() const { return started_; }
    const mtc::core::RestartSequence& sequence() const { return *sequence_; }
    /// Blocks the computing process has interpreted (live, any thread safe).
    std::uint64_t computedBlocks() const { return sequence_->computing().blocksSoFar(); }
    /// Milliseconds the computing process took (0 while it runs).
    double computingMs() const { return computingMs_; }
    /// The station's interpreter state when the restart was accepted: the
    /// "machine now" column of the result review.
    const mtc::core::InterpreterState& before() const { return before_; }
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
    void tick();
    void follow();
    /// Held, or waiting for another process's GAX / FAX: a slow scan will do.
    bool waiting() const;

    mtc::hmi::CellSession* session_;
    int slot_;
    mtc::core::SimulatedSps sps_;
    std::unique_ptr<mtc::core::RestartSequence> sequence_;
    QTimer timer_;
    mtc::core::RestartPhase lastPhase_ = mtc::core::RestartPhase::Idle;
    mtc::core::InterpreterState before_;
    bool started_ = false;
    double computingMs_ = 0.0;
    QElapsedTimer computingClock_;
};

}  // namespace mtc::screens
