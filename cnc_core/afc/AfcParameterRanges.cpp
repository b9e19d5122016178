#include "cnc_core/afc/AfcParameterRanges.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iterator>

#include "cnc_core/machine/MachineConfig.h"
#include "cnc_core/text/Numbers.h"

namespace mtc::core {
namespace {

// Seed 002, 4.2 (value range of each process parameter).
constexpr AfcParameterRange kRanges[] = {
    {"B063", 0.0, 12.0, true,
     "reference axis of adaptive feed control (1..9 X..C, 10..12 S1..S3, 0 none)", ""},
    {"B064", 0.0, 500.0, false, "limiting machining torque", "%"},
    {"B065", 0.0, 500.0, false, "minimum machining torque", "%"},
    {"B066", 0.0, 500.0, false, "maximum idling torque", "%"},
    {"B067", 0.0, 100.0, false, "maximum feed reduction", "%"},
    {"B068", 0.01, 100.0, false, "amplification", "1/s"},
    {"B069", 2.0, 60000.0, true, "measuring period", "ms"},
};

std::string number(double value, bool whole) {
    std::string s = formatFixed(value, whole ? 0 : 2);
    if (!whole) {  // 500.00 -> 500.0, 0.01 stays
        while (s.size() > 3 && s.back() == '0' && s[s.size() - 2] != '.')
            s.pop_back();
    }
    return s;
}

}  // namespace

const AfcParameterRange* afcParameterRangesBegin() {
    return std::begin(kRanges);
}

const AfcParameterRange* afcParameterRangesEnd() {
    return std::end(kRanges);
}

const AfcParameterRange* afcParameterRange(std::string_view key) {
    for (const AfcParameterRange& range : kRanges)
        if (key == range.key) return &range;
    return nullptr;
}

bool isAfcParameter(std::string_view key) {
    return key == "B062" || afcParameterRange(key) != nullptr;
}

std::string afcAllowedValues(std::string_view key) {
    if (key == "B062") return "yes or no";
    const AfcParameterRange* range = afcParameterRange(key);
    if (!range) return "";
    std::string text =
        number(range->minimum, range->whole) + " ... " + number(range->maximum, range->whole);
    if (range->whole) text += ", whole numbers";
    if (*range->unit) text += std::string(" ") + range->unit;
    return text + " (" + range->meaning + ")";
}

bool readAfcParameterValue(std::string_view key, std::string_view text, double& value) {
    if (key == "B062") {
        bool yes = false;
        if (!parseYesNo(std::string(text), yes)) return false;
        value = yes ? 1.0 : 0.0;
        return true;
    }
    const AfcParameterRange* range = afcParameterRange(key);
    if (!range) return true;
    double parsed = 0.0;
    if (text.empty() || readNumberPrefix(text, parsed) != text.size() || !std::isfinite(parsed))
        return false;
    if (parsed < range->minimum || parsed > range->maximum) return false;
    if (range->whole && parsed != std::floor(parsed)) return false;
    value = parsed;
    return true;
}

}  // namespace mtc::core
