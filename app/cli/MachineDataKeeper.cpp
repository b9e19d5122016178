#include "cli/MachineDataKeeper.h"

#include "cnc_core/machine_data/MachineDataFile.h"

namespace mtc::cli {

void MachineDataKeeper::load(core::MachineDataStore& data, core::DiagnosticList& diagnostics) {
    loadedRevision_ = data.revision();
    if (file_.empty()) return;
    core::MachineDataLoadResult loaded = core::MachineDataFile(file_).load(data);
    mayOverwrite_ = loaded.mayOverwrite;
    diagnostics.append(loaded.diagnostics);
    loadedRevision_ = data.revision();
}

void MachineDataKeeper::save(const core::MachineDataStore& data,
                             core::DiagnosticList& diagnostics) const {
    if (file_.empty() || data.revision() == loadedRevision_) return;
    std::string reason;
    if (!mayOverwrite_)
        reason = "the damaged machine data file could not be kept aside";
    else if (core::MachineDataFile(file_).save(data, reason))
        return;
    diagnostics.error("MD_FILE_SAVE", {}, "machine data not saved: " + reason);
}

}  // namespace mtc::cli
