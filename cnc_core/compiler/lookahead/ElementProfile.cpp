#include <algorithm>
#include <cmath>

#include "cnc_core/compiler/lookahead/VelocityPlanner.h"

namespace mtc::core::lookahead {

void ElementProfile::shape(double len, double v0, double v1, double cap, double a) {
    length = len;
    vStart = v0;
    vEnd = v1;
    vMax = cap;
    acceleration = a;
    rampUpEnd = std::clamp((cap * cap - v0 * v0) / (2.0 * a), 0.0, len);
    rampDownStart = std::clamp(len - (cap * cap - v1 * v1) / (2.0 * a), 0.0, len);
    if (rampUpEnd > rampDownStart) {
        // No cruise phase: the ramps meet below the cap.
        const double meet = std::clamp((v1 * v1 - v0 * v0 + 2.0 * a * len) / (4.0 * a), 0.0, len);
        rampUpEnd = rampDownStart = meet;
    }
}

double ElementProfile::velocityAt(double s) const {
    s = std::clamp(s, 0.0, length);
    const double up = std::sqrt(vStart * vStart + 2.0 * acceleration * s);
    const double down = std::sqrt(vEnd * vEnd + 2.0 * acceleration * (length - s));
    return std::min({vMax, up, down});
}

double ElementProfile::peakOn(double from, double to) const {
    if (to <= rampUpEnd) return velocityAt(to);
    if (from >= rampDownStart) return velocityAt(from);
    return velocityAt(std::clamp(rampUpEnd, from, to));
}

double ElementProfile::timeTo(double s) const {
    s = std::clamp(s, 0.0, length);
    const double a = acceleration;
    const double vUp = velocityAt(rampUpEnd);
    if (s <= rampUpEnd) return (velocityAt(s) - vStart) / a;
    double t = (vUp - vStart) / a;
    const double cruiseEnd = std::min(s, rampDownStart);
    if (cruiseEnd > rampUpEnd) t += (cruiseEnd - rampUpEnd) / vUp;
    if (s > rampDownStart) t += (velocityAt(rampDownStart) - velocityAt(s)) / a;
    return t;
}

}  // namespace mtc::core::lookahead
