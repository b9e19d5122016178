#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "cnc_core/machine_data/MachineDataFile.h"
#include "cnc_core/program/FileLock.h"

namespace mtc::core {

/// What a save or a refresh took over from the file.
struct MachineDataSync {
    bool ok = true;             ///< false: nothing written (`error` says why)
    std::string error;          ///< why not (lock, unreadable, write failed)
    std::size_t takenOver = 0;  ///< values another program had changed, now in the store
    DiagnosticList diagnostics;  ///< warnings (a damaged file found and kept aside, ...)
};

/// The machine data file of a cell shared by several programs (the panel,
/// `mtc200-cli md set`, `run --data`, ...): one writer at a time, and no
/// program writes an older copy over a newer one (docs/decisions/
/// config-files.md CF-020, CF-021).
///
/// It remembers the values the file held when this program last read or
/// wrote it (the base). save() locks the file (FileLock, bounded wait),
/// reads it again, takes over every value another program changed since
/// the base where this program did not change the same value, and writes
/// the result atomically; refresh() does the same without writing, when
/// the file changed on disk (its size, time or inode). Where both changed
/// the same value, this program's value is the one saved.
class SharedMachineDataFile {
  public:
    /// `lockWaitSeconds`: how long a save waits for another program's lock.
    explicit SharedMachineDataFile(std::string path,
                                   double lockWaitSeconds = FileLock::kDefaultWaitSeconds)
        : file_(std::move(path)), lockWait_(lockWaitSeconds) {}

    const std::string& path() const { return file_.path(); }
    /// Loads the file under the lock (MachineDataFile::load: a damaged file is
    /// kept aside, defaults load) and makes what was read the base. With
    /// `keepLocked` the lock is held until save() or release() (a short
    /// read-modify-write such as `md set`); when it cannot be had, the error
    /// MD_FILE_LOCKED says so and nothing will be saved.
    MachineDataLoadResult open(MachineDataStore& store, bool keepLocked = false);
    /// Gives up a lock held since open().
    void release() { held_.reset(); }
    /// Merges the file's news into `store` and writes `store` (see above).
    MachineDataSync save(MachineDataStore& store);
    /// Takes over another program's changes when the file changed since the
    /// last open/save/refresh; nothing when it did not (cheap: one stat).
    MachineDataSync refresh(MachineDataStore& store);
    /// False when open() found a damaged file it could not keep aside:
    /// then nothing is ever written over it.
    bool mayOverwrite() const { return mayOverwrite_; }

  private:
    using Key = std::tuple<int, int, int, int>;  ///< process, page, sub, element

    /// Reads the file (under the lock) and takes over what changed since
    /// the base; false (`sync.error`) when it cannot be read.
    bool merge(MachineDataStore& store, MachineDataSync& sync,
               std::vector<MachineDataStore::Entry>& theirs);
    void rememberBase(const std::vector<MachineDataStore::Entry>& entries);
    /// "size:mtime:inode" of the file ("" when missing).
    std::string stamp() const;

    MachineDataFile file_;
    double lockWait_;
    std::map<Key, double> base_;
    std::string stamp_;
    bool mayOverwrite_ = true;
    std::unique_ptr<FileLock> held_;  ///< the lock kept since open(keepLocked)
};

}  // namespace mtc::core
