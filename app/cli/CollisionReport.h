#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cli/JsonWriter.h"
#include "cnc_core/removal/ReentryCollisions.h"

namespace mtc::cli {

/// `restart --check-collisions` (CLI-CONTRACT.md "Extensions", D-021):
/// "collisions": [{"block", "program", "line", "phase", "motion", "position"}],
/// empty when the way back is clear; "collision_check" says whether the part
/// at the target could be checked at all (an unchecked way back is not a
/// safe one). `names`: the reported axis names (empty: not reported).
void writeCollisionsJson(JsonWriter& json, const std::optional<core::removal::ReentryCheck>& check,
                         const std::vector<std::string>& names);

/// One line per collision ("collision repos P99 N0002 L3 feed X=… Y=… Z=…"),
/// and the check's summary line.
void printCollisionsText(const std::optional<core::removal::ReentryCheck>& check,
                         const std::vector<std::string>& names);

}  // namespace mtc::cli
