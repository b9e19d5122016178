#pragma once

// The positional parameters of WINDOW_0x, FORM_xx and CYCLE_xx: names,
// meaning, defaults and ranges, for the reader, the writer and the GNE
// screen's parameter entry (docs/GNE-SYNTAX.md).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cnc_core/contour/GneModel.h"

namespace mtc::core::gne {

/// Largest magnitude of any GNE value (mm, degrees): parameters and contour
/// element words alike, so that no geometry, tessellation or pass count can
/// grow with a typed number (issue 15 §1).
constexpr double kMaxGneValue = 1e6;

/// One positional parameter.
struct ParamSpec {
    const char* name = "";      ///< short name as in the documentation ("XC")
    const char* meaning = "";   ///< one line for the operator
    bool required = false;      ///< no default: must be written
    double defaultValue = 0.0;  ///< used when the position is empty
    double minimum = 0.0;       ///< inclusive
    double maximum = 0.0;       ///< inclusive
    bool integer = false;       ///< whole numbers only
};

/// One keyword with positional parameters.
struct CallSpec {
    const char* keyword;  ///< "FORM_52"
    const char* title;    ///< "circle - milling"
    GnePlane plane;
    bool hasText;  ///< FORM_54/55: a quoted text follows the numbers
    std::vector<ParamSpec> params;
};

/// Every keyword with positional parameters, in documentation order.
const std::vector<CallSpec>& callSpecs();

/// The spec of `keyword`, or nullptr.
const CallSpec* findCallSpec(std::string_view keyword);

/// Checks one value against its spec; returns an operator message or "".
std::string checkParam(const ParamSpec& spec, std::optional<double> value);

/// Parameter `index` of `call` with its default applied (spec must match).
double paramValue(const CallSpec& spec, const GneCall& call, std::size_t index);

/// Positions of the tool data recorded in every turning cycle (CYCLE_10..12).
enum TurningCycleParam : std::size_t {
    kCycleNr = 0,
    kCycleTool,
    kCycleFeed,
    kCycleSpeed,
    kCycleEdge,
    kCycleToolRadius,
    kCycleCornerAngle,
    kCycleSettingAngle,
    kCycleClearance,
    kCycleDepth,                           ///< CYCLE_11 only
    kCycleAllowanceX,                      ///< CYCLE_11
    kCycleAllowanceZ,                      ///< CYCLE_11
    kCycleUniformAllowance = kCycleDepth,  ///< CYCLE_12
};

/// Positions of CYCLE_40's parameters.
enum MillingCycleParam : std::size_t {
    kMillNr = 0,
    kMillTool,
    kMillFeed,
    kMillSpeed,
    kMillToolRadius,
    kMillSide,
    kMillSafeZ,
    kMillCutZ,
    kMillPlungeFeed,
};

}  // namespace mtc::core::gne
