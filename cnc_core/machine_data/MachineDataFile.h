#pragma once

#include <string>

#include "cnc_core/language/Diagnostic.h"
#include "cnc_core/machine_data/MachineDataStore.h"

namespace mtc::core {

/// What loading the machine data file did.
struct MachineDataLoadResult {
    bool fileFound = false;      ///< a file was there (damaged or not)
    bool keptAside = false;      ///< the file was renamed to `asidePath`
    std::string asidePath;       ///< where the damaged or partly unusable file now is
    bool mayOverwrite = true;    ///< false: a damaged file could not be kept aside; do not save
    DiagnosticList diagnostics;  ///< warnings for the user (never silent)
};

/// The machine data of one cell in one file, written atomically.
///
/// Format (text, one value per line, see docs/decisions/machine-data.md MD-010):
///   MTC200-MACHINE-DATA 1
///   cell <cell name>
///   <process> <page> <sub> <element> <value>
///   end <number of value lines> <FNV-1a 64 of everything before this line, hex>
/// A file that does not follow this exactly (truncated, garbage, changed by
/// hand) is damaged: it is renamed aside, the defaults stay, a warning says so.
class MachineDataFile {
  public:
    explicit MachineDataFile(std::string path) : path_(std::move(path)) {}

    const std::string& path() const { return path_; }
    /// Reads the file into `store`. First removes `<path>.tmpXXXXXX` files
    /// older than a minute that a killed save left behind (warning
    /// MD_STALE_TEMPORARY each). A missing file leaves the defaults and
    /// reports nothing else. A damaged file is renamed to `<path>.damaged-<time>`
    /// and the store is reset to its defaults (warning MD_FILE_DAMAGED). Values
    /// the store refuses (pages or elements no longer configured, ranges) are
    /// left out, the file is kept aside the same way (warning
    /// MD_FILE_VALUES_IGNORED). Never throws.
    MachineDataLoadResult load(MachineDataStore& store) const;
    /// Writes every value of `store` atomically (temporary file + fsync +
    /// rename): the file is the old or the new one, never a part. Returns
    /// false and says why in `error` when any step fails; the old file is then untouched.
    bool save(const MachineDataStore& store, std::string& error) const;

    /// The file text for `store` (what save() writes).
    static std::string serialize(const MachineDataStore& store);
    /// Parses file text; false with `reason` when it is damaged.
    static bool parse(const std::string& text, std::string& cell,
                      std::vector<MachineDataStore::Entry>& entries, std::string& reason);

    /// Renames the file aside; fills `result` (mayOverwrite false on failure).
    void keepAside(MachineDataLoadResult& result) const;

  private:
    std::string path_;
};

}  // namespace mtc::core
