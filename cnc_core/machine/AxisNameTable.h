#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "cnc_core/machine/AxisName.h"
#include "cnc_core/machine/ProcessAxes.h"
#include "cnc_core/machine/Transformation.h"

namespace mtc::core {

/// How an axis word's name maps to a machine axis right now.
enum class AxisNameStatus : std::uint8_t {
    Unknown,            ///< no axis of the process has this name
    Ok,                 ///< designation 1 (or designation 2 while G31/G32 maps the axis)
    TransformedLinear,  ///< designation 1 of a linear axis that G31/G32 renamed (accepted, warning)
    TransformedRotary,  ///< designation 1 of a rotary axis that G31/G32 renamed (rejected)
    InactiveDesignation2,  ///< designation 2 while no transformation is active (rejected)
};

struct AxisLookup {
    int axis = -1;
    AxisNameStatus status = AxisNameStatus::Unknown;
};

/// Name -> machine axis lookup in O(1), rebuilt when the transformation
/// changes: while G31/G32 is active the two plane axes answer to axis
/// designation 2 (Cxx.075) when they have one (seed 003, 4.5 and 5.2).
class AxisNameTable {
  public:
    /// Builds the table for `axes` under `transformation`.
    static AxisNameTable build(const ProcessAxes& axes, const Transformation& transformation);
    /// Looks up letter (A..Z) + index (0..3).
    AxisLookup find(char letter, int index) const {
        if (letter < 'A' || letter > 'Z' || index < 0 || index > 3) return {};
        return entries_[static_cast<size_t>(letter - 'A') * 4 + static_cast<size_t>(index)];
    }

  private:
    void put(AxisName name, int axis, AxisNameStatus status);
    std::array<AxisLookup, 26 * 4> entries_{};
};

/// The name programs address machine axis `axis` by under `transformation`:
/// its designation 2 while G31/G32 transforms it and it has one, else its
/// designation 1 (AxisModel::displayName). Positions on the transformed
/// plane carry this name (docs/decisions/interpreter.md I-013a).
std::string programmedAxisName(const ProcessAxes& axes, const Transformation& transformation,
                               int axis);

}  // namespace mtc::core
