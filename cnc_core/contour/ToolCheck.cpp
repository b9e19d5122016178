#include "cnc_core/contour/ToolCheck.h"

#include <cmath>

#include "cnc_core/contour/GneText.h"

namespace mtc::core::gne {

std::vector<std::string> checkToolAssumption(const ToolAssumption& assumed,
                                             const ToolConfig* actual) {
    const std::string tool = "T" + std::to_string(assumed.tool);
    if (!actual) return {tool + " is not in the tool list"};
    std::vector<std::string> problems;
    if (std::fabs(actual->radius - assumed.radius) > 0.001)
        problems.push_back(tool + ": radius " + formatValue(actual->radius) +
                           " in the tool list, the cycle was programmed with " +
                           formatValue(assumed.radius));
    if (assumed.turning && actual->edgeOrientation != assumed.edge)
        problems.push_back(
            tool + ": cutting edge orientation " + std::to_string(actual->edgeOrientation) +
            " in the tool list, the cycle was programmed with " + std::to_string(assumed.edge));
    return problems;
}

}  // namespace mtc::core::gne
