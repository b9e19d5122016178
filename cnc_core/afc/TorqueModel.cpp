#include "cnc_core/afc/TorqueModel.h"

#include <algorithm>
#include <cmath>

namespace mtc::core {

TorqueModel::TorqueModel(TorqueModelParameters parameters) : p_(parameters) {}

double TorqueModel::noise(double seconds) const {
    // splitmix64 of (seed, millisecond): stateless, so the value depends on
    // the moment only, not on how many samples were taken before.
    const double ms = seconds > 0.0 ? std::min(seconds, 1e15) * 1000.0 : 0.0;  // NaN: 0
    const auto tick = static_cast<std::uint64_t>(std::llround(ms));
    std::uint64_t z = p_.seed + 0x9E3779B97F4A7C15ull * (tick + 1);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    const double unit = static_cast<double>(z >> 11) / 9007199254740992.0;  // [0, 1)
    return (2.0 * unit - 1.0) * p_.noiseAmplitude;
}

double TorqueModel::expectedTorque(double feed, double speedFraction, double engagement) const {
    const double speed = std::clamp(speedFraction, 0.0, 1.0);
    const double friction =
        feed > 0.0 ? p_.frictionAtRest + (p_.frictionAtMaxSpeed - p_.frictionAtRest) * speed : 0.0;
    // Cutting air (most moves of a program) needs no power of the feed.
    const double engaged = std::max(0.0, engagement);
    const double chip = engaged > 0.0 && feed > 0.0 && p_.referenceFeed > 0.0
                            ? std::pow(feed / p_.referenceFeed, p_.feedExponent)
                            : 0.0;
    return p_.stallTorque + friction + p_.cuttingTorque * engaged * chip + p_.constantLoad;
}

double TorqueModel::actualTorque(double feed, double speedFraction, double engagement,
                                 double seconds) const {
    return expectedTorque(feed, speedFraction, engagement) + noise(seconds);
}

}  // namespace mtc::core
