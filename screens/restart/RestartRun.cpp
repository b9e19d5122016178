#include "screens/restart/RestartRun.h"

#include "cnc_core/cell/Station.h"
#include "hmi/CellSession.h"

namespace mtc::screens {

RestartRun::RestartRun(mtc::hmi::CellSession* session, int slot, QObject* parent)
    : QObject(parent), session_(session), slot_(slot) {
    lastPhase_ = phase();
    connect(session_, &mtc::hmi::CellSession::processChanged, this, [this](int changed) {
        if (changed == slot_) follow();
    });
}

RestartRun::~RestartRun() = default;

mtc::core::Station& RestartRun::station() const {
    return session_->station(slot_);
}

const mtc::core::RestartSequence& RestartRun::sequence() const {
    return station().restart();
}

bool RestartRun::started() const {
    return station().restartStarted();
}

double RestartRun::computingMs() const {
    return station().restartComputingMs();
}

const mtc::core::InterpreterState& RestartRun::before() const {
    return station().restartBefore();
}

bool RestartRun::start(const mtc::core::RestartSelection& selection,
                       mtc::core::DiagnosticList& diagnostics) {
    if (!station().acceptRestart(selection, diagnostics)) return false;
    // The SPS answered at once (computing process ready); the process runs
    // with the session's next tick.
    follow();
    session_->notifyChanged(slot_);
    return true;
}

void RestartRun::abort() {
    if (!active()) return;
    station().abortRestart();
    follow();
    session_->notifyChanged(slot_);
}

double RestartRun::actualPosition(int axis) const {
    return station().machine().position(axis);
}

bool RestartRun::jog(int axis, double distance) {
    const bool ok = station().jogBy(axis, distance);
    if (ok) session_->notifyChanged(slot_);
    return ok;
}

void RestartRun::follow() {
    emit progressed();
    const mtc::core::RestartPhase current = phase();
    if (current == lastPhase_) return;
    lastPhase_ = current;
    emit phaseChanged(current);
}

}  // namespace mtc::screens
