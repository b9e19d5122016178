#pragma once

#include <array>

#include "cnc_core/interp/MachineSink.h"

namespace mtc::core {

/// Sweep angle (radians, > 0) of an arc Motion from start to end around its
/// centre in the direction of the move; equal start and end angles give a
/// full circle (2 pi). Meaningless for straight moves.
double motionSweep(const Motion& motion);

/// Length of the path of `motion` in machine units: the straight line of all
/// axes, or for an arc the arc in the plane combined with the helical share of
/// the other axes (rotary axes count in degrees).
double motionPathLength(const Motion& motion);

/// Machine positions after `fraction` (0..1) of the path of `motion`: on the
/// straight line, or on the arc (angle and helical axes in proportion). Axes
/// beyond motion.axisCount keep their `end` value.
std::array<double, kMaxAxes> motionPointAt(const Motion& motion, double fraction);

}  // namespace mtc::core
