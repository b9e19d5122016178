#include "cnc_core/motion/JunctionRule.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cnc_core/motion/PathLimits.h"

namespace mtc::core::motion {

namespace {

bool sameMapping(const PlaneMapping& a, const PlaneMapping& b) {
    return a.kind() == b.kind() && a.axis1() == b.axis1() && a.axis2() == b.axis2() &&
           a.planeUnits(a.axis1(), 1.0) == b.planeUnits(b.axis1(), 1.0) &&
           a.planeUnits(a.axis2(), 1.0) == b.planeUnits(b.axis2(), 1.0);
}

/// Largest v with v * |jump_i| <= step_i for every axis.
double stepLimited(const SegmentGeometry& g, const MotionLimits& limits, const Position& jump) {
    double v = std::numeric_limits<double>::infinity();
    for (int i = 0; i < g.axisCount(); ++i) {
        const double j = std::fabs(jump[static_cast<std::size_t>(i)]);
        if (j <= 1e-12) continue;
        v = std::min(v, planeLimit(g, limits, i).velocityStep / j);
    }
    return v;
}

}  // namespace

double junctionVelocity(const TransitionSide& ending, const TransitionSide& next,
                        const MotionLimits& limits) {
    if (!ending.geometry || !next.geometry || ending.rapid || next.rapid) return 0.0;
    const SegmentGeometry& a = *ending.geometry;
    const SegmentGeometry& b = *next.geometry;
    if (!sameMapping(a.mapping(), b.mapping()) || a.axisCount() != b.axisCount()) return 0.0;
    // Only the axes of the moves are written and read (stepLimited): zeroing
    // all twelve cost a `rep stos` whose start-up was some 10 % of the time
    // the machine takes to queue a move.
    Position kink;  // NOLINT(cppcoreguidelines-pro-type-member-init)
    double cosine = 0.0;
    for (int i = 0; i < a.axisCount(); ++i) {
        const auto k = static_cast<std::size_t>(i);
        kink[k] = b.startTangent()[k] - a.endTangent()[k];
        cosine += b.startTangent()[k] * a.endTangent()[k];
    }
    const bool tangential = cosine >= std::cos(kTangentialAngle);
    const BlockTransition mode = ending.mode;
    if (!tangential && !(mode.blendCorners && mode.exactStop)) return 0.0;  // G6 or G8
    double v = stepLimited(a, limits, kink);
    if (mode.exactStop) v = std::min(v, stepLimited(a, limits, a.endTangent()));
    return v;
}

}  // namespace mtc::core::motion
