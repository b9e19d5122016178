#pragma once

#include <QCoreApplication>
#include <QString>
#include <QStringList>
#include <optional>

#include "cnc_core/removal/ReentryCollisions.h"

namespace mtc::hmi {
class CellSession;
}

namespace mtc::screens {

/// The restart's way back checked against the part at the target, for the
/// result review (issue 19 §4, D-021): runs the core's checkRestartReentry on
/// the station's restart at the target reached (as `mtc200-cli restart
/// --check-collisions` does, same resolution) and keeps the answer with its
/// texts. Changes nothing of the station.
class RestartCollisions {
    Q_DECLARE_TR_FUNCTIONS(RestartCollisions)
  public:
    /// The restart of station `slot` of `session` (which must outlive this).
    RestartCollisions(mtc::hmi::CellSession* session, int slot);

    /// Checks the ADJUST / REPOS moves from where the restart stands now
    /// (nothing when it is not between the target reached and the re-entry).
    void check();
    void clear() { result_.reset(); }
    const std::optional<mtc::core::removal::ReentryCheck>& result() const { return result_; }
    /// Checked, with at least one collision.
    bool colliding() const { return result_ && result_->checked && !result_->collisions.empty(); }

    /// "ADJUST/REPOS moves that collide with the part: 1 of 3; the first:
    /// …", "Way
    /// back clear: ADJUST/REPOS moves checked against the part: 3", "Way
    /// back not checked against the part: …", or "" before a check.
    QString summary() const;
    /// "REPOS P99 N0002 (line 13)" of collision `index`.
    QString where(std::size_t index) const;
    /// "feed move cuts the part" or "rapid move touches the part".
    QString what(std::size_t index) const;
    /// "X-45.117 Y-50.000 Z-122.000 (machine)": where collision `index`
    /// first meets the part.
    QString position(std::size_t index) const;

  private:
    mtc::hmi::CellSession* session_;
    int slot_;
    std::optional<mtc::core::removal::ReentryCheck> result_;
};

}  // namespace mtc::screens
