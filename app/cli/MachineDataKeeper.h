#pragma once

#include <cstdint>
#include <string>

#include <optional>

#include "cnc_core/language/Diagnostic.h"
#include "cnc_core/machine_data/SharedMachineDataFile.h"

namespace mtc::cli {

/// The `--data FILE` of `run` and `restart`: loads the machine data file
/// before the program runs and saves it afterwards when the program changed
/// something (MTD writes, page 30 status, page 60 at a restart target).
/// The save takes over what other programs changed in the file meanwhile
/// (SharedMachineDataFile: locked, never an older copy written back).
/// Without a file ("" or "-") nothing is loaded or kept.
class MachineDataKeeper {
  public:
    explicit MachineDataKeeper(const std::string& dataFile)
        : file_(dataFile.empty() || dataFile == "-" ? "" : dataFile) {}

    /// Loads the file into `data`; its warnings go to `diagnostics`.
    void load(core::MachineDataStore& data, core::DiagnosticList& diagnostics);
    /// Saves `data` when it changed since load() (MD_FILE_SAVE error when it cannot).
    void save(core::MachineDataStore& data, core::DiagnosticList& diagnostics);
    /// The file ("" = none).
    const std::string& file() const { return file_; }

  private:
    std::string file_;
    std::optional<core::SharedMachineDataFile> shared_;
    std::uint64_t loadedRevision_ = 0;
};

}  // namespace mtc::cli
