#include "cnc_core/afc/AfcMotion.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "cnc_core/language/CheckedNumber.h"

namespace mtc::core {
namespace {

constexpr double kSampleEverySeconds = 0.010;  // trend resolution
constexpr int kMaxSamplesPerSpan = 2000;       // a long span or plain move: bounded samples
/// 2 ms cycles while the controller reacts (20 s); after that spans share
/// what is left of kAfcMaxStepsPerMove.
constexpr std::size_t kFineCycles = kAfcMaxStepsPerMove / 2;

/// The measuring period of ITM in the move, seconds after its start.
struct ItmWindow {
    bool measured = false;
    double from = 0.0;
    double to = 0.0;
};

/// Where the tool is in material at `share` of the path, `elapsed` seconds
/// into the move (docs/decisions/machine-data.md AFC-017).
double engagementAt(const AfcMoveInput& move, const ItmWindow& itm, double share, double elapsed,
                    bool controlled) {
    if (!move.feedMove) return 0.0;
    if (!withinCut(share, move.cutFrom, move.cutTo)) return 0.0;
    if (!itm.measured || move.materialKnown) return move.engagement;
    // No stock tells where the material is: an ITM block moves in air (what
    // ITM is for); with G26 in the same block the cut starts after the
    // measurement (seed 002 ch. 3: "right before machining").
    return controlled && elapsed >= itm.to ? move.engagement : 0.0;
}

int samplesFor(double seconds) {
    return clampedInteger(seconds / kSampleEverySeconds, 1, kMaxSamplesPerSpan);
}

/// ITM of the move: 508 / 509 become runtime errors. Returns false when the
/// move must stop after the measurement (509).
bool measureIdle(AdaptiveFeedControl& afc, const AfcMoveInput& move, ItmWindow& window,
                 AfcMoveResult& result) {
    afc.requestIdleMeasurement(false);
    const double feed = move.plannedSeconds > 0 ? move.length / move.plannedSeconds * 60.0 : 0.0;
    const double constant = std::max(0.0, move.plannedSeconds - 2.0 * move.accelerationSeconds);
    const double period = afc.effectiveSettings().measuringPeriodMs / 1000.0;
    window = {true, move.accelerationSeconds, move.accelerationSeconds + period};
    const double share = move.plannedSeconds > 0
                             ? std::min(1.0, (window.from + window.to) / 2 / move.plannedSeconds)
                             : 0.0;
    afc.setClock(move.startTime + window.from);
    const AfcStatus status =
        afc.measureIdleTorque(feed, move.speedFraction, constant, true,
                              engagementAt(move, window, share, window.from, afc.active()));
    if (status == AfcStatus::Ok) return true;
    afc.raiseRuntimeError(status, afc.message());
    if (status != AfcStatus::Error509) {  // 508: the block is known short at its end
        window.measured = false;          // nothing was measured
        return true;
    }
    result.fraction =
        move.plannedSeconds > 0 ? std::min(1.0, window.to / move.plannedSeconds) : 1.0;
    result.seconds = result.fraction * move.plannedSeconds;
    return false;
}

/// A move without G26: the torque is only observed for the trend, as one
/// record whose samples are made when the trend is read. The record is
/// written where the recorder keeps it (one per feed move of a run).
void observePlainMove(AdaptiveFeedControl& afc, const AfcMoveInput& move, const ItmWindow& itm,
                      AfcTrendRecorder* recorder) {
    if (!recorder || move.plannedSeconds <= 0) return;
    double lastActual = 0.0;
    double lastMachining = 0.0;
    recorder->addObserved([&](AfcObservedMove& observed) {
        const double feed = move.length / move.plannedSeconds * 60.0;
        afc.fillTrendSample(observed.constant, move.startTime, feed);
        observed.model = afc.model();
        observed.startTime = move.startTime;
        observed.plannedSeconds = move.plannedSeconds;
        observed.count = samplesFor(move.plannedSeconds);
        observed.feed = feed;
        observed.speedFraction = move.speedFraction;
        // The engagement rule of the whole cut, asked where the cut starts.
        observed.engagement =
            move.cutFrom < move.cutTo ? engagementAt(move, itm, move.cutFrom, 0.0, false) : 0.0;
        observed.cutFrom = move.cutFrom;
        observed.cutTo = move.cutTo;
        observed.itmMeasured = itm.measured;
        observed.itmFrom = itm.from;
        observed.itmTo = itm.to;
        observed.idleTorque = observed.constant.idleTorque;
        observed.stallCompensation = afc.stallCompensation();
        observed.torquesAt(observed.count, lastActual, lastMachining);
    });
    afc.setClock(move.startTime);
    afc.takeObservation(lastActual, lastMachining);
}

/// Seconds from `elapsed` / `travelled` until the engagement may change or
/// the path ends, at `feed` mm/min.
double secondsToBoundary(const AfcMoveInput& move, const ItmWindow& itm, double travelled,
                         double elapsed, double feed) {
    const double speed = feed / 60.0;
    double until = (move.length - travelled) / speed;
    for (double share : {move.cutFrom, move.cutTo}) {
        const double distance = share * move.length - travelled;
        if (distance > 1e-9) until = std::min(until, distance / speed);
    }
    if (itm.measured && elapsed < itm.to) until = std::min(until, itm.to - elapsed);
    return std::max(until, 0.0);
}

/// The state of one controlled move.
struct Progress {
    double travelled = 0.0;  ///< mm
    double elapsed = 0.0;    ///< s
    double standing = 0.0;   ///< s at feed 0
    double sinceSample = 0.0;
    std::size_t steps = 0;
};

/// One 2 ms controller cycle.
void fineCycle(AdaptiveFeedControl& afc, const AfcMoveInput& move, const ItmWindow& itm,
               double engagement, AfcTrendRecorder* recorder, Progress& p) {
    const double feed = afc.advance(kAfcCycleSeconds, move.feed, move.speedFraction, engagement);
    p.elapsed += kAfcCycleSeconds;
    p.travelled += feed / 60.0 * kAfcCycleSeconds;
    p.sinceSample += kAfcCycleSeconds;
    p.standing = feed <= 0.0 ? p.standing + kAfcCycleSeconds : 0.0;
    ++p.steps;
    if (recorder && p.sinceSample >= kSampleEverySeconds - 1e-9) {
        const bool measuring = itm.measured && p.elapsed >= itm.from && p.elapsed <= itm.to;
        recorder->add(afc.trendSample(move.startTime + p.elapsed, feed, measuring));
        p.sinceSample = 0.0;
    }
}

/// A span of time in one step (AdaptiveFeedControl::advanceSpan): to the
/// next boundary when the controller is settled (or the step budget is
/// spent), else a share of the remaining time that keeps the steps bounded.
void span(AdaptiveFeedControl& afc, const AfcMoveInput& move, const ItmWindow& itm,
          double engagement, bool settled, AfcTrendRecorder* recorder, Progress& p) {
    const double reduction = afc.effectiveReduction();
    const double feed = afc.errorPending() ? 0.0 : move.feed * (1.0 - reduction / 100.0);
    double seconds = 0.0;
    if (feed <= 0.0) {
        seconds = std::max(kAfcCycleSeconds, kAfcStandstillLimitSeconds - p.standing);
    } else {
        seconds = secondsToBoundary(move, itm, p.travelled, p.elapsed, feed);
        const std::size_t left = kAfcMaxStepsPerMove > p.steps ? kAfcMaxStepsPerMove - p.steps : 1;
        if (!settled && left > 1) seconds = std::max(kAfcCycleSeconds, seconds / left);
    }
    seconds = std::min(seconds, kAfcMaxMoveSeconds - p.elapsed);
    const double end = afc.advanceSpan(seconds, samplesFor(seconds), move.feed, move.speedFraction,
                                       engagement, recorder);
    const double meanFeed = (feed + end) / 2.0;
    p.travelled = std::min(move.length, p.travelled + meanFeed / 60.0 * seconds);
    p.elapsed += seconds;
    p.standing = end <= 0.0 ? p.standing + seconds : 0.0;
    ++p.steps;
}

/// G26 on a feed move: the I controller until the path is travelled.
void controlledMove(AdaptiveFeedControl& afc, const AfcMoveInput& move, const ItmWindow& itm,
                    AfcTrendRecorder* recorder, AfcMoveResult& result) {
    Progress p;
    motion::TimedCourse course;
    afc.setClock(move.startTime);
    while (p.travelled < move.length - 1e-9) {
        const double engagement =
            engagementAt(move, itm, p.travelled / move.length, p.elapsed, true);
        const bool settled = afc.settled(move.feed, move.speedFraction, engagement);
        const bool standing = afc.effectiveReduction() >= 100.0;  // 510 needs its 20 ms
        if ((!settled || standing) && p.steps < kFineCycles)
            fineCycle(afc, move, itm, engagement, recorder, p);
        else
            span(afc, move, itm, engagement, settled || p.steps + 1 >= kAfcMaxStepsPerMove,
                 recorder, p);
        course.add(p.elapsed, p.travelled);
        if (afc.errorPending()) break;  // error 510: the axes stop
        if (p.standing >= kAfcStandstillLimitSeconds) {
            afc.raiseRuntimeError(AfcStatus::FeedStopped,
                                  "the feed stood at 0 (100 % reduction allowed by 013) for " +
                                      std::to_string(static_cast<int>(kAfcStandstillLimitSeconds)) +
                                      " s; the simulation stops the program");
            break;
        }
        if (p.elapsed >= kAfcMaxMoveSeconds - 1e-9) {
            afc.raiseRuntimeError(
                AfcStatus::MoveTooLong,
                "the move under G26 would last longer than " +
                    std::to_string(static_cast<int>(kAfcMaxMoveSeconds)) +
                    " s of simulated time; the simulation stops it (program a shorter path or a "
                    "higher feed)");
            break;
        }
    }
    result.adapted = true;
    result.seconds = p.elapsed;
    result.steps = p.steps;
    const bool arrived = p.travelled >= move.length - 1e-9;  // the loop's own tolerance
    result.fraction = arrived || move.length <= 0 ? 1.0 : p.travelled / move.length;
    if (course.finish(p.elapsed, p.travelled))
        result.course = std::make_shared<const motion::TimedCourse>(std::move(course));
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
    ItmWindow itm;
    bool goOn = true;
    if (afc.idleMeasurementRequested()) goOn = measureIdle(afc, move, itm, result);
    if (goOn && afc.active() && move.feedMove && move.length > 0 && move.feed > 0 &&
        !afc.errorPending())
        controlledMove(afc, move, itm, recorder, result);
    else if (goOn)
        observePlainMove(afc, move, itm, recorder);
    if (result.seconds > 0) result.meanFeed = move.length * result.fraction / result.seconds * 60.0;
    if (result.fraction < 1.0) afc.setStopFraction(result.fraction);
    afc.setClock(move.startTime + result.seconds);
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
    p.seed = clampedInteger<std::uint64_t>(parameter(process, "seed", 2002));
    return p;
}

double cuttingEngagement(const ProcessConfig& process) {
    return std::max(0.0, parameter(process, "engagement", 1.0));
}

}  // namespace mtc::core
