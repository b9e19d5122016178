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
/// The noise is a function of the seed and the machine time (one value per
/// millisecond, a counter-based generator): whoever asks at the same moment
/// of the same run gets the same value, so the CLI and the panel see the same
/// noise however often they sample (trend, controller, ITM).
class TorqueModel {
  public:
    explicit TorqueModel(TorqueModelParameters parameters = {});

    const TorqueModelParameters& parameters() const { return p_; }
    /// The actual torque at machine time `seconds`. `feed` mm/min
    /// (effective), `speedFraction` 0..1 of the axis' maximum speed,
    /// `engagement` >= 0.
    double actualTorque(double feed, double speedFraction, double engagement, double seconds) const;
    /// The torque without noise (for tests and the trend's expectations).
    double expectedTorque(double feed, double speedFraction, double engagement) const;
    /// The noise at machine time `seconds` (uniform in ± noiseAmplitude).
    double noise(double seconds) const;
    /// Changes the feed-independent load (a jam appears or goes away).
    void setConstantLoad(double percent) { p_.constantLoad = percent; }

  private:
    TorqueModelParameters p_;
};

}  // namespace mtc::core
