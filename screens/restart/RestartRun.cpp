#include "screens/restart/RestartRun.h"

#include <QElapsedTimer>

#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/machine/SimulatedMachine.h"
#include "hmi/CellSession.h"
#include "hmi/SimulationClock.h"

namespace mtc::screens {

namespace {
constexpr int kTickMs = 15;
/// Work per tick: slices of blocks until this much time is used, so a tick
/// stays well under a frame while the computing process runs at full speed.
constexpr qint64 kTickBudgetNs = 8'000'000;
constexpr std::uint64_t kSliceBlocks = 20'000;

bool runsBlocks(mtc::core::RestartPhase phase) {
    using mtc::core::RestartPhase;
    return phase == RestartPhase::Active || phase == RestartPhase::Computing ||
           phase == RestartPhase::Adjusting || phase == RestartPhase::Repositioning;
}
}  // namespace

RestartRun::RestartRun(mtc::hmi::CellSession* session, int slot, QObject* parent)
    : QObject(parent), session_(session), slot_(slot), sps_(session->control(slot)) {
    sequence_ = std::make_unique<mtc::core::RestartSequence>(
        session->control(slot), sps_, session->interpreter(slot), session->store(),
        session->machine(slot));
    sequence_->setAxisTransfer(&session->axisTransfer());
    timer_.setInterval(kTickMs);
    connect(&timer_, &QTimer::timeout, this, &RestartRun::tick);
    // Keys the sequence handled (Start, Manual, Control reset, ...) change its phase.
    connect(session_, &mtc::hmi::CellSession::processChanged, this, [this](int changed) {
        if (changed == slot_) follow();
    });
}

RestartRun::~RestartRun() = default;

bool RestartRun::start(const mtc::core::RestartSelection& selection,
                       mtc::core::DiagnosticList& diagnostics) {
    const mtc::core::InterpreterState snapshot = session_->interpreter(slot_).state();
    if (!sequence_->accept(selection, diagnostics)) return false;
    before_ = snapshot;
    started_ = true;
    computingMs_ = 0.0;
    computingClock_.start();
    follow();
    return true;
}

void RestartRun::abort() {
    if (!sequence_->active()) return;
    sequence_->requestAbort();
    tick();
}

double RestartRun::actualPosition(int axis) const {
    return session_->machine(slot_).position(axis);
}

bool RestartRun::jog(int axis, double distance) {
    const bool ok = sequence_->jog(axis, actualPosition(axis) + distance);
    if (ok) {
        emit progressed();
        session_->notifyChanged(slot_);
    }
    return ok;
}

bool RestartRun::waiting() const {
    return sequence_->held() || !sequence_->waitingFor().empty();
}

void RestartRun::tick() {
    QElapsedTimer budget;
    budget.start();
    mtc::core::RestartPhase phase = sequence_->phase();
    do {
        phase = sequence_->advance(kSliceBlocks);
    } while (runsBlocks(phase) && !waiting() && budget.nsecsElapsed() < kTickBudgetNs);
    emit progressed();
    follow();
}

void RestartRun::follow() {
    const mtc::core::RestartPhase phase = sequence_->phase();
    // Back-to-back slices while blocks are interpreted (the event loop runs
    // between them), a slow scan while the sequence waits for the operator.
    timer_.setInterval(runsBlocks(phase) && !waiting() ? 0 : kTickMs);
    if (sequence_->active() && !timer_.isActive()) timer_.start();
    if (!sequence_->active()) timer_.stop();
    if (phase == lastPhase_) return;
    const mtc::core::RestartPhase previous = lastPhase_;
    lastPhase_ = phase;
    const auto computing = [](mtc::core::RestartPhase p) {
        return p == mtc::core::RestartPhase::Active || p == mtc::core::RestartPhase::Computing;
    };
    if (computing(previous) && !computing(phase))
        computingMs_ = static_cast<double>(computingClock_.nsecsElapsed()) / 1e6;
    // State re-established: machining continues at the target block in
    // simulated time, as after Start (seed 000, 2.9 step 9).
    if (phase == mtc::core::RestartPhase::Reestablished) session_->clock(slot_).resume();
    emit phaseChanged(phase);
    session_->notifyChanged(slot_);
}

}  // namespace mtc::screens
