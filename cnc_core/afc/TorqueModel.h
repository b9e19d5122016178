#pragma once

#include <cstdint>

namespace mtc::core {

/// Constants of the simulated reference axis (all torques in % of the
/// nominal drive torque, seed 002 2.2). Defaults: a spindle-driven milling
/// cut where full engagement at 1000 mm/min takes 60 % of nominal torque.
struct TorqueModelParameters {
    double stallTorque = 0.0;          ///< weight torque of an inclined axis (signed), %
    double frictionAtRest = 6.0;       ///< idling torque when the axis just moves, %
    double frictionAtMaxSpeed = 10.0;  ///< idling torque at maximum speed, %
    double cuttingTorque = 60.0;       ///< cutting torque at full engagement and referenceFeed, %
    double referenceFeed = 1000.0;     ///< mm/min
    double feedExponent = 0.8;         ///< cutting torque grows with feed^exponent (chip thickness)
    double constantLoad = 0.0;    ///< load that stays at any feed (jam, clamping not released), %
    double noiseAmplitude = 1.0;  ///< uniform noise ± this, %
    std::uint64_t seed = 2002;    ///< deterministic noise
};

/// The torque/force actual value (S-0-0084) of the reference axis:
///   M_act = M_stall + M_friction(speed) + M_cut(feed, engagement) + M_load + noise
///   M_friction = frictionAtRest + (frictionAtMaxSpeed - frictionAtRest) * speedFraction
///               (0 when the axis stands still)
///   M_cut = cuttingTorque * engagement * (feed / referenceFeed)^feedExponent
///   M_load = constantLoad (while the axis is held, whatever the feed)
/// Engagement 0 = cutting air, 1 = the full cut the coefficients describe.
/// The noise comes from a xorshift generator: the same seed gives the same run.
class TorqueModel {
  public:
    explicit TorqueModel(TorqueModelParameters parameters = {});

    const TorqueModelParameters& parameters() const { return p_; }
    /// One sample of the actual torque. `feed` mm/min (effective),
    /// `speedFraction` 0..1 of the axis' maximum speed, `engagement` >= 0.
    double actualTorque(double feed, double speedFraction, double engagement);
    /// The torque without noise (for tests and the trend's expectations).
    double expectedTorque(double feed, double speedFraction, double engagement) const;
    /// Changes the feed-independent load (a jam appears or goes away).
    void setConstantLoad(double percent) { p_.constantLoad = percent; }
    /// Starts the noise sequence again.
    void reseed(std::uint64_t seed);

  private:
    double noise();

    TorqueModelParameters p_;
    std::uint64_t state_;
};

}  // namespace mtc::core
