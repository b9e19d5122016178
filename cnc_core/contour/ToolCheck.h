#pragma once

// The seed's caution (seed 001, ch. 3): the tool edge orientation, radius,
// corner angle and setting angle assumed when a GNE cycle was programmed
// must exist when it is machined. This compares a recorded assumption
// (the cycle's "T.. ;GNE TOOL ..." block) with the tool list.

#include <string>
#include <vector>

#include "cnc_core/contour/GneExpansion.h"
#include "cnc_core/machine/MachineConfig.h"

namespace mtc::core::gne {

/// Every difference between `assumed` and the tool list entry `actual`
/// (nullptr = the tool is not in the list), one operator message each;
/// empty when the tool fits. Radii must agree within 0.001 mm. The corner
/// and setting angles cannot be checked while the tool list has no such
/// data (ToolConfig); they are not reported as differences.
std::vector<std::string> checkToolAssumption(const ToolAssumption& assumed,
                                             const ToolConfig* actual);

}  // namespace mtc::core::gne
