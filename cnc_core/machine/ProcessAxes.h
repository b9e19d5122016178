#pragma once

#include <array>
#include <string>
#include <vector>

#include "cnc_core/language/Diagnostic.h"
#include "cnc_core/machine/AxisName.h"
#include "cnc_core/machine/MachineConfig.h"

namespace mtc::core {

/// One axis of a process as the interpreter sees it (built from AxisConfig).
struct AxisModel {
    std::string configName;  ///< name in the configuration: "X", "Z2", "S1"
    int configLine = 0;      ///< line of its section in the configuration file (0 = unknown)
    AxisName name;           ///< designation 1 in programs ("C" for spindle S1/C); invalid = none
    AxisName designation2;   ///< Cxx.075, used while G31/G32 is active; invalid = none
    bool rotary = false;     ///< rotary axis, or spindle with rotary axis capability
    bool spindle = false;    ///< a spindle (S1..S3), with or without rotary capability
    int spindleIndex = 0;    ///< 1..3 for spindles, 0 otherwise
    bool endless = false;    ///< rotary axis with both travel limits 0
    std::array<AxisDefinition, 4> definitions{};  ///< Cxx.053: [0] base, rest G20 alternates
    int definitionCount = 0;
    int polarDirection = 0;                       ///< Cxx.076
    double maxVelocity = 10000.0;                 ///< mm/min or deg/min (rapid traverse)
    double rapidSecondsPerUnit = 60.0 / 10000.0;  ///< 60 / maxVelocity
    double minPosition = 0.0;                     ///< travel limits; both 0 = not monitored
    double maxPosition = 0.0;

    /// True when the travel limits are monitored (they differ).
    bool limited() const { return minPosition != maxPosition; }

    /// The name programs and displays use: designation 1 ("C" for spindle
    /// S1/C), or the configuration name of a plain spindle ("S2").
    std::string displayName() const { return name.valid() ? name.toString() : configName; }
    /// True when `definition` is listed in Cxx.053 (base or alternate).
    bool allows(AxisDefinition definition) const;
    AxisDefinition baseDefinition() const {
        return definitionCount > 0 ? definitions[0] : AxisDefinition::None;
    }
};

/// The axes of one process in machine order (the order of ProcessConfig::axes,
/// which is also the index order of Motion::end). Immutable once built.
class ProcessAxes {
  public:
    /// Builds the axis table. Configuration errors (bad or duplicate
    /// designations, two axes with the same base definition, too many axes)
    /// are added to `diagnostics`; the table then holds what could be used.
    static ProcessAxes build(const ProcessConfig& config, DiagnosticList& diagnostics);

    int count() const { return static_cast<int>(axes_.size()); }
    const AxisModel& axis(int index) const { return axes_[static_cast<size_t>(index)]; }
    const std::vector<AxisModel>& axes() const { return axes_; }
    /// Machine axis index of designation 1 `name`, or -1.
    int findByName(AxisName name) const;
    /// Machine axis index of designation 2 `name`, or -1.
    int findByDesignation2(AxisName name) const;
    /// Machine axis index of spindle 1..3, or -1.
    int spindleAxis(int spindleIndex) const;

  private:
    std::vector<AxisModel> axes_;
};

}  // namespace mtc::core
