// The I controller of adaptive feed control over long spans of time: what
// lets a move under G26 be simulated with a bounded number of steps however
// long it lasts (AfcMotion). The 2 ms cycle is AdaptiveFeedControl::advance.
#include <algorithm>
#include <cmath>

#include "cnc_core/afc/AdaptiveFeedControl.h"

namespace mtc::core {
namespace {

/// 007 closer to 010 than this (% of nominal torque): the controller is settled.
constexpr double kSettledTorque = 1e-3;

}  // namespace

double AdaptiveFeedControl::expectedMachining(double reduction, double programmedFeed,
                                              double speedFraction, double engagement) const {
    const double factor = 1.0 - reduction / 100.0;
    return model_.expectedTorque(programmedFeed * factor, speedFraction * factor, engagement) -
           element(5) - stallCompensation();
}

bool AdaptiveFeedControl::settled(double programmedFeed, double speedFraction,
                                  double engagement) const {
    if (error510_ || !active_) return true;
    const double drift = expectedMachining(reduction_, programmedFeed, speedFraction, engagement) -
                         effectiveSettings().limitingTorque;
    if (reduction_ <= 0.0) return drift <= kSettledTorque;
    if (reduction_ >= 100.0) return drift >= -kSettledTorque;
    return std::fabs(drift) < kSettledTorque;
}

double AdaptiveFeedControl::torqueSlope(double programmedFeed, double speedFraction,
                                        double engagement) const {
    const double low = std::max(0.0, reduction_ - 0.5), high = std::min(100.0, reduction_ + 0.5);
    const double dm = expectedMachining(low, programmedFeed, speedFraction, engagement) -
                      expectedMachining(high, programmedFeed, speedFraction, engagement);
    return std::max(0.0, dm / (high - low));
}

double AdaptiveFeedControl::advanceSpan(double seconds, int samples, double programmedFeed,
                                        double speedFraction, double engagement,
                                        AfcTrendRecorder* recorder) {
    const double start = time_;
    const int count = std::max(1, samples);
    if (error510_ || !active_ || !(seconds > 0.0)) {
        time_ += std::max(0.0, seconds);
        return error510_ ? 0.0 : programmedFeed;
    }
    const AfcSettings s = effectiveSettings();
    const double before = reduction_;
    // Linearised implicit Euler of d011/dt = 003 * (007(011) - 010): the
    // reduction moves towards the equilibrium and never past it.
    const double drift =
        expectedMachining(before, programmedFeed, speedFraction, engagement) - s.limitingTorque;
    const double stiffness =
        s.amplification * torqueSlope(programmedFeed, speedFraction, engagement);
    const double after = std::clamp(
        before + s.amplification * drift * seconds / (1.0 + stiffness * seconds), 0.0, 100.0);
    const double step = seconds / count;
    for (int i = 1; i <= count; ++i) {
        reduction_ = before + (after - before) * i / count;
        time_ = start + i * step;
        const double factor = 1.0 - reduction_ / 100.0;
        const double actual =
            model_.actualTorque(programmedFeed * factor, speedFraction * factor, engagement, time_);
        afterControl(step, actual, actual - element(5) - stallCompensation(), s);
        if (recorder) recorder->add(trendSample(time_, error510_ ? 0.0 : programmedFeed * factor));
        if (error510_) break;
    }
    time_ = start + seconds;
    return error510_ ? 0.0 : programmedFeed * (1.0 - reduction_ / 100.0);
}

}  // namespace mtc::core
