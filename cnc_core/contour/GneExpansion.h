#pragma once

// Expansion of GNE instructions into NC blocks the interpreter runs
// (G0/G1/G2/G3 with absolute centres, docs/GNE-SYNTAX.md): contours and
// forms are geometry, the cycles machine them.

#include <string>
#include <vector>

#include "cnc_core/contour/GneGeometry.h"
#include "cnc_core/contour/GneModel.h"

namespace mtc::core::gne {

/// The tool data a cycle was programmed with (seed 001, ch. 3 caution):
/// checked against the tool list when the program runs (ToolCheck.h).
struct ToolAssumption {
    int tool = 0;
    bool turning = true;
    double radius = 0.0;        ///< nose / cutter radius
    int edge = 0;               ///< turning: cutting edge orientation 0..9
    double cornerAngle = 0.0;   ///< turning: corner angle of the insert (degrees)
    double settingAngle = 0.0;  ///< turning: setting angle of the tool (degrees)
    std::uint32_t line = 0;     ///< line of the cycle
};

/// The NC blocks of one GNE instruction (empty for windows, contours, forms).
struct ExpandedCall {
    std::uint32_t line = 0;
    std::string keyword;
    std::vector<std::string> blocks;  ///< block texts without block numbers
};

/// Result of expanding a GneDocument.
struct GneExpansion {
    std::vector<ExpandedCall> calls;   ///< one per cycle, in program order
    std::vector<Geometry> geometries;  ///< every solved contour and form
    std::vector<ToolAssumption> tools;
    std::vector<GneDiagnostic> diagnostics;
    bool ok() const { return diagnostics.empty(); }
};

/// Solves every contour, builds every form and expands every cycle.
/// Diagnostics name the line of the instruction at fault.
GneExpansion expandGne(const GneDocument& document);

/// "T1 ;GNE TOOL EDGE 3 TR 0.4 CA 80 SA 95": the tool block of a cycle that
/// records the assumption in the NC program.
std::string toolBlock(const ToolAssumption& tool);

/// Reads a tool block written by toolBlock(); false for any other text.
bool parseToolBlock(const std::string& text, ToolAssumption& tool);

/// Cutting edge orientation 0..9 as the offset of the programmed tool tip
/// from the nose centre in plane coordinates (Z, X), unit length per axis.
Point edgeVector(int edge);

}  // namespace mtc::core::gne
