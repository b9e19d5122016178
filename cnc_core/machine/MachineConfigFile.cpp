#include "cnc_core/machine/MachineConfigFile.h"

#include "cnc_core/machine/ConfigText.h"
#include "cnc_core/program/FileText.h"

namespace mtc::core {

MachineConfigReadResult readMachineConfigFile(const std::string& path) {
    std::string text, error;
    if (!readFileText(path, text, error, kMaxMachineConfigBytes)) {
        MachineConfigReadResult result;
        result.diagnostics.error("CFG_FILE", {}, "machine configuration " + error);
        return result;
    }
    MachineConfigReadOptions options;
    options.fileName = path;
    options.requireEndMarker = true;
    return readMachineConfig(text, options);
}

}  // namespace mtc::core
