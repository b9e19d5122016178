#pragma once

/// The one arc rule of the control (docs/DECISIONS.md D-016): when an arc is
/// a full circle and how far an arc turns. Every layer that turns an arc's
/// start, end and centre into an angle (interpreter, tool compensation,
/// machine motion, tool path view, NC compiler, GNE contours) asks here.
namespace mtc::core {

/// Start and end of a programmed G2 / G3 closer than this (mm, in the plane)
/// make one whole turn. It is the interpreter's radius tolerance
/// (InterpreterOptions::arcTolerance, decision I-009): an end point that
/// counts as "on the circle" within it also counts as "at the start" within it.
inline constexpr double kFullCircleChord = 0.002;

/// Directions of start and end (seen from the centre) closer than this
/// (radians) are the same direction: an arc of that little turn is a full
/// circle even when its flag was not carried (e.g. an arc from a point to
/// itself built by a test or a jog).
inline constexpr double kSameDirection = 1e-12;

/// The full-circle decision of a programmed arc: start (s1, s2) and end
/// (e1, e2) in the plane are at most `chord` apart. Inline: the interpreter
/// asks it for every arc, and a call there costs its registers.
inline bool closesCircle(double s1, double s2, double e1, double e2,
                         double chord = kFullCircleChord) {
    const double d1 = e1 - s1, d2 = e2 - s2;
    return d1 * d1 + d2 * d2 <= chord * chord;
}

/// Signed angle (radians; positive counter-clockwise) an arc turns from start
/// (s1, s2) to end (e1, e2) around the centre (c1, c2) in the (1, 2) plane:
///  - `fullCircle` (closesCircle() of the programmed arc): +-2 pi;
///  - otherwise the angle in the arc's sense, in (0, 2 pi]: an end just
///    behind the start gives almost a whole turn, and an end in the start's
///    direction (within kSameDirection) a whole turn.
/// Magnitude in (0, 2 pi], sign by `clockwise`; never NaN for finite input
/// (a point at the centre has direction 0).
double arcSweep(double s1, double s2, double e1, double e2, double c1, double c2, bool clockwise,
                bool fullCircle);

}  // namespace mtc::core
