#pragma once

#include "cnc_core/interp/BlockContext.h"
#include "cnc_core/interp/BlockInput.h"
#include "cnc_core/interp/BlockPlan.h"
#include "cnc_core/interp/InterpreterState.h"
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
    /// block must not be a G20 block. Returns false on an error.
    bool plan(const BlockContext& context, const BlockInput& input, const ModalState& current,
              BlockPlan& plan, double arcTolerance) const;

  private:
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
};

}  // namespace mtc::core
