#pragma once

#include <string>

#include "cnc_core/language/Diagnostic.h"
#include "cnc_core/machine_data/MachineDataStore.h"

namespace mtc::cli {

/// What `md get` and `md set` print besides the page itself.
struct MachineDataReport {
    int process = 0;
    std::string processName;
    std::string dataFile;  ///< "" = nothing kept
    core::DiagnosticList diagnostics;
};

/// `md get PAGE` as text: a title line, then per sub a table
/// Nr. / Title / Value / Unit / Type / Protection; `onlySub` >= 0: that sub only.
void printPageText(const core::MachineDataStore& store, const core::MachineDataPage& page,
                   const MachineDataReport& report, int onlySub = -1);
/// `md get PAGE --json`:
/// {"status","process","page","title","data_file","subs":[...],"diagnostics"};
/// `onlySub` >= 0: "subs" holds that sub only.
void printPageJson(const core::MachineDataStore& store, const core::MachineDataPage& page,
                   const MachineDataReport& report, int onlySub = -1);
/// `md get` without a page: the pages of the process (text or JSON).
void printPageList(const core::MachineDataStore& store, const MachineDataReport& report, bool json);
/// The result of `md set` (text or JSON); `status` "ok" or "error".
void printSetResult(const core::MachineDataAddress& address, const core::MachineDataElement& e,
                    double before, double after, const MachineDataReport& report, bool json);
/// A refused command: diagnostics on stderr (text) or {"status":"error",...}.
void printRefusal(const MachineDataReport& report, bool json);

}  // namespace mtc::cli
