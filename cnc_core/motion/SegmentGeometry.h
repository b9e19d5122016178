#pragma once

#include "cnc_core/motion/PlaneMapping.h"

namespace mtc::core::motion {

/// The path of one move, parameterised by its length: a straight line over
/// every moving axis, or an arc in the plane of two axes with the other axes
/// moving linearly with it (helix). Coordinates are those of the move's
/// plane (PlaneMapping); the end is exactly Motion::end in machine positions.
class SegmentGeometry {
  public:
    /// Geometry of `motion` (G0/G1 lines, G2/G3 arcs and helices). The arc's
    /// sweep is arcSweep() with Motion::fullCircle (D-016).
    static SegmentGeometry of(const Motion& motion, const MotionLimits& limits);
    /// The same as `*this = of(motion, limits)`, worked out in place: a
    /// geometry is some 600 bytes, and the machine's queue slot is then
    /// written once instead of being zeroed, filled and copied per move.
    void describe(const Motion& motion, const MotionLimits& limits);

    bool arc() const { return arc_; }
    double length() const { return length_; }
    const PlaneMapping& mapping() const { return mapping_; }
    int axisCount() const { return axisCount_; }
    /// Start and end in plane coordinates.
    const Position& planeStart() const { return start_; }
    const Position& planeEnd() const { return end_; }
    /// Exact machine end position (Motion::end).
    const Position& machineEnd() const { return machineEnd_; }
    /// Unit tangent in plane coordinates at the start / end of the path.
    const Position& startTangent() const { return startTangent_; }
    const Position& endTangent() const { return endTangent_; }
    /// Arcs: radius at the start (plane units), signed sweep (radians, > 0
    /// counter-clockwise), plane axes.
    double radius() const { return radius0_; }
    double sweep() const { return sweep_; }
    int planeAxis1() const { return p1_; }
    int planeAxis2() const { return p2_; }

    /// Plane coordinates at path distance `s` (clamped to 0 .. length).
    void planePoint(double s, Position& plane) const;
    /// Machine position at path distance `s`; `machine` holds the previous
    /// machine position on entry (G31 angle continuity). s >= length gives
    /// exactly the end.
    void machinePoint(double s, Position& machine) const {
        if (!(s >= length_)) return machinePointOnPath(s, machine);
        // Inline for the end, where every move that runs to it arrives (MOT-026).
        for (int i = 0; i < axisCount_; ++i)
            machine[static_cast<std::size_t>(i)] = machineEnd_[static_cast<std::size_t>(i)];
    }
    /// Largest |tangent component| of `axis` anywhere along the path.
    double maxTangentComponent(int axis) const;

  private:
    /// machinePoint() short of the end.
    void machinePointOnPath(double s, Position& machine) const;
    /// `before`: axisCount() before describe() (the tangents are 0 from there on).
    void describeLine(int before);
    /// The arc's figures of a default geometry (a line has none).
    void clearArc();
    void describeArc(double c1, double c2, bool clockwise, bool fullCircle, int before);
    /// cos and sin of a polar angle around the arc's centre.
    struct Polar {
        double cos = 1.0, sin = 0.0;
    };
    static Polar polar(double d1, double d2, double radius, double angle);
    void arcTangent(Polar at, double radius, Position& tangent) const;

    PlaneMapping mapping_;
    int axisCount_ = 0;
    bool arc_ = false;
    Position start_{}, end_{}, machineEnd_{};
    Position startTangent_{}, endTangent_{};
    double length_ = 0.0;
    int p1_ = -1, p2_ = -1;
    double center1_ = 0.0, center2_ = 0.0;
    double radius0_ = 0.0, radius1_ = 0.0;
    double angle0_ = 0.0, sweep_ = 0.0;
    Polar startPolar_, endPolar_;
    double planeShare_ = 0.0;  ///< the plane's share of the unit tangent (< 1 on a helix)
};

/// Largest share of the first (`secondAxis` false) or second plane axis in
/// the unit tangent of a circle swept from polar angle `angle0` by `sweep`
/// radians (signed): max |sin| or max |cos| over the swept angles, given
/// that share at the start and the end of the sweep (|sin| or |cos| of
/// angle0 and angle0 + sweep, e.g. from the radius vectors: no trigonometry).
double arcTangentExtreme(double angle0, double sweep, bool secondAxis, double startShare,
                         double endShare);

}  // namespace mtc::core::motion
