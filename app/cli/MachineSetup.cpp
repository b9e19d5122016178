#include "cli/MachineSetup.h"

#include "cnc_core/machine/MachineConfigFile.h"
#include "resources/EmbeddedResources.h"

namespace mtc::cli {

std::optional<core::MachineConfig> loadMachine(const std::string& machineFile,
                                               core::DiagnosticList& diagnostics) {
    core::MachineConfigReadResult result;
    std::string origin = machineFile;
    if (machineFile.empty()) {
        bool found = false;
        const std::string_view text = resources::find(resources::kDemoCellName, &found);
        origin = "built-in demo cell";
        if (!found) {
            diagnostics.error("CLI_MACHINE_MISSING", {}, "the built-in demo cell is missing");
            return std::nullopt;
        }
        core::MachineConfigReadOptions options;
        options.fileName = origin;
        options.requireEndMarker = true;
        result = core::readMachineConfig(text, options);
    } else {
        result = core::readMachineConfigFile(machineFile);
    }
    if (!result.ok()) {
        const bool unreadable = result.diagnostics.items().front().code == "CFG_FILE";
        diagnostics.error(unreadable ? "CLI_FILE_UNREADABLE" : "CLI_MACHINE_INVALID", {},
                          unreadable ? result.diagnostics.items().front().message
                                     : "machine configuration " + origin + " has errors");
        if (!unreadable) diagnostics.append(result.diagnostics);
        return std::nullopt;
    }
    diagnostics.append(result.diagnostics);  // warnings only
    return std::move(result.config);
}

bool checkProcessExists(const core::MachineConfig& machine, int process,
                        core::DiagnosticList& diagnostics) {
    if (machine.process(process) != nullptr) return true;
    diagnostics.error(
        "CLI_NO_SUCH_PROCESS", {},
        "process " + std::to_string(process) + " does not exist in machine '" + machine.name + "'",
        {"the machine has " + std::to_string(machine.processes.size()) + " process(es)"});
    return false;
}

}  // namespace mtc::cli
