#pragma once

#include <string>

#include "cnc_core/machine/MachineConfigReader.h"

namespace mtc::core {

/// Largest machine configuration file read (far above any cell; a cell with
/// a million tools is about 40 MB).
inline constexpr std::size_t kMaxMachineConfigBytes = std::size_t(256) << 20;

/// Reads and checks the machine configuration file `path` (every command of
/// the CLI and the panel go through it): a path that is not a readable
/// regular file (directory, FIFO, device, missing) or is larger than
/// kMaxMachineConfigBytes is the error CFG_FILE; the text must end with
/// `[end]` (CFG_TRUNCATED otherwise). Messages name the path. Never throws.
MachineConfigReadResult readMachineConfigFile(const std::string& path);

}  // namespace mtc::core
