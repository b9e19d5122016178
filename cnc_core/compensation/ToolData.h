#pragma once

// The one place where tool compensation reads tool data (radius, length,
// cutting edge orientation). Today the tools list of the machine
// configuration (ToolConfig); the persisted tool list of a process replaces
// it by changing activeToolData() only.

#include "cnc_core/interp/InterpreterState.h"
#include "cnc_core/machine/MachineConfig.h"

namespace mtc::core {

/// What compensation needs of the tool in working position.
struct ToolData {
    int number = 0;       ///< 0 = no tool
    double radius = 0.0;  ///< cutter radius / nose radius (mm)
    double length = 0.0;  ///< tool length (mm)
    int orientation = 0;  ///< cutting edge orientation 0..9 (1..8: turning tools)

    /// A turning tool: its cutting edge orientation is one of the eight positions 1..8.
    bool turning() const { return orientation >= 1 && orientation <= 8; }
};

/// The tool in working position (docs/decisions/compensation.md TC-006):
/// the tool in tool spindle 1 (page 60 element 5, set by MTP on a turret,
/// TCH/TMS on a magazine); when no change command has put one there, the
/// programmed T. No tool, or a number not in the list, is a tool of size 0.
inline ToolData activeToolData(const ProcessConfig& config, const ModalState& modal) {
    const int number = modal.toolSpindle[0] != 0 ? modal.toolSpindle[0] : modal.tool;
    ToolData data;
    data.number = number;
    if (number == 0) return data;
    if (const ToolConfig* tool = config.tool(number)) {
        data.radius = tool->radius;
        data.length = tool->length;
        data.orientation = tool->edgeOrientation;
    }
    return data;
}

}  // namespace mtc::core
