#pragma once

#include "cnc_core/motion/SegmentGeometry.h"

namespace mtc::core::motion {

/// How a block ends (G codes of groups 10 and 11, docs/decisions/motion.md MOT-005).
struct BlockTransition {
    bool exactStop = false;     ///< G9: every block end at a velocity the axes can stop from
    bool blendCorners = false;  ///< G7: non-tangential transitions not at rest (with G9 only)
};

/// Two blocks meet tangentially when their tangents differ by at most this
/// angle (radians, 1 degree).
inline constexpr double kTangentialAngle = 0.017453292519943295;

/// What the engine knows about one side of a block transition.
struct TransitionSide {
    const SegmentGeometry* geometry = nullptr;
    bool rapid = false;
    BlockTransition mode;  ///< of the block (used on the ending side)
};

/// Largest path velocity (plane units/s) at which the transition from block
/// `ending` into block `next` may be crossed, before the blocks' own caps:
///  - 0 at and after a G0 move and where the plane mapping changes;
///  - a non-tangential transition (more than kTangentialAngle) is crossed at
///    rest under G6 or G8 (seed 001 ch. 6), under G7 together with G9 at the
///    velocity where no axis jumps by more than its velocity step;
///  - a tangential transition at the velocity where the remaining kink makes
///    no axis jump by more than its velocity step, and under G9 also no more
///    than the velocity each axis could stop from with one such step.
double junctionVelocity(const TransitionSide& ending, const TransitionSide& next,
                        const MotionLimits& limits);

}  // namespace mtc::core::motion
