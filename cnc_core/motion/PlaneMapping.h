#pragma once

#include <array>

#include "cnc_core/motion/MotionLimits.h"

namespace mtc::core::motion {

using Position = std::array<double, kMaxAxes>;

/// The plane a move is interpolated in. Without transformation (G30) it is
/// the machine's own coordinates. Under G32 the rotary plane axis is
/// interpolated on the developed cylinder surface (mm = degrees x RI), under
/// G31 the linear and rotary plane axes in the fictitious cartesian plane of
/// facing (seed 003 ch. 4; the same formulas as machine/Transformation).
class PlaneMapping {
  public:
    /// The mapping of `motion` (identity for G30 or an incomplete G31/G32).
    static PlaneMapping of(const Motion& motion, const MotionLimits& limits);
    /// `*this = of(motion, limits)` without a temporary: copying one back
    /// read it with wide loads across the narrow stores that had just
    /// written it, a store-forwarding stall on every move.
    void describe(const Motion& motion, const MotionLimits& limits);

    bool identity() const { return kind_ == 30; }
    int kind() const { return kind_; }
    /// Machine axes spanning the transformed plane (-1 without transformation).
    int axis1() const { return axis1_; }
    int axis2() const { return axis2_; }

    /// Machine positions to plane coordinates (only the two plane axes change).
    void toPlane(const Position& machine, Position& plane) const {
        plane = machine;  // inline for the usual case, G30 (MOT-026)
        if (kind_ != 30) transformToPlane(machine, plane);
    }
    /// Plane coordinates to machine positions. `machine` holds the previous
    /// machine position on entry: under G31 the angle takes the turn nearest
    /// to it, and keeps it at the rotation centre.
    void toMachine(const Position& plane, Position& machine) const;
    /// A rotary plane axis's velocity or acceleration (degrees) in plane
    /// units (mm) under G32; unchanged otherwise.
    double planeUnits(int axis, double degreesValue) const {
        // Inline for the usual case: the limits of every moving axis of
        // every queued move come through here (MOT-023).
        return kind_ == 32 ? developedUnits(axis, degreesValue) : degreesValue;
    }
    /// True when machine axis `axis` is a rotary axis measured in mm in the plane.
    bool developed(int axis) const;

  private:
    /// toPlane()'s plane axes under G31 / G32.
    void transformToPlane(const Position& machine, Position& plane) const;
    /// planeUnits() under G32.
    double developedUnits(int axis, double degreesValue) const;

    int kind_ = 30;
    int axis1_ = -1, axis2_ = -1;
    int linear_ = -1, rotary_ = -1;  ///< G31: the linear and the rotary plane axis
    double radius_ = 0.0;            ///< G32: RI
    std::array<int, 2> polar_{};     ///< Cxx.076 of axis1_, axis2_
    std::array<bool, 2> rotaryAxis_{};
};

}  // namespace mtc::core::motion
