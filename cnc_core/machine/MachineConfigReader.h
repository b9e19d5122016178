#pragma once

#include <string_view>

#include "cnc_core/language/Diagnostic.h"
#include "cnc_core/machine/MachineConfig.h"

namespace mtc::core {

/// Result of reading a machine configuration: the config as far as it could be
/// read, plus every problem (with line numbers). `ok` is false on any error.
struct MachineConfigReadResult {
    MachineConfig config;
    DiagnosticList diagnostics;
    bool ok() const { return !diagnostics.hasErrors(); }
};

/// Parses the machine configuration text format (docs/MACHINE-CONFIG.md).
/// Never throws; unknown sections/keys and bad values become diagnostics.
MachineConfigReadResult readMachineConfig(std::string_view text);

}  // namespace mtc::core
