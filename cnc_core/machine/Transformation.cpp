#include "cnc_core/machine/Transformation.h"

#include <cmath>

namespace mtc::core {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegPerRad = 180.0 / kPi;

double rotationSign(const AxisModel& axis) {
    return axis.polarDirection == 1 ? -1.0 : 1.0;
}

void checkNotOtherActive(int current, int wanted, std::vector<PlaneProblem>& problems) {
    if (current != 30 && current != wanted)
        problems.push_back({"TRANSFORMATION_SWITCH",
                            "G" + std::to_string(current) +
                                " is active: deselect it with G30 before G" +
                                std::to_string(wanted),
                            0});
}

bool planeAxesExist(const PlaneSelection& plane, std::vector<PlaneProblem>& problems) {
    if (plane.firstAxis() >= 0 && plane.secondAxis() >= 0) return true;
    problems.push_back({"TRANSFORMATION_PLANE", "the working plane is not spanned by two axes", 0});
    return false;
}

}  // namespace

double nearestTurn(double degrees, double reference) {
    const double turns = std::round((reference - degrees) / 360.0);
    return degrees + turns * 360.0;
}

std::vector<PlaneProblem> Transformation::selectCylinder(const ProcessAxes& axes,
                                                         const PlaneSelection& plane,
                                                         bool radiusGiven, double radius) {
    std::vector<PlaneProblem> problems;
    checkNotOtherActive(kind_, 32, problems);
    if (!radiusGiven)
        problems.push_back({"G32_RI_MISSING", "G32 needs the effective radius RI", 0});
    else if (!(radius > 0.0))
        problems.push_back({"G32_RI_NOT_POSITIVE", "the effective radius RI must be > 0", 0});
    else if (kind_ == 32 && radius != radius_)
        problems.push_back(
            {"G32_RI_CHANGE", "RI cannot change while G32 is active; deselect with G30 first", 0});
    if (!planeAxesExist(plane, problems)) return problems;
    const int a1 = plane.firstAxis(), a2 = plane.secondAxis();
    if (!axes.axis(a1).rotary && !axes.axis(a2).rotary)
        problems.push_back({"G32_NO_ROTARY_AXIS",
                            "G32 needs a rotary axis in the working plane (select it with G20)",
                            0});
    if (!problems.empty()) return problems;
    kind_ = 32;
    radius_ = radius;
    axis1_ = a1;
    axis2_ = a2;
    return problems;
}

std::vector<PlaneProblem> Transformation::selectFacing(const ProcessAxes& axes,
                                                       const PlaneSelection& plane) {
    std::vector<PlaneProblem> problems;
    checkNotOtherActive(kind_, 31, problems);
    if (!planeAxesExist(plane, problems)) return problems;
    const int a1 = plane.firstAxis(), a2 = plane.secondAxis();
    if (axes.axis(a1).rotary == axes.axis(a2).rotary)
        problems.push_back(
            {"G31_PLANE", "G31 needs one linear and one rotary axis in the working plane", 0});
    if (!problems.empty()) return problems;
    kind_ = 31;
    radius_ = 0.0;
    axis1_ = a1;
    axis2_ = a2;
    return problems;
}

double Transformation::cylinderDegrees(const ProcessAxes& axes, int axis,
                                       double millimetres) const {
    if (!axes.axis(axis).rotary) return millimetres;
    return rotationSign(axes.axis(axis)) * millimetres / radius_ * kDegPerRad;
}

double Transformation::cylinderMillimetres(const ProcessAxes& axes, int axis,
                                           double degrees) const {
    if (!axes.axis(axis).rotary) return degrees;
    return rotationSign(axes.axis(axis)) * degrees / kDegPerRad * radius_;
}

void Transformation::toMachine(const ProcessAxes& axes, double c1, double c2, double previous1,
                               double previous2, double& m1, double& m2) const {
    if (kind_ == 32) {
        m1 = cylinderDegrees(axes, axis1_, c1);
        m2 = cylinderDegrees(axes, axis2_, c2);
        return;
    }
    if (kind_ != 31) {
        m1 = c1;
        m2 = c2;
        return;
    }
    const bool linearFirst = !axes.axis(axis1_).rotary;
    const int linear = linearFirst ? axis1_ : axis2_;
    const int rotary = linearFirst ? axis2_ : axis1_;
    const double cl = linearFirst ? c1 : c2, cr = linearFirst ? c2 : c1;
    const double previousAngle = linearFirst ? previous2 : previous1;
    double radius = std::hypot(cl, cr);
    double angle = radius == 0.0 ? previousAngle * rotationSign(axes.axis(rotary))
                                 : std::atan2(cr, cl) * kDegPerRad;
    if (axes.axis(linear).polarDirection == 1 && radius != 0.0) {
        radius = -radius;
        angle += 180.0;
    }
    const double machineAngle = nearestTurn(rotationSign(axes.axis(rotary)) * angle, previousAngle);
    (linearFirst ? m1 : m2) = radius;
    (linearFirst ? m2 : m1) = machineAngle;
}

void Transformation::toPlane(const ProcessAxes& axes, double m1, double m2, double& c1,
                             double& c2) const {
    if (kind_ == 32) {
        c1 = cylinderMillimetres(axes, axis1_, m1);
        c2 = cylinderMillimetres(axes, axis2_, m2);
        return;
    }
    if (kind_ != 31) {
        c1 = m1;
        c2 = m2;
        return;
    }
    const bool linearFirst = !axes.axis(axis1_).rotary;
    const int rotary = linearFirst ? axis2_ : axis1_;
    const double radius = linearFirst ? m1 : m2;
    const double angle = rotationSign(axes.axis(rotary)) * (linearFirst ? m2 : m1) / kDegPerRad;
    (linearFirst ? c1 : c2) = radius * std::cos(angle);
    (linearFirst ? c2 : c1) = radius * std::sin(angle);
}

}  // namespace mtc::core
