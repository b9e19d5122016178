#pragma once

#include <array>

namespace mtc::core::motion {

/// Velocity over time along (the rest of) one segment, in closed form: at
/// most three phases of constant acceleration (towards the cruise velocity,
/// cruise, down to the end velocity) — the trapezoid, or the triangle when
/// the segment is too short to reach the cruise velocity. Planned from any
/// state, so a change of override, a feed hold or a new look-ahead limit
/// re-plans from where the axes are, without a jump in position or velocity.
class SegmentProfile {
  public:
    /// Plans the path from position `s0` with velocity `v0` over `length`
    /// towards the cruise velocity `cap` (0 = come to rest: feed hold,
    /// override 0 %), ending at `vEnd` (at most `cap`) with acceleration
    /// `acceleration` (> 0). Where `vEnd` cannot be reached the profile
    /// ends as near to it as the acceleration allows (a velocity above it
    /// after an override cut is carried into the next segment).
    void plan(double s0, double v0, double length, double cap, double vEnd, double acceleration);

    /// True when the profile reaches the end of the segment; false when it
    /// comes to rest before (then it rests there for ever).
    bool reachesEnd() const { return reachesEnd_; }
    /// Time from the plan to the end of the segment or to rest, s.
    double duration() const { return duration_; }
    /// Velocity at the end of the segment (or 0 at rest).
    double endVelocity() const { return endVelocity_; }
    /// Path position (s0 + travelled) at the end or at rest.
    double endPosition() const { return endPosition_; }
    /// Path position and velocity `t` seconds after the plan (t >= 0).
    void sample(double t, double& s, double& v) const;

  private:
    /// A phase of constant acceleration. Where it starts (position and
    /// velocity) follows from the phases before it and is worked out by
    /// sample() only: a run that never samples (the CLI's, MOT-026) needs
    /// the durations alone.
    struct Phase {
        double duration = 0.0;
        double acceleration = 0.0;
    };
    void addPhase(double duration, double acceleration) {
        if (!(duration > 0.0)) return;
        phases_[static_cast<std::size_t>(count_)] = {duration, acceleration};
        duration_ += duration;
        ++count_;
    }
    void finish(double endPosition, double endVelocity, bool reachesEnd);

    std::array<Phase, 3> phases_{};
    int count_ = 0;
    double s0_ = 0.0, v0_ = 0.0;
    double duration_ = 0.0;
    double endVelocity_ = 0.0;
    double endPosition_ = 0.0;
    bool reachesEnd_ = true;
};

}  // namespace mtc::core::motion
