#pragma once

#include <string>

namespace mtc::core {

/// Where the machine data of the cell `cellName` is kept when nobody names a
/// file: `$XDG_STATE_HOME/mtc200/machine-data/<name>.mdt`, else
/// `$HOME/.local/state/mtc200/machine-data/<name>.mdt`; <name> is the cell
/// name with every character other than letters, digits, '-' and '_'
/// replaced by '_' ("cell" when empty). Empty when neither variable is set
/// (then nothing is kept). Reads the environment; changes nothing.
std::string defaultMachineDataPath(const std::string& cellName);

/// Creates the directory of `path` and its parents (mode 0755) as needed.
/// Returns false with `error` when one cannot be made.
bool makeParentDirectories(const std::string& path, std::string& error);

}  // namespace mtc::core
