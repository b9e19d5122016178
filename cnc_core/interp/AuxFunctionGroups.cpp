#include "cnc_core/interp/AuxFunctionGroups.h"

namespace mtc::core {

AuxFunctionGroups::AuxFunctionGroups(const ProcessConfig& config) {
    table_.fill(16);
    for (const auto& group : config.mGroups)
        if (group.number >= 1 && group.number <= 15)
            for (int m : group.functions)
                if (m >= 0 && m < kFunctions)
                    table_[static_cast<std::size_t>(m)] = static_cast<std::uint8_t>(group.number);
    // Mnn and M1nn are the same function of spindle 1 (the reference spindle):
    // whichever of the two the configuration lists gives the group of both.
    for (int nn = 0; nn < 100; ++nn) {
        if (!isSpindleFunction(nn)) continue;
        auto& plain = table_[static_cast<std::size_t>(nn)];
        auto& indexed = table_[100 + static_cast<std::size_t>(nn)];
        if (plain == 16) plain = indexed;
        if (indexed == 16) indexed = plain;
    }
}

}  // namespace mtc::core
