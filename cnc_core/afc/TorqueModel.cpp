#include "cnc_core/afc/TorqueModel.h"

#include <algorithm>
#include <cmath>

namespace mtc::core {

TorqueModel::TorqueModel(TorqueModelParameters parameters) : p_(parameters), state_(0) {
    reseed(p_.seed);
}

void TorqueModel::reseed(std::uint64_t seed) {
    state_ = seed ? seed : 0x9E3779B97F4A7C15ull;  // xorshift must not start at 0
}

double TorqueModel::noise() {
    state_ ^= state_ << 13;
    state_ ^= state_ >> 7;
    state_ ^= state_ << 17;
    const double unit = static_cast<double>(state_ >> 11) / 9007199254740992.0;  // [0, 1)
    return (2.0 * unit - 1.0) * p_.noiseAmplitude;
}

double TorqueModel::expectedTorque(double feed, double speedFraction, double engagement) const {
    const double speed = std::clamp(speedFraction, 0.0, 1.0);
    const double friction =
        feed > 0.0 ? p_.frictionAtRest + (p_.frictionAtMaxSpeed - p_.frictionAtRest) * speed : 0.0;
    const double chip = feed > 0.0 && p_.referenceFeed > 0.0
                            ? std::pow(feed / p_.referenceFeed, p_.feedExponent)
                            : 0.0;
    return p_.stallTorque + friction + p_.cuttingTorque * std::max(0.0, engagement) * chip +
           p_.constantLoad;
}

double TorqueModel::actualTorque(double feed, double speedFraction, double engagement) {
    return expectedTorque(feed, speedFraction, engagement) + noise();
}

}  // namespace mtc::core
