#pragma once

#include <array>

/// The geometry the toolpath builder needs, free of state so that tests can
/// check it directly: chordal tessellation of arcs and the wrap of the
/// developed plane of lateral cylinder surface machining (seed 003, ch. 4)
/// onto its cylinder.
namespace mtc::core::curve {

inline constexpr double kPi = 3.14159265358979323846;

/// Greatest distance between an arc of `radius` and the chord spanning
/// `angle` radians of it (the sagitta r (1 - cos(angle / 2))).
double sagitta(double radius, double angle);

/// Most chords of one arc (or one wrapped G32 line): beyond it the drawing
/// is coarser than the tolerance (a radius of kilometres, thousands of turns)
/// instead of taking memory and time that grow with the programmed number.
inline constexpr double kMaxArcChords = 65536.0;

/// Chords an arc of `radius` sweeping `sweep` radians is drawn with so that
/// no chord is farther than `tolerance` from the arc: at least 1, at least one
/// per quarter turn, at most kMaxArcChords. A tolerance <= 0 is treated as
/// 0.001 mm.
int arcChords(double radius, double sweep, double tolerance);

// The sweep of an arc: arcSweep() in cnc_core/geometry/ArcSweep.h (D-016).

/// Developed coordinate (mm on the cylinder surface) of a rotary axis at
/// `degrees` with effective radius RI `radius`. The polar direction Cxx.076 = 1
/// reverses the sense (as Transformation does).
double developedFromDegrees(double degrees, double radius, int polarDirection);
/// The rotary axis position (degrees) of developed coordinate `millimetres`.
double degreesFromDeveloped(double millimetres, double radius, int polarDirection);

/// Point of the wrapped cylinder: the cylinder axis is scene axis `axial`
/// (0 X, 1 Y, 2 Z) through the origin, the angle `degrees` turns from the next
/// scene axis (axial + 1) towards the one after it (axial + 2), right-handed
/// about the cylinder axis; `along` is the position on the cylinder axis.
std::array<double, 3> cylinderPoint(int axial, double radius, double along, double degrees);

/// Distance of point p from the segment a-b (3D).
double distanceToSegment(const std::array<double, 3>& p, const std::array<double, 3>& a,
                         const std::array<double, 3>& b);

}  // namespace mtc::core::curve
