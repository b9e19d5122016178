#include "DemoCell.h"

#include "../FuzzTargets.h"
#include "cnc_core/machine/MachineConfigReader.h"
#include "resources/EmbeddedResources.h"

namespace mtc::fuzz {

const core::MachineConfig& demoCell() {
    static const core::MachineConfig cell = [] {
        const std::string_view text = mtc::resources::find(mtc::resources::kDemoCellName);
        core::MachineConfigReadResult read = core::readMachineConfig(text);
        require(read.ok(), "the demo cell loads", text);
        return read.config;
    }();
    return cell;
}

}  // namespace mtc::fuzz
