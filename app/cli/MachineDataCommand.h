#pragma once

#include "cli/CliOptions.h"

namespace mtc::cli {

/// `md get [PAGE]` and `md set PAGE ELEMENT VALUE [--as nc|sps|gui]
/// [--password PW] [--sub N]` on the machine data of the cell (--machine,
/// --process, --data FILE, --json). Exit codes: 0 done; 1 the machine data
/// refused (unknown page/element, out of range, wrong type, protected,
/// password); 2 usage, text in a numeric field, or a data file that cannot be
/// read or written. Prints the result (text or one JSON document).
int runMachineDataCommand(const CliOptions& options);

}  // namespace mtc::cli
