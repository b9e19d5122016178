#include "cnc_core/afc/AfcMotion.h"

#include <algorithm>
#include <cmath>

namespace mtc::core {
namespace {

constexpr double kSampleEverySeconds = 0.010;  // trend resolution
constexpr int kMaxSamplesPerPlainMove = 2000;  // moves without G26: bounded cost

/// ITM of the move: 508 / 509 become runtime errors. Returns false when the
/// move must stop after the measurement (509).
bool measureIdle(AdaptiveFeedControl& afc, const AfcMoveInput& move, AfcMoveResult& result) {
    afc.requestIdleMeasurement(false);
    const double feed = move.plannedSeconds > 0 ? move.length / move.plannedSeconds * 60.0 : 0.0;
    const double constant = std::max(0.0, move.plannedSeconds - 2.0 * move.accelerationSeconds);
    const AfcStatus status = afc.measureIdleTorque(feed, move.speedFraction, constant, true);
    if (status == AfcStatus::Ok) return true;
    afc.raiseRuntimeError(status, afc.message());
    if (status != AfcStatus::Error509) return true;  // 508: the block is known short at its end
    const double measured =
        move.accelerationSeconds + afc.effectiveSettings().measuringPeriodMs / 1000.0;
    result.fraction = move.plannedSeconds > 0 ? std::min(1.0, measured / move.plannedSeconds) : 1.0;
    result.seconds = result.fraction * move.plannedSeconds;
    return false;
}

/// A move without G26: the torque is only observed for the trend.
void observePlainMove(AdaptiveFeedControl& afc, const AfcMoveInput& move,
                      AfcTrendRecorder* recorder) {
    if (!recorder || move.plannedSeconds <= 0) return;
    const int samples = std::clamp(static_cast<int>(move.plannedSeconds / kSampleEverySeconds), 1,
                                   kMaxSamplesPerPlainMove);
    const double step = move.plannedSeconds / samples;
    const double engagement = move.feedMove ? move.engagement : 0.0;
    const double feed = move.length / move.plannedSeconds * 60.0;
    for (int i = 1; i <= samples; ++i) {
        afc.observe(feed, move.speedFraction, engagement);
        recorder->add(afc.trendSample(move.startTime + i * step, feed));
    }
}

/// G26 on a feed move: the I controller cycle by cycle.
void controlledMove(AdaptiveFeedControl& afc, const AfcMoveInput& move, AfcTrendRecorder* recorder,
                    AfcMoveResult& result) {
    double travelled = 0.0, seconds = 0.0, standing = 0.0, sinceSample = 0.0;
    while (travelled < move.length) {
        const double feed =
            afc.advance(kAfcCycleSeconds, move.feed, move.speedFraction, move.engagement);
        seconds += kAfcCycleSeconds;
        travelled += feed / 60.0 * kAfcCycleSeconds;
        sinceSample += kAfcCycleSeconds;
        if (recorder && sinceSample >= kSampleEverySeconds - 1e-9) {
            recorder->add(afc.trendSample(move.startTime + seconds, feed));
            sinceSample = 0.0;
        }
        if (afc.errorPending()) break;  // error 510: the axes stop
        standing = feed <= 0.0 ? standing + kAfcCycleSeconds : 0.0;
        if (standing >= kAfcStandstillLimitSeconds) {
            afc.raiseRuntimeError(AfcStatus::FeedStopped,
                                  "the feed stood at 0 (100 % reduction allowed by 013) for " +
                                      std::to_string(static_cast<int>(kAfcStandstillLimitSeconds)) +
                                      " s; the simulation stops the program");
            break;
        }
    }
    result.adapted = true;
    result.seconds = seconds;
    result.fraction = move.length > 0 ? std::min(1.0, travelled / move.length) : 1.0;
}

double parameter(const ProcessConfig& process, const char* key, double fallback) {
    auto found = process.torqueModel.find(key);
    return found == process.torqueModel.end() ? fallback : found->second;
}

}  // namespace

AfcMoveResult simulateAfcMove(AdaptiveFeedControl& afc, const AfcMoveInput& move,
                              AfcTrendRecorder* recorder) {
    AfcMoveResult result;
    result.seconds = move.plannedSeconds;
    bool goOn = true;
    if (afc.idleMeasurementRequested()) goOn = measureIdle(afc, move, result);
    if (goOn && afc.active() && move.feedMove && move.length > 0 && move.feed > 0 &&
        !afc.errorPending())
        controlledMove(afc, move, recorder, result);
    else if (goOn)
        observePlainMove(afc, move, recorder);
    if (result.seconds > 0) result.meanFeed = move.length * result.fraction / result.seconds * 60.0;
    afc.addExtraSeconds(result.seconds - move.plannedSeconds);
    return result;
}

TorqueModelParameters torqueModelFromConfig(const ProcessConfig& process) {
    TorqueModelParameters p;
    p.stallTorque = parameter(process, "stall", p.stallTorque);
    p.frictionAtRest = parameter(process, "friction_rest", p.frictionAtRest);
    p.frictionAtMaxSpeed = parameter(process, "friction_max", p.frictionAtMaxSpeed);
    p.cuttingTorque = parameter(process, "cutting", p.cuttingTorque);
    p.referenceFeed = parameter(process, "reference_feed", p.referenceFeed);
    p.feedExponent = parameter(process, "exponent", p.feedExponent);
    p.constantLoad = parameter(process, "load", p.constantLoad);
    p.noiseAmplitude = parameter(process, "noise", p.noiseAmplitude);
    p.seed = static_cast<std::uint64_t>(std::max(0.0, parameter(process, "seed", 2002)));
    return p;
}

double cuttingEngagement(const ProcessConfig& process) {
    return std::max(0.0, parameter(process, "engagement", 1.0));
}

}  // namespace mtc::core
