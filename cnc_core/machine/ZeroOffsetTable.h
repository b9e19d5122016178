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
        return row(code)[column(definition)];
    }
    /// The offsets of G`code` by column(): G53 (and a code outside G54..G59)
    /// a row of 0. The motion planner reads one row per block (MOT-025).
    const double* row(int code) const {
        return rows_[code < 54 || code > 59 ? 0 : static_cast<size_t>(code - 53)].data();
    }
    /// Column of `definition` in a row(); None has a column that is always 0.
    static std::size_t column(AxisDefinition definition) {
        return definition == AxisDefinition::None ? kDefinitionCount
                                                  : static_cast<std::size_t>(definition);
    }
    /// Changes one entry (operator input); false for a bad code/definition.
    bool set(int code, AxisDefinition definition, double offset);

  private:
    /// Row 0: G53, rows 1..6: G54..G59; the last column stays 0 (None).
    std::array<std::array<double, kDefinitionCount + 1>, 7> rows_{};
};

}  // namespace mtc::core
