#pragma once

#include <QObject>
#include <QString>
#include <QTimer>
#include <memory>
#include <optional>

#include "cnc_core/restart/RestartVerifier.h"

namespace mtc::hmi {
class CellSession;
}

namespace mtc::screens {

/// The restart verifier of one station on the panel (restart.md R-028): the
/// whole selected program in slices of a timer (the restart screen's soft
/// key), or the chosen target at once (the result review). Only runs the
/// core's RestartVerifier and keeps its answers; it changes nothing of the
/// station.
class RestartVerification : public QObject {
    Q_OBJECT
  public:
    RestartVerification(mtc::hmi::CellSession* session, int slot, QObject* parent = nullptr);
    ~RestartVerification() override;

    /// Starts the verification of program `program` with ADJUST / REPOS
    /// (every arrival, 16 passes). False when it cannot start (`why` says why).
    bool startProgram(int program, QString& why);
    bool running() const { return timer_.isActive(); }
    /// The last program verification (its report while it runs).
    const mtc::core::VerifyReport* programReport() const;
    /// "Verifying P1: 1,204 arrivals ..." or the coverage line at the end.
    QString programText() const;

    /// The accepted selection as one target from `before` (the station's
    /// state when Enter was pressed): the same comparison the CLI makes.
    void verifyTarget(const mtc::core::RestartSelection& selection,
                      const mtc::core::InterpreterState& before);
    void clearTarget() { target_.reset(); }
    const std::optional<mtc::core::VerifiedTarget>& target() const { return target_; }

  signals:
    void progressed();
    void finished();

  private:
    void tick();

    mtc::hmi::CellSession* session_;
    int slot_;
    int program_ = 0;
    std::unique_ptr<mtc::core::RestartVerifier> verifier_;
    std::optional<mtc::core::VerifiedTarget> target_;
    QTimer timer_;
};

}  // namespace mtc::screens
