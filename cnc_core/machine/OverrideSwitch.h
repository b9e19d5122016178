#pragma once

namespace mtc::core {

/// The override switches of the machine control panel (docs/decisions/
/// motion.md MOT-016): one step up (`direction` > 0) or down (< 0) from
/// `percent`. A value between two positions goes to the next position in
/// that direction; the ends stay where they are.
///
/// Feed override: 0, 1, 2, 4, 6, 8, 10, then every 10 % up to `maxPercent`
/// (B074, 100 ... 200 %; a maximum that is not a multiple of 10 is a position
/// of its own).
int feedOverrideStep(int percent, int direction, int maxPercent);

/// Rapid traverse override: 0, 1, 10, 25, 50, 100 %.
int rapidOverrideStep(int percent, int direction);

}  // namespace mtc::core
