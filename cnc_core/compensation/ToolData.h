#pragma once

// The one place where tool compensation reads tool data (radius, lengths,
// cutting edge orientation): the tool list of the process (cnc_core/tooldata,
// persisted beside the machine data; docs/decisions/tool-data.md).

#include <array>

#include "cnc_core/interp/InterpreterState.h"
#include "cnc_core/tooldata/ToolList.h"

namespace mtc::core {

/// What compensation needs of the tool edge in working position.
struct ToolData {
    int number = 0;            ///< 0 = no tool
    int edge = 0;              ///< the edge E used (0 = none)
    bool edgeMissing = false;  ///< E was programmed but the tool has no such edge
    double radius = 0.0;       ///< cutter radius / nose radius, geometry + wear (mm)
    /// L1, L2 (1st / 2nd plane axis) and L3 (perpendicular axis), geometry +
    /// wear (seed 003 ch. 3.6).
    std::array<double, 3> lengths{};
    int orientation = 0;  ///< cutting edge orientation 0..9 (1..8: turning tools)

    /// A turning tool: its cutting edge orientation is one of the eight positions 1..8.
    bool turning() const { return orientation >= 1 && orientation <= 8; }
};

/// The tool edge in working position (docs/decisions/compensation.md
/// TC-009): the tool in tool spindle 1 (page 60 element 5, set by MTP on a
/// turret, TCH/TMS on a magazine); when no change command has put one there,
/// the programmed T. The edge is the programmed E, else the tool's first
/// edge. No tool, or a number not in the list, is a tool of size 0; an E the
/// tool does not have is marked `edgeMissing` (size 0 as well).
inline ToolData activeToolData(const ToolList& tools, const ModalState& modal) {
    const int number = modal.toolSpindle[0] != 0 ? modal.toolSpindle[0] : modal.tool;
    ToolData data;
    data.number = number;
    if (number == 0 || tools.find(number) == nullptr) return data;
    const ToolEdge* edge = tools.edge(number, modal.edge);
    if (edge == nullptr) {
        data.edgeMissing = true;
        data.edge = modal.edge;
        return data;
    }
    data.edge = edge->edge;
    data.radius = edge->totalRadius();
    data.lengths = {edge->totalLength(1), edge->totalLength(2), edge->totalLength(3)};
    data.orientation = edge->orientation;
    return data;
}

}  // namespace mtc::core
