#include "cnc_core/afc/AfcObservedMove.h"

namespace mtc::core {

AfcTrendSample AfcObservedMove::sample(int k) const {
    const double step = plannedSeconds / count;
    const double elapsed = k * step;
    const double share = elapsed / plannedSeconds;
    const double cutting = withinCut(share, cutFrom, cutTo) ? engagement : 0.0;
    AfcTrendSample s = constant;
    s.time = startTime + elapsed;
    s.torqueActual = model.actualTorque(feed, speedFraction, cutting, startTime + elapsed);
    s.machiningTorque = s.torqueActual - idleTorque - stallCompensation;
    s.measuringIdle = itmMeasured && elapsed >= itmFrom && elapsed <= itmTo;
    return s;
}

}  // namespace mtc::core
