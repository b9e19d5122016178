#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "cnc_core/interp/MachineSink.h"
#include "cnc_core/machine/ProcessAxes.h"

namespace mtc::core {

/// One axis word of a G20 block, in program order.
struct FreePlaneAxis {
    int axis = -1;       ///< machine axis index
    double value = 0.0;  ///< the programmed value (must be 0)
    int column = 0;      ///< source column of the word, for diagnostics
};

/// A broken boundary condition of G20 (seed 003, 3.2), or a plane that the
/// machine cannot span. `code` is stable; `column` points at the axis word.
struct PlaneProblem {
    std::string code;
    std::string message;
    int column = 0;
};

/// The working plane and the allocation of axis definitions (X Y Z U V W A B C)
/// to the machine axes: G17, G18, G19 and free plane selection G20 (seed 003,
/// ch. 3 and 5.1). A small value type (copied with the interpreter state);
/// the axis table is passed in where needed.
class PlaneSelection {
  public:
    /// Base coordinate system (first definition of every axis) and plane
    /// `plane` (17, 18 or 19; anything else gives 17).
    static PlaneSelection base(const ProcessAxes& axes, int plane);

    /// G17/G18/G19: restores the base allocation and selects the plane.
    /// Fails (returns a problem, changes nothing) when the machine lacks an
    /// axis with the plane's 1st or 2nd definition.
    std::vector<PlaneProblem> selectStandard(const ProcessAxes& axes, int plane);

    /// G20 with 2 or 3 axes (1st plane axis, 2nd plane axis, perpendicular).
    /// Checks every boundary condition; on any problem nothing changes.
    /// Allocation: start from the allocation in force; the n-th axis
    /// receives definition X, Y, Z (n = 1, 2, 3); the axis that held that
    /// definition receives the programmed axis's previous definition (a
    /// swap). With two axes the axis holding Z keeps it unless a swap moves
    /// it (it must be linear). docs/decisions/interpreter.md I-010, I-010a.
    std::vector<PlaneProblem> selectFree(const ProcessAxes& axes,
                                         const std::vector<FreePlaneAxis>& programmed);

    int plane() const { return plane_; }  ///< 17, 18, 19 or 20
    /// Machine axis holding `definition`, or -1.
    int axisOf(AxisDefinition definition) const {
        return definition == AxisDefinition::None
                   ? -1
                   : axisOfDefinition_[static_cast<size_t>(definition)];
    }
    /// Current definition of machine axis `axis` (None = no functionality).
    AxisDefinition definitionOf(int axis) const {
        return definitionOfAxis_[static_cast<size_t>(axis)];
    }
    /// Definitions spanning the plane: 1st axis, 2nd axis, perpendicular.
    std::array<AxisDefinition, 3> planeDefinitions() const {
        switch (plane_) {
            case 18:
                return {AxisDefinition::Z, AxisDefinition::X, AxisDefinition::Y};
            case 19:
                return {AxisDefinition::Y, AxisDefinition::Z, AxisDefinition::X};
            default:
                return {AxisDefinition::X, AxisDefinition::Y, AxisDefinition::Z};
        }
    }
    int firstAxis() const { return axisOf(planeDefinitions()[0]); }
    int secondAxis() const { return axisOf(planeDefinitions()[1]); }
    int perpendicularAxis() const { return axisOf(planeDefinitions()[2]); }
    /// True when the allocation differs from the base coordinate system.
    bool isBase(const ProcessAxes& axes) const;
    /// Same plane and same allocation of every definition (one byte compare:
    /// the motion planner asks it once per block, MOT-025).
    bool sameAs(const PlaneSelection& other) const {
        static_assert(sizeof(PlaneSelection) == kDefinitionCount + kMaxAxes + 1, "no padding");
        return std::memcmp(this, &other, sizeof(PlaneSelection)) == 0;
    }

  private:
    void assign(int axis, AxisDefinition definition);

    std::array<std::int8_t, kDefinitionCount> axisOfDefinition_{};
    std::array<AxisDefinition, kMaxAxes> definitionOfAxis_{};
    std::int8_t plane_ = 17;
};

}  // namespace mtc::core
