#include "cnc_core/interp/MotionPath.h"

#include <algorithm>
#include <cmath>

#include "cnc_core/geometry/ArcSweep.h"

namespace mtc::core {
namespace {

bool isArc(const Motion& m) {
    return (m.type == MotionType::ArcCW || m.type == MotionType::ArcCCW) && m.planeAxis1 >= 0 &&
           m.planeAxis2 >= 0;
}

}  // namespace

double motionSweep(const Motion& m) {
    const int a = m.planeAxis1, b = m.planeAxis2;
    return std::fabs(arcSweep(m.start[a], m.start[b], m.end[a], m.end[b], m.center1, m.center2,
                              m.type == MotionType::ArcCW, m.fullCircle));
}

double motionPathLength(const Motion& m) {
    const bool arc = isArc(m);
    double other = 0.0;
    for (int i = 0; i < m.axisCount && i < kMaxAxes; ++i) {
        if (arc && (i == m.planeAxis1 || i == m.planeAxis2)) continue;
        const double d = m.end[i] - m.start[i];
        other += d * d;
    }
    if (!arc) return std::sqrt(other);
    const double radius =
        std::hypot(m.start[m.planeAxis1] - m.center1, m.start[m.planeAxis2] - m.center2);
    const double length = radius * motionSweep(m);
    return std::sqrt(length * length + other);
}

std::array<double, kMaxAxes> motionPointAt(const Motion& m, double fraction) {
    const double f = std::clamp(fraction, 0.0, 1.0);
    std::array<double, kMaxAxes> point = m.end;
    for (int i = 0; i < m.axisCount && i < kMaxAxes; ++i)
        point[i] = m.start[i] + (m.end[i] - m.start[i]) * f;
    if (!isArc(m) || f >= 1.0) return point;
    const int a = m.planeAxis1, b = m.planeAxis2;
    const double radius = std::hypot(m.start[a] - m.center1, m.start[b] - m.center2);
    const double start = std::atan2(m.start[b] - m.center2, m.start[a] - m.center1);
    const double turn = motionSweep(m) * f * (m.type == MotionType::ArcCCW ? 1.0 : -1.0);
    point[a] = m.center1 + radius * std::cos(start + turn);
    point[b] = m.center2 + radius * std::sin(start + turn);
    return point;
}

}  // namespace mtc::core
