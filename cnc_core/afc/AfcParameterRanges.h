#pragma once

#include <string>
#include <string_view>

namespace mtc::core {

/// Allowed values of one process parameter of adaptive feed control
/// (seed 002, 4.2): Bxx.063 .. Bxx.069.
struct AfcParameterRange {
    const char* key;  ///< "B063" .. "B069"
    double minimum;
    double maximum;
    bool whole;           ///< only whole numbers (B063, B069)
    const char* meaning;  ///< "limiting machining torque", ...
    const char* unit;     ///< "%", "1/s", "ms" or ""
};

/// Every range, B063 first: the one table of these limits (the machine
/// configuration's schema takes its B063..B069 rules from here).
const AfcParameterRange* afcParameterRangesBegin();
const AfcParameterRange* afcParameterRangesEnd();

/// The range of `key` (B063..B069), nullptr for any other key.
const AfcParameterRange* afcParameterRange(std::string_view key);

/// "0.0 ... 500.0 %" / "yes or no": what `key` (B062..B069) allows.
std::string afcAllowedValues(std::string_view key);

/// True when `key` is B062..B069.
bool isAfcParameter(std::string_view key);

/// Checks the configuration text of B062..B069: B062 yes/no, the others a
/// number inside their range (whole where the seed says so). Keys that are
/// not AFC parameters pass. On a bad value `value` is left alone.
bool readAfcParameterValue(std::string_view key, std::string_view text, double& value);

}  // namespace mtc::core
