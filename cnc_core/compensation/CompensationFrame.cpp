#include "cnc_core/compensation/CompensationFrame.h"

#include "cnc_core/contour/GneExpansion.h"

namespace mtc::core {

CompensationFrame CompensationFrame::of(const ModalState& modal, const ToolData& tool) {
    CompensationFrame frame;
    frame.axis1 = modal.plane.firstAxis();
    frame.axis2 = modal.plane.secondAxis();
    frame.transformation = modal.transformation;
    frame.radius = tool.radius;
    const bool turning = tool.turning() && !modal.transformation.active();
    // The same edge positions as the GNE cycles (docs/decisions/gne.md G-008).
    if (turning) frame.edge = tool.radius * gne::edgeVector(tool.orientation);
    // One axis gets a length under G48: a turning tool's is the 2nd plane axis
    // (X under G18, the turret holds it radially: L2), every other tool's the
    // perpendicular axis (L3), seed 003 ch. 3.6.
    frame.lengthAxis = turning ? frame.axis2 : modal.plane.perpendicularAxis();
    frame.length = turning ? tool.lengths[1] : tool.lengths[2];
    return frame;
}

bool CompensationFrame::sameGeometry(const CompensationFrame& other) const {
    const Transformation &a = transformation, &b = other.transformation;
    return axis1 == other.axis1 && axis2 == other.axis2 && a.kind() == b.kind() &&
           a.effectiveRadius() == b.effectiveRadius() && a.planeAxis(0) == b.planeAxis(0) &&
           a.planeAxis(1) == b.planeAxis(1);
}

bool CompensationFrame::sameTool(const CompensationFrame& other) const {
    return radius == other.radius && edge == other.edge;
}

comp::Vec2 CompensationFrame::toPlane(const ProcessAxes& axes,
                                      const std::array<double, kMaxAxes>& machine) const {
    const double m1 = machine[static_cast<std::size_t>(axis1)];
    const double m2 = machine[static_cast<std::size_t>(axis2)];
    if (!transformation.active()) return {m1, m2};
    double c1 = 0.0, c2 = 0.0;
    transformation.toPlane(axes, m1, m2, c1, c2);
    return {c1, c2};
}

void CompensationFrame::toMachine(const ProcessAxes& axes, const comp::Vec2& p,
                                  const std::array<double, kMaxAxes>& previous, double& m1,
                                  double& m2) const {
    if (!transformation.active()) {
        m1 = p.x();
        m2 = p.y();
        return;
    }
    transformation.toMachine(axes, p.x(), p.y(), previous[static_cast<std::size_t>(axis1)],
                             previous[static_cast<std::size_t>(axis2)], m1, m2);
}

void CompensationFrame::centreToMotion(const ProcessAxes& axes, const comp::Vec2& centre,
                                       const std::array<double, kMaxAxes>& previous, double& c1,
                                       double& c2) const {
    if (transformation.kind() == 32) return toMachine(axes, centre, previous, c1, c2);
    c1 = centre.x();
    c2 = centre.y();
}

bool CompensationFrame::rotaryUntransformed(const ProcessAxes& axes) const {
    for (int axis : {axis1, axis2})
        if (axis >= 0 && axes.axis(axis).rotary && !transformation.transforms(axis)) return true;
    return false;
}

}  // namespace mtc::core
