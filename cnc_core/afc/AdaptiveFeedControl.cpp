#include "cnc_core/afc/AdaptiveFeedControl.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string_view>

#include "cnc_core/language/CheckedNumber.h"
#include "cnc_core/machine_data/StandardPages.h"
#include "cnc_core/text/Numbers.h"

namespace mtc::core {
namespace {

constexpr double kZeroFeedLimitSeconds = 0.020;  // error 510 after 20 ms at 0 feed
constexpr double kSampleSeconds = 0.001;         // measurement cycle of ITM and P-7-3651
constexpr std::size_t kTrendLimit = 200000;      // samples kept for the trend

std::string percent(double value) {
    return formatFixed(value, 1) + " %";
}

}  // namespace

const char* afcStatusCode(AfcStatus status) {
    switch (status) {
        case AfcStatus::Ok:
            return "";
        case AfcStatus::NotAvailable:
            return "AFC_NOT_AVAILABLE";
        case AfcStatus::NoReferenceAxis:
            return "AFC_NO_REFERENCE_AXIS";
        case AfcStatus::Incompatible:
            return "AFC_INCOMPATIBLE";
        case AfcStatus::ErrorPending:
            return "AFC_ERROR_PENDING";
        case AfcStatus::Error508:
            return "AFC_ERROR_508";
        case AfcStatus::Error509:
            return "AFC_ERROR_509";
        case AfcStatus::Error510:
            return "AFC_ERROR_510";
        case AfcStatus::BadPeriod:
            return "AFC_BAD_PERIOD";
        case AfcStatus::FeedStopped:
            return "AFC_FEED_STOPPED";
        case AfcStatus::MoveTooLong:
            return "AFC_MOVE_TOO_LONG";
    }
    return "AFC_ERROR";
}

AdaptiveFeedControl::AdaptiveFeedControl(const ProcessConfig& process, MachineDataStore& store,
                                         TorqueModelParameters model, SignalTable* signalTable)
    : process_(process),
      store_(store),
      signals_(signalTable),
      parameters_(readAfcParameters(process, parameterDiagnostics_)),
      model_(model) {}

void AdaptiveFeedControl::followStore() const {
    const std::uint64_t revision = store_.revision();
    if (revision == memo_.revision) return;
    memo_.revision = revision;
    memo_.known = 0;
    memo_.settingsKnown = false;
    memo_.stallKnown = false;
}

double AdaptiveFeedControl::element(int number) const {
    followStore();
    const bool kept = number >= 0 && number < static_cast<int>(memo_.value.size());
    const std::uint32_t bit = kept ? 1u << number : 0u;
    if (memo_.known & bit) return memo_.value[static_cast<std::size_t>(number)];
    double value = 0.0;
    const bool read =
        store_.read({kAdaptiveFeedPage, process_.index, 0, number}, value) == MachineDataStatus::Ok;
    if (read && kept) {
        memo_.value[static_cast<std::size_t>(number)] = value;
        memo_.known |= bit;
    }
    return value;
}

void AdaptiveFeedControl::setStatus(int element, double value) {
    const double top = element >= 11 && element <= 13 ? 100.0 : 999.9;
    store_.update({kAdaptiveFeedPage, process_.index, 0, element}, std::clamp(value, 0.0, top));
}

void AdaptiveFeedControl::setSignal(const char* name, int value) {
    (std::string_view(name) == "THMIS" ? thrustMissing_ : excessiveThrust_) = value != 0;
    if (!signals_) return;
    char signal[32];
    std::snprintf(signal, sizeof signal, "P%02dS%s", process_.index, name);
    signals_->set(signal, value);
}

const AfcSettings& AdaptiveFeedControl::effectiveSettings() const {
    followStore();
    if (!memo_.settingsKnown) {
        memo_.settings =
            element(2) != 0.0 ? settingsFromPage30(store_, process_.index) : parameters_.settings;
        memo_.settingsKnown = true;
    }
    return memo_.settings;
}

bool AdaptiveFeedControl::referenceAxisExists(int significance) const {
    const std::string name = afcAxisName(significance);
    if (name.empty()) return false;
    for (const AxisConfig& axis : process_.axes) {
        if (significance >= 10) {
            if (axis.kind == AxisKind::Spindle && axis.spindleIndex == significance - 9)
                return true;
        } else if (axis.name == name ||
                   (!axis.definitions.empty() && axis.definitions.front() == name)) {
            return true;
        }
    }
    return false;
}

AfcStatus AdaptiveFeedControl::refuse(AfcStatus status, std::string message) {
    message_ = std::move(message);
    return status;
}

const char* AdaptiveFeedControl::incompatibleFunction(int gCode) {
    switch (gCode) {
        case 74:
            return "axis homing cycle (G74)";
        case 75:
            return "feed to positive stop (G75)";
        case 33:
            return "thread cutting (G33)";
        case 63:
        case 64:
            return "tapping without compensation chuck (G63/G64)";
        case 65:
            return "tapping with the spindle as lead axis (G65)";
        case 77:
            return "repositioning and NC program restart (G77)";
        case 31:
            return "face milling (G31)";
        case 32:
            return "cylinder interpolation (G32)";
        default:
            return nullptr;
    }
}

AfcStatus AdaptiveFeedControl::checkBlock(const std::vector<int>& gCodes) {
    if (!active_) return AfcStatus::Ok;
    for (int g : gCodes)
        if (const char* function = incompatibleFunction(g))
            return refuse(AfcStatus::Incompatible, std::string(function) +
                                                       " is not possible while adaptive feed "
                                                       "control (G26) is active");
    return AfcStatus::Ok;
}

AfcStatus AdaptiveFeedControl::checkSwitchOn(const std::vector<int>& activeGCodes,
                                             std::string& reason) const {
    if (active_) return AfcStatus::Ok;
    if (!parameters_.available) {
        reason = "adaptive feed control is not available (process parameter Bxx.062 = no)";
        return AfcStatus::NotAvailable;
    }
    if (error510_) {
        reason = "error 510 must be cleared first (Clear Error)";
        return AfcStatus::ErrorPending;
    }
    for (int g : activeGCodes)
        if (const char* function = incompatibleFunction(g)) {
            reason = std::string("G26 is not possible with ") + function;
            return AfcStatus::Incompatible;
        }
    const int axis =
        element(2) != 0.0 ? static_cast<int>(element(2)) : parameters_.settings.referenceAxis;
    if (!referenceAxisExists(axis)) {
        reason = "reference axis " + std::to_string(axis) + " (" + afcAxisName(axis) +
                 ") is not an axis of process " + std::to_string(process_.index);
        return AfcStatus::NoReferenceAxis;
    }
    return AfcStatus::Ok;
}

AfcStatus AdaptiveFeedControl::switchOn(const std::vector<int>& activeGCodes) {
    if (active_) return AfcStatus::Ok;
    std::string reason;
    const AfcStatus status = checkSwitchOn(activeGCodes, reason);
    if (status != AfcStatus::Ok) return refuse(status, std::move(reason));
    used_ = true;
    if (element(2) == 0.0) copySettingsToPage30(parameters_.settings, store_, process_.index);
    active_ = true;
    reduction_ = peakMachining_ = peakReduction_ = zeroFeedSeconds_ = 0.0;
    minimumExceeded_ = false;
    setStatus(1, 1);
    setStatus(11, 0);
    setSignal("THMIS", 0);
    return AfcStatus::Ok;
}

void AdaptiveFeedControl::deactivate() {
    if (!active_) return;
    active_ = false;
    setStatus(1, 0);
    setStatus(8, peakMachining_);
    setStatus(12, peakReduction_);
}

void AdaptiveFeedControl::switchOff() {
    const bool wasActive = active_;
    const double minimum = effectiveSettings().minimumTorque;
    deactivate();
    if (wasActive && minimum != 0.0) setSignal("THMIS", minimumExceeded_ ? 0 : 1);
}

void AdaptiveFeedControl::programEnd() {
    deactivate();
    idleRequested_ = false;
    setSignal("THMIS", 0);
    setSignal("EXCTH", 0);
}

void AdaptiveFeedControl::controlReset() {
    programEnd();
}

void AdaptiveFeedControl::clearError() {
    error510_ = false;
    zeroFeedSeconds_ = 0.0;
    runtimeError_ = AfcStatus::Ok;
    runtimeMessage_.clear();
}

void AdaptiveFeedControl::raiseRuntimeError(AfcStatus status, std::string message) {
    if (runtimeError_ != AfcStatus::Ok) return;  // the first error is the one reported
    runtimeError_ = status;
    runtimeMessage_ = std::move(message);
}

AfcStatus AdaptiveFeedControl::takeRuntimeError(std::string& message) {
    const AfcStatus status = runtimeError_;
    message = std::move(runtimeMessage_);
    runtimeError_ = AfcStatus::Ok;
    runtimeMessage_.clear();
    return status;
}

double AdaptiveFeedControl::takeExtraSeconds() {
    const double seconds = extraSeconds_;
    extraSeconds_ = 0.0;
    return seconds;
}

AfcStatus AdaptiveFeedControl::measureIdleTorque(double feed, double speedFraction,
                                                 double constantSeconds, bool speedConstant,
                                                 double engagement) {
    if (!parameters_.available)
        return refuse(AfcStatus::NotAvailable,
                      "ITM: adaptive feed control is not available (Bxx.062 = no)");
    const AfcSettings s = effectiveSettings();
    if (!referenceAxisExists(s.referenceAxis))
        return refuse(AfcStatus::NoReferenceAxis, "ITM: no reference axis in this process");
    used_ = true;
    const double period = s.measuringPeriodMs / 1000.0;
    if (!speedConstant || feed <= 0.0 || constantSeconds < period)
        return refuse(AfcStatus::Error508,
                      "error 508: idling torque recording " +
                          std::string(afcAxisName(s.referenceAxis)) +
                          ": the block runs at constant speed for " +
                          std::to_string(clampedInteger<long long>(constantSeconds * 1000)) +
                          " ms, the measuring period is " +
                          std::to_string(static_cast<int>(s.measuringPeriodMs)) + " ms");
    const int samples = std::max(1, static_cast<int>(std::lround(period / kSampleSeconds)));
    double sum = 0.0;
    for (int i = 0; i < samples; ++i)
        sum += model_.actualTorque(feed, speedFraction, engagement, time_ + i * kSampleSeconds);
    const double idle = sum / samples - stallCompensation();
    setStatus(5, idle);
    if (s.maximumIdleTorque != 0.0 && idle > s.maximumIdleTorque)
        return refuse(AfcStatus::Error509,
                      "error 509: idling torque " + percent(idle) + " > max. idling torque " +
                          percent(s.maximumIdleTorque) + " " + afcAxisName(s.referenceAxis));
    return AfcStatus::Ok;
}

AfcStatus AdaptiveFeedControl::recordStallTorque(const std::string& axis, double periodMs,
                                                 double feedWhileRecording) {
    if (!(periodMs >= 0.0 && periodMs <= 60000.0))
        return refuse(AfcStatus::BadPeriod, "P-7-3651: the period must be 0.0 ... 60000 ms");
    used_ = true;
    if (clockSync_) clockSync_();
    const int samples =
        std::max(1, static_cast<int>(std::lround(periodMs / 1000.0 / kSampleSeconds)));
    double sum = 0.0;
    for (int i = 0; i < samples; ++i)
        sum += model_.actualTorque(feedWhileRecording, feedWhileRecording > 0 ? 0.5 : 0.0, 0.0,
                                   time_ + i * kSampleSeconds);
    const double tenths = std::round(sum / samples * 10.0);  // P-7-3652 unit: 0.1 %
    stallTorques_[axis] = tenths;
    memo_.stallKnown = false;
    if (axis == afcAxisName(effectiveSettings().referenceAxis))
        setStatus(14, std::fabs(tenths) / 10.0);
    return AfcStatus::Ok;
}

double AdaptiveFeedControl::stallCompensation() const {
    followStore();
    if (memo_.stallKnown) return memo_.stall;
    const double shown = element(14);
    double compensation = shown;
    auto found = stallTorques_.find(afcAxisName(effectiveSettings().referenceAxis));
    if (found != stallTorques_.end()) {
        const double recorded = found->second / 10.0;
        // 014 shows |P-7-3652| (seed 002 5.2); the torque formulas of Fig. 4-2,
        // 5-5 and 5-7 subtract the measured stall torque itself, sign included.
        if (std::fabs(std::fabs(recorded) - shown) < 0.05) compensation = recorded;
    }
    memo_.stall = compensation;
    memo_.stallKnown = true;
    return compensation;
}

double AdaptiveFeedControl::measuredStallTorque(const std::string& axis) const {
    auto found = stallTorques_.find(axis);
    return found == stallTorques_.end() ? 0.0 : found->second;
}

void AdaptiveFeedControl::raise510() {
    error510_ = true;
    message_ = "error 510: 100% feed reduction " +
               std::string(afcAxisName(effectiveSettings().referenceAxis));
    raiseRuntimeError(AfcStatus::Error510, message_);
}

double AdaptiveFeedControl::advance(double dt, double programmedFeed, double speedFraction,
                                    double engagement) {
    time_ += dt;
    if (error510_) return 0.0;
    if (!active_) return programmedFeed;
    const AfcSettings s = effectiveSettings();
    const double factor = 1.0 - reduction_ / 100.0;
    const double feed = programmedFeed * factor;
    const double actual = model_.actualTorque(feed, speedFraction * factor, engagement, time_);
    const double machining = actual - element(5) - stallCompensation();
    reduction_ =
        std::clamp(reduction_ + s.amplification * (machining - s.limitingTorque) * dt, 0.0, 100.0);
    afterControl(dt, actual, machining, s);
    const double effective = programmedFeed * (1.0 - reduction_ / 100.0);
    if (trend_.size() < kTrendLimit)
        trend_.push_back({time_, actual, machining, reduction_, effective});
    return error510_ ? 0.0 : effective;
}

void AdaptiveFeedControl::afterControl(double dt, double actual, double machining,
                                       const AfcSettings& s) {
    lastActual_ = actual;
    lastMachining_ = machining;
    peakMachining_ = std::max(peakMachining_, machining);
    peakReduction_ = std::max(peakReduction_, reduction_);
    if (machining > s.minimumTorque) minimumExceeded_ = true;
    setStatus(7, machining);
    setStatus(11, reduction_);
    setSignal("EXCTH", reduction_ > s.maximumReduction ? 1 : 0);
    zeroFeedSeconds_ = reduction_ >= 100.0 ? zeroFeedSeconds_ + dt : 0.0;
    if (zeroFeedSeconds_ >= kZeroFeedLimitSeconds && s.maximumReduction < 100.0) raise510();
}

}  // namespace mtc::core

namespace mtc::core {

void AdaptiveFeedControl::observe(double feed, double speedFraction, double engagement,
                                  double offset) {
    lastActual_ = model_.actualTorque(feed, speedFraction, engagement, time_ + offset);
    lastMachining_ = lastActual_ - element(5) - stallCompensation();
}

AfcTrendSample AdaptiveFeedControl::trendSample(double time, double effectiveFeed,
                                                bool measuringIdle) const {
    AfcTrendSample sample;
    fillTrendSample(sample, time, effectiveFeed, measuringIdle);
    return sample;
}

void AdaptiveFeedControl::fillTrendSample(AfcTrendSample& sample, double time, double effectiveFeed,
                                          bool measuringIdle) const {
    const AfcSettings& s = effectiveSettings();
    sample.time = time;
    sample.torqueActual = lastActual_;
    sample.machiningTorque = lastMachining_;
    sample.idleTorque = element(5);
    sample.limitingTorque = s.limitingTorque;
    sample.minimumTorque = s.minimumTorque;
    sample.maximumIdleTorque = s.maximumIdleTorque;
    sample.feedReduction = active_ ? reduction_ : 0.0;
    sample.peakReduction = peakReduction_;
    sample.maximumReduction = s.maximumReduction;
    sample.effectiveFeed = effectiveFeed;
    sample.stallTorque = element(14);
    sample.active = active_;
    sample.measuringIdle = measuringIdle;
    sample.excessiveThrust = excessiveThrust_;
    sample.thrustMissing = thrustMissing_;
}

}  // namespace mtc::core
