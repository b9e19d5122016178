#pragma once

#include <cstdint>
#include <string>

#include "cnc_core/language/Diagnostic.h"
#include "cnc_core/machine_data/MachineDataStore.h"

namespace mtc::cli {

/// The `--data FILE` of `run` and `restart`: loads the machine data file
/// before the program runs and saves it afterwards when the program changed
/// something (MTD writes, page 30 status, page 60 at a restart target).
/// Without a file ("" or "-") nothing is loaded or kept.
class MachineDataKeeper {
  public:
    explicit MachineDataKeeper(const std::string& dataFile)
        : file_(dataFile.empty() || dataFile == "-" ? "" : dataFile) {}

    /// Loads the file into `data`; its warnings go to `diagnostics`.
    void load(core::MachineDataStore& data, core::DiagnosticList& diagnostics);
    /// Saves `data` when it changed since load() (MD_FILE_SAVE error when it cannot).
    void save(const core::MachineDataStore& data, core::DiagnosticList& diagnostics) const;
    /// The file ("" = none).
    const std::string& file() const { return file_; }

  private:
    std::string file_;
    bool mayOverwrite_ = true;
    std::uint64_t loadedRevision_ = 0;
};

}  // namespace mtc::cli
