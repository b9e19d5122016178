#include "cnc_core/afc/AfcSettings.h"

#include <cmath>

#include "cnc_core/afc/AfcParameterRanges.h"
#include "cnc_core/machine_data/StandardPages.h"

namespace mtc::core {
namespace {

/// Where each of Bxx.064..069 goes (ranges: AfcParameterRanges).
struct ParameterField {
    const char* number;
    double AfcSettings::*field;
};

constexpr ParameterField kFields[] = {
    {"B064", &AfcSettings::limitingTorque},    {"B065", &AfcSettings::minimumTorque},
    {"B066", &AfcSettings::maximumIdleTorque}, {"B067", &AfcSettings::maximumReduction},
    {"B068", &AfcSettings::amplification},     {"B069", &AfcSettings::measuringPeriodMs},
};

/// Reads parameter `number` of `p` into `out` when it is given and valid; a
/// bad value is AFC_PARAMETER (the machine configuration reader refuses it
/// first; this covers configurations built in code).
bool readParameter(const ProcessConfig& p, const char* number, double& out,
                   DiagnosticList& diagnostics) {
    auto found = p.parameters.find(number);
    if (found == p.parameters.end()) return false;
    if (readAfcParameterValue(number, found->second, out)) return true;
    diagnostics.error("AFC_PARAMETER", {},
                      "process " + std::to_string(p.index) + " parameter " + number + " = '" +
                          found->second + "' is outside " + afcAllowedValues(number) +
                          "; the default is used");
    return false;
}

double element(const MachineDataStore& store, int process, int number, double fallback) {
    double value = fallback;
    store.read({kAdaptiveFeedPage, process, 0, number}, value);
    return value;
}

}  // namespace

AfcParameters readAfcParameters(const ProcessConfig& process, DiagnosticList& diagnostics) {
    AfcParameters result;
    double available = 0;
    if (readParameter(process, "B062", available, diagnostics)) result.available = available != 0;
    double axis = 0;
    if (readParameter(process, "B063", axis, diagnostics))
        result.settings.referenceAxis = static_cast<int>(axis);
    for (const ParameterField& field : kFields)
        readParameter(process, field.number, result.settings.*(field.field), diagnostics);
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
