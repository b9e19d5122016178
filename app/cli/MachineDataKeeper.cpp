#include "cli/MachineDataKeeper.h"

namespace mtc::cli {

void MachineDataKeeper::load(core::MachineDataStore& data, core::DiagnosticList& diagnostics) {
    loadedRevision_ = data.revision();
    if (file_.empty()) return;
    shared_.emplace(file_);
    core::MachineDataLoadResult loaded = shared_->open(data);
    diagnostics.append(loaded.diagnostics);
    loadedRevision_ = data.revision();
}

void MachineDataKeeper::save(core::MachineDataStore& data, core::DiagnosticList& diagnostics) {
    if (!shared_ || data.revision() == loadedRevision_) return;
    core::MachineDataSync sync = shared_->save(data);
    diagnostics.append(sync.diagnostics);
    if (!sync.ok) diagnostics.error("MD_FILE_SAVE", {}, "machine data not saved: " + sync.error);
}

}  // namespace mtc::cli
