#pragma once

#include <algorithm>
#include <cmath>

#include "cnc_core/interp/BlockContext.h"
#include "cnc_core/interp/BlockInput.h"
#include "cnc_core/interp/BlockPlan.h"
#include "cnc_core/interp/InterpreterState.h"
#include "cnc_core/interp/PlanningOptions.h"
#include "cnc_core/machine/ProcessAxes.h"
#include "cnc_core/machine/ZeroOffsetTable.h"

namespace mtc::core {

/// Turns axis words into target positions and a move (G0, G1, G2, G3):
///  - value conversion: inch (G70) x 25.4 for linear and transformed axes,
///    diameter (G16) / 2 for the axis with definition X, incremental (G91);
///  - workpiece -> machine: + zero offset of the axis's current definition,
///    then G31/G32 for the two plane axes;
///  - arcs: centre I/J/K as coordinates of the axes with definition X/Y/Z
///    (absolute under G90, relative to the start under G91), both radii
///    checked against the tolerance, the centre must lie in the plane;
///  - travel limits of every programmed axis, feed present for G1/G2/G3,
///    simulated time of the move.
/// Smallest path feed a move may have, mm/min (MOT-010): a smaller one
/// would give a simulated duration that grows with the programmed number.
inline constexpr double kMinimumFeed = 0.001;

/// What plan() derives from the axis table, G70/G71, G15/G16 and the axis
/// allocation, for one such combination without a transformation (MOT-025):
/// built when one of them changes, read by every block in between.
struct PlanFrame {
    // Per machine axis, side by side (one index per axis and block):
    std::array<double, kMaxAxes> inch{};         ///< 25.4 when G70 converts the axis, else 1
    std::array<double, kMaxAxes> diameter{};     ///< 0.5 when G16 halves it (definition X), else 1
    std::array<double, kMaxAxes> low{}, high{};  ///< travel limits +- 1e-9; +-inf if not monitored
    std::array<double, kMaxAxes> secondsPerUnit{};      ///< rapidSecondsPerUnit
    std::array<std::uint8_t, kMaxAxes> offsetColumn{};  ///< ZeroOffsetTable::column(definition)
    std::array<std::uint8_t, kMaxAxes> spindleIndex{};  ///< 1..3 for a spindle (rotaryAxisMode)
    std::uint16_t spindleMask = 0;
    bool valid = false;
    /// The G15/G16 and G70/G71 it was built for, as the two adjacent groups.
    std::uint32_t radiusUnits = 0;
    PlaneSelection plane;
    /// Plane axes of an arc (-1 when the plane cannot carry one: missing or rotary).
    int p1 = -1, p2 = -1;
    std::array<std::uint8_t, 3> centreSlot{};  ///< I, J, K: 0 = p1, 1 = p2, 2 = outside
    std::uint8_t centreInPlane = 0;            ///< bit k: centreSlot[k] < 2
};

/// The path feed in mm/min: F, under G95 F times the reference spindle's
/// speed. plan() checks it; an arc needs it earlier, for its time bound.
inline double pathFeedOf(const ModalState& next) {
    const double feed = next.feed;
    if (next.g[kGroupFeedType] != 95) return feed;
    return feed * next.spindleSpeed[static_cast<size_t>(next.referenceSpindle)];
}

class MotionPlanner {
  public:
    MotionPlanner(const ProcessAxes* axes, const ZeroOffsetTable* offsets)
        : axes_(axes), offsets_(offsets) {}

    /// Zero offset (mm, or degrees for an untransformed rotary axis) that
    /// applies to machine axis `axis` in `modal`.
    double offsetOf(const ModalState& modal, int axis) const;
    /// Re-derives every workpiece coordinate from the machine positions (after
    /// a change of zero offset, axis allocation or transformation): the axes
    /// do not move, their programmed coordinates change.
    void recomputeWork(ModalState& modal) const;
    /// Plans the move of the block's axis words into plan.next / plan. The
    /// block must not be a G20 block. Returns false on an error (plan is
    /// then unspecified: the interpreter refuses the block and discards it).
    /// Without options.shortcuts every block takes the general path (the
    /// tests compare both).
    bool plan(const BlockContext& context, const BlockInput& input, const ModalState& current,
              BlockPlan& plan, const PlanningOptions& options) const;

  private:
    /// The general path: every modal state, every error.
    bool planGeneral(const BlockContext& context, const BlockInput& input,
                     const ModalState& current, BlockPlan& plan, double arcTolerance) const;
    bool frameFits(const ModalState& next) const;
    void buildFrame(const ModalState& next) const;
    /// The arc of a framed block whose positions are written: centre, radii,
    /// sweep, time (MotionPlannerFrame.cpp).
    bool framedArc(const BlockContext& context, const BlockInput& input, const ModalState& current,
                   BlockPlan& plan, double arcTolerance) const;
    /// FEED_MISSING, FEED_PER_REVOLUTION_NO_SPEED or FEED_TOO_SMALL (cold).
    [[gnu::cold]] static bool feedRefused(const BlockContext& context, int g, double feed,
                                          double feedRate);
    /// Feed checks and the move's time, shared by both paths. Inline: every
    /// G1/G2/G3 block passes here, and its usual case is a few instructions.
    bool finishMove(const BlockContext& context, const BlockInput& input, BlockPlan& plan, int g,
                    std::uint32_t moved, double length, double axisSeconds) const {
        ModalState& next = plan.next;
        // G94 with a feed it accepts: no check left that could refuse the block
        // (the calls of the others would cost every block their registers).
        if (next.g[kGroupFeedType] == 95 || !(next.feed >= kMinimumFeed))
            return finishChecked(context, input, plan, g, moved, length, axisSeconds);
        plan.feedRate = next.feed;
        if (plan.feedRate != feedCache_.feed)  // the feed changes far less often than blocks
            feedCache_ = {plan.feedRate, 60.0 / plan.feedRate};
        // No axis moves faster than its max_velocity (MOT-003): F60000 on a
        // 30000 mm/min axis takes the time of 30000 mm/min.
        next.time += std::max(length * feedCache_.secondsPerUnit, axisSeconds);
        return true;
    }
    /// finishMove() with every check (G95, a feed it may refuse).
    bool finishChecked(const BlockContext& context, const BlockInput& input, BlockPlan& plan, int g,
                       std::uint32_t moved, double length, double axisSeconds) const;
    double programmedValue(const ModalState& next, int axis, double value) const;
    void toMachine(const ModalState& current, ModalState& next, std::uint16_t axisMask) const;
    /// Axes whose position the block changes (G31 couples both plane axes).
    std::uint32_t movedAxes(const BlockInput& input, const ModalState& next) const;
    /// TRAVEL_LIMIT diagnostic for `axis` (cold path).
    bool travelLimit(const BlockContext& context, const BlockInput& input, const AxisModel& m,
                     int axis, double position) const;
    double rapidTime(const ModalState& current, const ModalState& next, std::uint32_t moved) const;
    /// G95: false (G95_ROTARY_AXIS) when a moved rotary axis has definition X, Y or Z.
    bool feedPerRevolutionAxes(const BlockContext& context, const BlockInput& input,
                               const ModalState& next, std::uint32_t moved) const;
    /// Arc centre, sweep and length; `axisSeconds` = the time the slowest
    /// axis needs for its share of the arc at its max_velocity.
    bool arc(const BlockContext& context, const BlockInput& input, const ModalState& current,
             BlockPlan& plan, double arcTolerance, double& length, double& axisSeconds) const;
    /// An arc's plane axes, start, end and centre (work coordinates), radii
    /// and the plane axes' seconds per unit (secondsPerPlaneUnit()).
    struct ArcGeometry {
        /// From `current`'s to `next`'s work position in plane axes p1, p2
        /// around `centre`; radii are set by arcRadii().
        ArcGeometry(int plane1, int plane2, const ModalState& current, const ModalState& next,
                    const double (&centre)[2], double secondsPerUnit1, double secondsPerUnit2)
            : p1(plane1),
              p2(plane2),
              s1(current.work[static_cast<std::size_t>(plane1)]),
              s2(current.work[static_cast<std::size_t>(plane2)]),
              e1(next.work[static_cast<std::size_t>(plane1)]),
              e2(next.work[static_cast<std::size_t>(plane2)]),
              c1(centre[0]),
              c2(centre[1]),
              perUnit1(secondsPerUnit1),
              perUnit2(secondsPerUnit2) {}
        int p1, p2;
        double s1, s2, e1, e2, c1, c2;
        double r1 = 0.0, r2 = 0.0;
        double perUnit1, perUnit2;
    };
    /// Sets both radii; false when the block must be refused (ARC_RADIUS_ZERO,
    /// ARC_RADIUS_MISMATCH).
    static bool arcRadii(ArcGeometry& a, double arcTolerance) {
        a.r1 = std::sqrt((a.s1 - a.c1) * (a.s1 - a.c1) + (a.s2 - a.c2) * (a.s2 - a.c2));
        a.r2 = std::sqrt((a.e1 - a.c1) * (a.e1 - a.c1) + (a.e2 - a.c2) * (a.e2 - a.c2));
        return !(a.r1 < 1e-9) && !(std::fabs(a.r1 - a.r2) > arcTolerance);
    }
    /// Sweep, length, axis time and the plan's arc fields of a checked arc
    /// (both paths).
    void arcMove(const BlockInput& input, const ModalState& current, BlockPlan& plan,
                 const ArcGeometry& geometry, double arcTolerance, double& length,
                 double& axisSeconds) const;
    /// Seconds per unit of the move's plane for `axis` at its max_velocity
    /// (under G32 a rotary plane axis in mm of the developed surface, under
    /// G31 both plane coordinates at the linear plane axis's velocity).
    double secondsPerPlaneUnit(const ModalState& next, int axis) const;

    const ProcessAxes* axes_;
    const ZeroOffsetTable* offsets_;
    /// 60 / feed for the last feed seen: saves a division per block.
    struct FeedCache {
        double feed = -1.0;
        double secondsPerUnit = 0.0;
    };
    mutable FeedCache feedCache_;
    mutable PlanFrame frame_;
};

}  // namespace mtc::core
