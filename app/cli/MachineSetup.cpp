#include "cli/MachineSetup.h"

#include "cli/ProgramMemory.h"
#include "cnc_core/machine/MachineConfigReader.h"
#include "resources/EmbeddedResources.h"

namespace mtc::cli {

std::optional<core::MachineConfig> loadMachine(const std::string& machineFile,
                                               core::DiagnosticList& diagnostics) {
    std::string text;
    std::string origin = machineFile;
    if (machineFile.empty()) {
        bool found = false;
        text = std::string(resources::find(resources::kDemoCellName, &found));
        origin = "built-in demo cell";
        if (!found) {
            diagnostics.error("CLI_MACHINE_MISSING", {}, "the built-in demo cell is missing");
            return std::nullopt;
        }
    } else {
        std::string error;
        if (!readTextFile(machineFile, text, error)) {
            diagnostics.error("CLI_FILE_UNREADABLE", {}, error);
            return std::nullopt;
        }
    }
    core::MachineConfigReadResult result = core::readMachineConfig(text);
    if (!result.ok()) {
        diagnostics.error("CLI_MACHINE_INVALID", {},
                          "machine configuration " + origin + " has errors");
        diagnostics.append(result.diagnostics);
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
