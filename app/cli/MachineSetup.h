#pragma once

#include <optional>
#include <string>

#include "cnc_core/language/Diagnostic.h"
#include "cnc_core/machine/MachineConfig.h"

namespace mtc::cli {

/// Loads the machine of a command: the file given with --machine, or the
/// built-in demo cell when `machineFile` is empty. Fails (nothing, CLI_* and
/// configuration diagnostics in `diagnostics`) when the file cannot be read
/// or has errors.
std::optional<core::MachineConfig> loadMachine(const std::string& machineFile,
                                               core::DiagnosticList& diagnostics);

/// Checks that `process` exists in `machine`. Fails (false, CLI_NO_SUCH_PROCESS
/// in `diagnostics`) otherwise.
bool checkProcessExists(const core::MachineConfig& machine, int process,
                        core::DiagnosticList& diagnostics);

}  // namespace mtc::cli
