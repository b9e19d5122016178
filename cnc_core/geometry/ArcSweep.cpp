#include "cnc_core/geometry/ArcSweep.h"

#include <cmath>

namespace mtc::core {

namespace {
constexpr double kTwoPi = 2.0 * 3.14159265358979323846;
}

double arcSweep(double s1, double s2, double e1, double e2, double c1, double c2, bool clockwise,
                bool fullCircle) {
    const double sign = clockwise ? -1.0 : 1.0;
    if (fullCircle) return sign * kTwoPi;
    const double u1 = s1 - c1, u2 = s2 - c2, v1 = e1 - c1, v2 = e2 - c2;
    // Counter-clockwise angle from centre->start to centre->end, in (-pi, pi].
    double angle = sign * std::atan2(u1 * v2 - u2 * v1, u1 * v1 + u2 * v2);
    if (angle <= kSameDirection) angle += kTwoPi;
    if (!(angle <= kTwoPi)) angle = kTwoPi;  // rounding at the top (and NaN)
    return sign * angle;
}

}  // namespace mtc::core
