#pragma once

#include <string>
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

/// How a configuration text is read.
struct MachineConfigReadOptions {
    /// Named at the start of every message ("cell.cfg: [process 0 axis X] ...").
    std::string fileName = "machine configuration";
    /// True for every text that comes from a file (readMachineConfigFile, the
    /// built-in demo cell): the text must end with the `[end]` line, so that a
    /// file cut off anywhere is refused (CFG_TRUNCATED; docs/MACHINE-CONFIG.md).
    /// Texts built in memory (tests) may leave it out.
    bool requireEndMarker = false;
};

/// Parses the machine configuration text format (docs/MACHINE-CONFIG.md).
/// Every value is checked against its rule (ConfigSchema.h: type, finiteness,
/// range); unknown sections and keys, duplicates and bad values are errors
/// naming file, line, section, key, value and the allowed range; then the
/// axes of every process are checked together (ProcessAxes::build). Linear
/// in the size of the text. Never throws.
MachineConfigReadResult readMachineConfig(std::string_view text,
                                          const MachineConfigReadOptions& options = {});

}  // namespace mtc::core
