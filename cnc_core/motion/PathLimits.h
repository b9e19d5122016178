#pragma once

#include "cnc_core/motion/SegmentGeometry.h"

namespace mtc::core::motion {

/// Path velocity and acceleration a move may have so that no axis exceeds
/// its own limits (docs/decisions/motion.md MOT-003; the same rule as the
/// compiler's look-ahead, docs/decisions/lookahead.md LA-003/LA-005).
struct PathLimits {
    double velocity = 0.0;      ///< largest path velocity, plane units / s
    double acceleration = 0.0;  ///< path acceleration, plane units / s^2
};

/// The limits of machine axis `axis` in the units of the move's plane
/// (developed mm for a rotary plane axis under G32, the linear plane axis's
/// limits for both plane coordinates under G31).
AxisLimit planeLimit(const SegmentGeometry& geometry, const MotionLimits& limits, int axis);

/// Limits of `geometry`: for every axis with a share t of the tangent,
/// v <= v_axis / max|t| and a <= a_axis / max|t|. On arcs half of each
/// axis's acceleration is left to the centripetal part, so additionally
/// v^2 / r <= a_plane / 2. Under G32 a rotary plane axis counts in mm of
/// the developed surface; under G31 both plane coordinates take the limits
/// of the linear plane axis. A path of length 0 gets both limits 0.
PathLimits pathLimits(const SegmentGeometry& geometry, const MotionLimits& limits);

}  // namespace mtc::core::motion
