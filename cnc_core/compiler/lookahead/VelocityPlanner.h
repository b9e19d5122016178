#pragma once

#include <string>
#include <vector>

#include "cnc_core/compiler/lookahead/PathElement.h"
#include "cnc_core/compiler/lookahead/PathGeometry.h"

namespace mtc::core::lookahead {

/// Velocity along one element: constant acceleration `acceleration` up from
/// `vStart`, at most `vMax`, constant deceleration down to `vEnd` (mm, s).
struct ElementProfile {
    double length = 0.0;         ///< mm
    double vStart = 0.0;         ///< mm/s at s = 0
    double vEnd = 0.0;           ///< mm/s at s = length
    double vMax = 0.0;           ///< cap of the element, mm/s
    double acceleration = 0.0;   ///< planning path acceleration, mm/s^2 (> 0)
    double rampUpEnd = 0.0;      ///< s where the acceleration phase ends
    double rampDownStart = 0.0;  ///< s where the deceleration phase begins

    /// Sets vStart/vEnd/vMax/acceleration/length and the ramp bounds.
    void shape(double len, double v0, double v1, double cap, double a);
    /// Profile velocity at `s` (0..length), mm/s.
    double velocityAt(double s) const;
    /// Largest profile velocity on [from, to], mm/s.
    double peakOn(double from, double to) const;
    /// Time from the element's start to `s`, seconds.
    double timeTo(double s) const;
};

/// One block to emit: a programmed block (subIndex 0) or a sub-block with a
/// reduced F that the planner split off it (subIndex 1, 2, ...).
struct PlannedBlock {
    int element = 0;      ///< index into the planned elements
    int subIndex = 0;     ///< 0 = first part of the element, then 1, 2, ...
    int subCount = 1;     ///< parts the element was split into
    double sStart = 0.0;  ///< path position of the start, mm from the segment start
    double sEnd = 0.0;    ///< path position of the end, mm
    double vStart = 0.0;  ///< profile velocity at the start, mm/min
    double vEnd = 0.0;    ///< profile velocity at the end, mm/min
    double vMax = 0.0;    ///< the element's velocity cap, mm/min
    double feed = 0.0;    ///< F to program (peak of the profile, rounded down to 0.1), mm/min
    double time = 0.0;    ///< time along the profile, s
    AxisVector start;     ///< start point
    AxisVector end;       ///< end point
};

/// Something that prevents planning, with the element it concerns.
struct PlanProblem {
    int element = -1;
    std::string code;  ///< stable: LA_NOT_CONTIGUOUS, LA_ZERO_LENGTH, LA_NO_FEED, ...
    std::string message;
};

/// The planned velocity profile of one LA_ON ... LA_OFF polygon.
struct LookAheadPlan {
    std::vector<ElementGeometry> geometry;  ///< per element
    std::vector<ElementProfile> profiles;   ///< per element
    std::vector<double> junctionLimit;      ///< per node (elements + 1), mm/s
    std::vector<PlannedBlock> blocks;       ///< in path order
    std::vector<PlanProblem> problems;      ///< empty = plan is valid
    double totalLength = 0.0;               ///< mm
    double totalTime = 0.0;                 ///< s
    bool ok() const { return problems.empty(); }
};

/// Share of the path acceleration the planner uses; the rest absorbs the
/// rounding of F to 0.1 mm/min (docs/decisions/lookahead.md LA-006).
constexpr double kAccelerationMargin = 0.98;

/// Plans the velocity profile of `elements` (contiguous, at rest at both
/// ends) under the axis limits and the look-ahead parameters, and splits
/// elements into sub-blocks wherever the profile accelerates or decelerates.
LookAheadPlan planVelocityProfile(const std::vector<PathElement>& elements,
                                  const AxisLimits& limits, const LookAheadParameters& parameters);

/// The acceleration limit per axis of `element` (axis maximum x ACC_EFF), mm/s^2.
AxisVector effectiveAcceleration(const PathElement& element, const AxisLimits& limits);

/// Largest velocity change per axis at a block transition (seed: 2 x axis
/// acceleration x VFBT, over one block cycle), mm/s.
AxisVector transitionVelocityChange(const AxisVector& acceleration,
                                    const LookAheadParameters& parameters);

}  // namespace mtc::core::lookahead
