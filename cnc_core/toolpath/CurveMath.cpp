#include "cnc_core/toolpath/CurveMath.h"

#include <algorithm>
#include <cmath>

namespace mtc::core::curve {

double sagitta(double radius, double angle) {
    return radius * (1.0 - std::cos(angle / 2.0));
}

int arcChords(double radius, double sweep, double tolerance) {
    const double tol = tolerance > 0.0 ? tolerance : 0.001;
    // A non-finite sweep (a NaN from a degenerate arc) is drawn as one turn.
    const double angle = std::isfinite(sweep) ? std::fabs(sweep) : 2.0 * kPi;
    // Every count is capped as a double before it becomes an int: memory and
    // time never grow with a programmed radius or turn count.
    const double quarter = std::min(std::ceil(angle / (kPi / 2.0) - 1e-12), kMaxArcChords);
    if (!(radius > tol)) return std::max(1, static_cast<int>(quarter));
    // Largest angle whose sagitta is the tolerance: 2 acos(1 - tol / r); it
    // vanishes for a huge radius.
    const double step = 2.0 * std::acos(1.0 - tol / radius);
    const double chords = std::ceil(angle / step - 1e-12);
    const double count = chords < kMaxArcChords ? chords : kMaxArcChords;  // NaN too
    return std::max({1, static_cast<int>(count), static_cast<int>(quarter)});
}

double developedFromDegrees(double degrees, double radius, int polarDirection) {
    const double sign = polarDirection == 1 ? -1.0 : 1.0;
    return sign * degrees * kPi / 180.0 * radius;
}

double degreesFromDeveloped(double millimetres, double radius, int polarDirection) {
    const double sign = polarDirection == 1 ? -1.0 : 1.0;
    return sign * millimetres / radius * 180.0 / kPi;
}

std::array<double, 3> cylinderPoint(int axial, double radius, double along, double degrees) {
    const double a = degrees * kPi / 180.0;
    std::array<double, 3> p{};
    p[static_cast<std::size_t>(axial)] = along;
    p[static_cast<std::size_t>((axial + 1) % 3)] = radius * std::cos(a);
    p[static_cast<std::size_t>((axial + 2) % 3)] = radius * std::sin(a);
    return p;
}

double distanceToSegment(const std::array<double, 3>& p, const std::array<double, 3>& a,
                         const std::array<double, 3>& b) {
    double ab[3], ap[3], len2 = 0.0, dot = 0.0;
    for (int i = 0; i < 3; ++i) {
        const auto k = static_cast<std::size_t>(i);
        ab[i] = b[k] - a[k];
        ap[i] = p[k] - a[k];
        len2 += ab[i] * ab[i];
        dot += ab[i] * ap[i];
    }
    const double t = len2 > 0.0 ? std::clamp(dot / len2, 0.0, 1.0) : 0.0;
    double d2 = 0.0;
    for (int i = 0; i < 3; ++i) {
        const double d = ap[i] - t * ab[i];
        d2 += d * d;
    }
    return std::sqrt(d2);
}

}  // namespace mtc::core::curve
