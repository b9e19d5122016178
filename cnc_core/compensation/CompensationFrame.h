#pragma once

#include <array>

#include "cnc_core/compensation/PlanePath.h"
#include "cnc_core/compensation/ToolData.h"
#include "cnc_core/interp/MachineSink.h"
#include "cnc_core/machine/ProcessAxes.h"
#include "cnc_core/machine/Transformation.h"

namespace mtc::core {

/// The coordinate frame tool compensation works in: the working plane's two
/// axes with the transformation (G31/G32) that maps them, and the tool in
/// working position. Plane coordinates are the programmed plane with its
/// zero offsets applied, before the transformation (mm on the developed
/// surface under G32, the fictitious cartesian plane under G31): a change of
/// zero offset does not move them.
struct CompensationFrame {
    int axis1 = -1, axis2 = -1;  ///< machine axes spanning the plane (1st, 2nd)
    Transformation transformation;
    double radius = 0.0;  ///< tool radius (cutter radius, nose radius)
    /// Turning tool without transformation: the tool reference point (the
    /// theoretical tip) minus the nose centre, in plane coordinates.
    comp::Vec2 edge = comp::Vec2::Zero();
    int lengthAxis = -1;  ///< the axis G48 moves by the tool length
    double length = 0.0;  ///< tool length

    /// The frame of `modal` with `tool` in working position (TC-005, TC-008).
    static CompensationFrame of(const ModalState& modal, const ToolData& tool);

    /// Same plane axes and transformation.
    bool sameGeometry(const CompensationFrame& other) const;
    /// Same radius and edge offset.
    bool sameTool(const CompensationFrame& other) const;

    /// Plane coordinates of machine positions.
    comp::Vec2 toPlane(const ProcessAxes& axes, const std::array<double, kMaxAxes>& machine) const;
    /// Machine positions of the plane axes for plane point `p`; `previous`
    /// are the positions before the move (rotary axes take the nearest turn).
    void toMachine(const ProcessAxes& axes, const comp::Vec2& p,
                   const std::array<double, kMaxAxes>& previous, double& m1, double& m2) const;
    /// An arc centre as Motion carries it (G32: machine positions, otherwise
    /// plane coordinates; interpreter.md I-015).
    void centreToMotion(const ProcessAxes& axes, const comp::Vec2& centre,
                        const std::array<double, kMaxAxes>& previous, double& c1, double& c2) const;
    /// A plane axis is a rotary axis no transformation maps (seed 003, 4.2:
    /// no radius compensation then).
    bool rotaryUntransformed(const ProcessAxes& axes) const;
};

}  // namespace mtc::core
