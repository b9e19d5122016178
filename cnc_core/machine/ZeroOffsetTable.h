#pragma once

#include <array>

#include "cnc_core/language/Diagnostic.h"
#include "cnc_core/machine/AxisName.h"
#include "cnc_core/machine/MachineConfig.h"

namespace mtc::core {

/// The settable zero offsets G54..G59 of a process. Following seed 003, 3.5
/// the table is oriented towards the axis definition: the value in column X
/// applies to whichever axis has definition X at the time (so a G20 that
/// gives the Z axis definition X makes it use the X column). Values in mm.
class ZeroOffsetTable {
  public:
    /// Reads the [process N zero-offsets] entries. Keys must be G54..G59 and
    /// the words must name definitions X..C; anything else is a diagnostic.
    static ZeroOffsetTable build(const ProcessConfig& config, DiagnosticList& diagnostics);

    /// Offset of G`code` (53..59) for `definition`; 0 for G53 or None.
    double value(int code, AxisDefinition definition) const {
        if (code < 54 || code > 59 || definition == AxisDefinition::None) return 0.0;
        return values_[static_cast<size_t>(code - 54)][static_cast<size_t>(definition)];
    }
    /// Changes one entry (operator input); false for a bad code/definition.
    bool set(int code, AxisDefinition definition, double offset);

  private:
    std::array<std::array<double, kDefinitionCount>, 6> values_{};
};

}  // namespace mtc::core
