#include "cnc_core/afc/AfcSettings.h"

#include <cmath>

#include "cnc_core/machine_data/StandardPages.h"

namespace mtc::core {
namespace {

/// One Bxx parameter: number, range, and where it goes.
struct ParameterRange {
    const char* number;
    double minimum;
    double maximum;
    bool whole;
    double AfcSettings::*field;
};

constexpr ParameterRange kRanges[] = {
    {"B064", 0.0, 500.0, false, &AfcSettings::limitingTorque},
    {"B065", 0.0, 500.0, false, &AfcSettings::minimumTorque},
    {"B066", 0.0, 500.0, false, &AfcSettings::maximumIdleTorque},
    {"B067", 0.0, 100.0, false, &AfcSettings::maximumReduction},
    {"B068", 0.01, 100.0, false, &AfcSettings::amplification},
    {"B069", 2.0, 60000.0, true, &AfcSettings::measuringPeriodMs},
};

bool readNumber(const ProcessConfig& p, const char* number, double minimum, double maximum,
                bool whole, double& out, DiagnosticList& diagnostics) {
    auto found = p.parameters.find(number);
    if (found == p.parameters.end()) return false;
    const double fallback = -1e300;
    const double value = p.number(number, fallback);
    if (value == fallback || value < minimum || value > maximum ||
        (whole && value != std::floor(value))) {
        diagnostics.error("AFC_PARAMETER", {},
                          "process " + std::to_string(p.index) + " parameter " + number + " = '" +
                              found->second + "' is outside " + std::to_string(minimum) + " ... " +
                              std::to_string(maximum) + "; the default is used");
        return false;
    }
    out = value;
    return true;
}

double element(const MachineDataStore& store, int process, int number, double fallback) {
    double value = fallback;
    store.read({kAdaptiveFeedPage, process, 0, number}, value);
    return value;
}

}  // namespace

AfcParameters readAfcParameters(const ProcessConfig& process, DiagnosticList& diagnostics) {
    AfcParameters result;
    result.available = process.flag("B062", false);
    double axis = 0;
    if (readNumber(process, "B063", 0, 12, true, axis, diagnostics))
        result.settings.referenceAxis = static_cast<int>(axis);
    for (const ParameterRange& range : kRanges)
        readNumber(process, range.number, range.minimum, range.maximum, range.whole,
                   result.settings.*(range.field), diagnostics);
    return result;
}

AfcSettings settingsFromPage30(const MachineDataStore& store, int process) {
    AfcSettings s;
    s.referenceAxis = static_cast<int>(element(store, process, 2, 0));
    s.amplification = element(store, process, 3, s.amplification);
    s.measuringPeriodMs = element(store, process, 4, s.measuringPeriodMs);
    s.maximumIdleTorque = element(store, process, 6, s.maximumIdleTorque);
    s.minimumTorque = element(store, process, 9, s.minimumTorque);
    s.limitingTorque = element(store, process, 10, s.limitingTorque);
    s.maximumReduction = element(store, process, 13, s.maximumReduction);
    return s;
}

void copySettingsToPage30(const AfcSettings& s, MachineDataStore& store, int process) {
    const auto put = [&](int number, double value) {
        store.update({kAdaptiveFeedPage, process, 0, number}, value);
    };
    put(2, s.referenceAxis);
    put(3, s.amplification);
    put(4, s.measuringPeriodMs);
    put(6, s.maximumIdleTorque);
    put(9, s.minimumTorque);
    put(10, s.limitingTorque);
    put(13, s.maximumReduction);
}

const char* afcAxisName(int significance) {
    static const char* const names[] = {"",  "X", "Y", "Z",  "U",  "V", "W",
                                        "A", "B", "C", "S1", "S2", "S3"};
    return significance >= 1 && significance <= 12 ? names[significance] : "";
}

}  // namespace mtc::core
