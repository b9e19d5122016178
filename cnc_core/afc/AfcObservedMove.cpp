#include "cnc_core/afc/AfcObservedMove.h"

namespace mtc::core {

namespace {

double elapsedAt(const AfcObservedMove& move, int k) {
    return k * (move.plannedSeconds / move.count);
}

}  // namespace

void AfcObservedMove::torquesAt(int k, double& actual, double& machining) const {
    const double elapsed = elapsedAt(*this, k);
    const double share = elapsed / plannedSeconds;
    const double cutting = withinCut(share, cutFrom, cutTo) ? engagement : 0.0;
    actual = model.actualTorque(feed, speedFraction, cutting, startTime + elapsed);
    machining = actual - idleTorque - stallCompensation;
}

AfcTrendSample AfcObservedMove::sample(int k) const {
    const double elapsed = elapsedAt(*this, k);
    AfcTrendSample s = constant;
    s.time = startTime + elapsed;
    torquesAt(k, s.torqueActual, s.machiningTorque);
    s.measuringIdle = itmMeasured && elapsed >= itmFrom && elapsed <= itmTo;
    return s;
}

}  // namespace mtc::core
