#pragma once

#include <array>
#include <cstdint>

#include "cnc_core/machine/MachineConfig.h"

namespace mtc::core {

/// The one rule that puts an M function into its group and decides what the
/// page 61 buffer keeps (seed 000, 3.1, 4.2, 5.2, 5.4; restart.md R-006,
/// Used by the interpreter (M(1)..M(16)) and by the restart's buffer
/// collector, so groups and buffers never disagree.
///
/// - An M the configuration lists in a group 1..15 belongs to that group.
/// - Spindle-index forms: Mjnn (j = 1..3; nn = 03, 04, 05, 19 spindle
///   control, 40..44 gear step) is function nn of spindle j. Mnn without
///   index addresses the reference spindle (SPC), which is spindle 1 in this
///   simulator (interpreter.md I-006), so Mnn and M1nn are one function:
///   when either is configured, both belong to that group (M103 is in the
///   group of M3, M141 in the gear group of M41, M119 in the group of M19).
///   For j = 2, 3 only the configured number counts (M203 is not M3).
/// - Every other M is group 16.
/// - The page 61 M(16) buffer keeps group-16 functions except the program
///   control functions M00, M01, M02, M30 and the M19 forms (M19, M119,
///   M219, M319, seed 000, 4.2).
class AuxFunctionGroups {
  public:
    static constexpr int kFunctions = 1000;  ///< M0 .. M999

    explicit AuxFunctionGroups(const ProcessConfig& config);

    /// Group 1..16 of M function `m` (0..999); 16 outside that range.
    int groupOf(int m) const {
        return m >= 0 && m < kFunctions ? table_[static_cast<std::size_t>(m)] : 16;
    }
    /// True when `m` goes into the page 61 M(16) buffer.
    bool storedInBuffer(int m) const { return storedInBuffer(m, groupOf(m)); }
    /// The same for `m` of group `group` (the rule, in one place).
    static bool storedInBuffer(int m, int group) {
        return group == 16 && !isProgramControl(m) && !isSpindleOrientation(m);
    }
    /// M number -> group, for the interpreter's per-block look-up.
    const std::array<std::uint8_t, kFunctions>& table() const { return table_; }

    /// M00, M01, M02, M30.
    static bool isProgramControl(int m) { return m == 0 || m == 1 || m == 2 || m == 30; }
    /// M19, M119, M219, M319: spindle orientation of the reference spindle or spindle j.
    static bool isSpindleOrientation(int m) { return m >= 0 && m % 100 == 19 && m / 100 <= 3; }
    /// True when `nn` (m % 100) is a spindle control or gear function that
    /// takes a spindle index: 3, 4, 5, 19, 40..44.
    static bool isSpindleFunction(int nn) {
        return nn == 3 || nn == 4 || nn == 5 || nn == 19 || (nn >= 40 && nn <= 44);
    }

  private:
    std::array<std::uint8_t, kFunctions> table_{};
};

}  // namespace mtc::core
