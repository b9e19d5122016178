#pragma once

#include <vector>

#include "cnc_core/machine/PlaneSelection.h"
#include "cnc_core/machine/ProcessAxes.h"

namespace mtc::core {

/// The transformation functions of G code group 17 (seed 003, ch. 4):
/// G30 none, G31 facing (polar coordinate transformation), G32 lateral
/// cylinder surface machining with effective radius RI. A small value type
/// copied with the interpreter state.
///
/// Coordinates: while G31/G32 is active the two plane axes are programmed in
/// a fictitious cartesian plane (mm). `toMachine` turns those plane
/// coordinates into machine positions (linear axes in mm, rotary axes in
/// degrees); `toPlane` is the inverse. The polar direction Cxx.076 of the
/// rotary axis reverses its sense of rotation; that of the linear axis puts
/// facing after the rotation centre (negative radius).
class Transformation {
  public:
    int kind() const { return kind_; }  ///< 30, 31 or 32
    bool active() const { return kind_ != 30; }
    double effectiveRadius() const { return radius_; }
    int planeAxis(int i) const { return i == 0 ? axis1_ : axis2_; }
    /// True when machine axis `axis` spans the transformed plane.
    bool transforms(int axis) const { return active() && (axis == axis1_ || axis == axis2_); }

    /// G32 RI: checks RI given and > 0, no other transformation active, RI
    /// unchanged when G32 is already active, and a rotary axis in the plane.
    /// On a problem nothing changes.
    std::vector<PlaneProblem> selectCylinder(const ProcessAxes& axes, const PlaneSelection& plane,
                                             bool radiusGiven, double radius);
    /// G31: the plane must be spanned by one linear and one rotary axis and
    /// no other transformation may be active. On a problem nothing changes.
    std::vector<PlaneProblem> selectFacing(const ProcessAxes& axes, const PlaneSelection& plane);
    /// G30: no transformation.
    void deselect() { *this = Transformation(); }

    /// Plane coordinates (c1 of plane axis 1, c2 of plane axis 2, mm) to
    /// machine positions m1, m2. `previous1/2` are the machine positions
    /// before the move: rotary results take the turn nearest to them, and at
    /// the rotation centre (G31) the angle keeps its previous value.
    void toMachine(const ProcessAxes& axes, double c1, double c2, double previous1,
                   double previous2, double& m1, double& m2) const;
    /// Machine positions m1, m2 of the plane axes to plane coordinates.
    void toPlane(const ProcessAxes& axes, double m1, double m2, double& c1, double& c2) const;

  private:
    double cylinderDegrees(const ProcessAxes& axes, int axis, double millimetres) const;
    double cylinderMillimetres(const ProcessAxes& axes, int axis, double degrees) const;

    int kind_ = 30;
    double radius_ = 0.0;
    int axis1_ = -1, axis2_ = -1;
};

/// The angle `degrees` + k * 360 that lies nearest to `reference`.
double nearestTurn(double degrees, double reference);

}  // namespace mtc::core
