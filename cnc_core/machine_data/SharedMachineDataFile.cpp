#include "cnc_core/machine_data/SharedMachineDataFile.h"

#include <sys/stat.h>

#include "cnc_core/program/FileText.h"

namespace mtc::core {

MachineDataLoadResult SharedMachineDataFile::open(MachineDataStore& store, bool keepLocked) {
    auto lock = std::make_unique<FileLock>(file_.path(), lockWait_);
    MachineDataLoadResult result;
    if (!lock->locked() && keepLocked) {
        mayOverwrite_ = false;
        result.mayOverwrite = false;
        result.diagnostics.error("MD_FILE_LOCKED", {},
                                 "the machine data is NOT saved: " + lock->error());
        return result;
    }
    // Without the lock (a writer is slow) the file can still be read: it is
    // only ever replaced whole.
    result = file_.load(store);
    mayOverwrite_ = result.mayOverwrite;
    rememberBase(store.entries());
    stamp_ = stamp();
    if (keepLocked) held_ = std::move(lock);
    return result;
}

MachineDataSync SharedMachineDataFile::save(MachineDataStore& store) {
    MachineDataSync sync;
    std::unique_ptr<FileLock> lock = std::move(held_);
    if (!lock) lock = std::make_unique<FileLock>(file_.path(), lockWait_);
    if (!mayOverwrite_)
        sync.error = "the damaged machine data file could not be kept aside, so it is not "
                     "overwritten";
    else if (!lock->locked())
        sync.error = lock->error();
    std::vector<MachineDataStore::Entry> theirs;
    if (sync.error.empty() && merge(store, sync, theirs) && file_.save(store, sync.error)) {
        rememberBase(store.entries());
        stamp_ = stamp();
        return sync;
    }
    sync.ok = false;
    return sync;
}

MachineDataSync SharedMachineDataFile::refresh(MachineDataStore& store) {
    MachineDataSync sync;
    if (stamp() == stamp_) return sync;
    FileLock lock(file_.path(), lockWait_);
    if (!lock.locked()) {  // being written right now: next time
        sync.ok = false;
        sync.error = lock.error();
        return sync;
    }
    std::vector<MachineDataStore::Entry> theirs;
    if (!merge(store, sync, theirs)) {
        sync.ok = false;
        return sync;
    }
    if (!theirs.empty()) rememberBase(theirs);
    stamp_ = stamp();
    return sync;
}

bool SharedMachineDataFile::merge(MachineDataStore& store, MachineDataSync& sync,
                                  std::vector<MachineDataStore::Entry>& theirs) {
    theirs.clear();
    if (whyNotARegularFile(file_.path()) == "does not exist")
        return true;  // nothing to take over (removed, or never written)
    std::string text, reason, cell;
    if (!readFileText(file_.path(), text, reason)) {
        sync.error = "cannot read the machine data file again before saving: " + reason;
        return false;
    }
    if (!MachineDataFile::parse(text, cell, theirs, reason)) {
        // Damaged by someone else meanwhile: keep it aside, then write ours.
        MachineDataLoadResult aside;
        file_.keepAside(aside);
        sync.diagnostics.append(aside.diagnostics);
        sync.diagnostics.warning("MD_FILE_DAMAGED", {},
                                 "machine data file " + file_.path() + " was damaged (" + reason +
                                     ")" + (aside.keptAside ? "; kept as " + aside.asidePath : ""));
        theirs.clear();
        if (!aside.keptAside) {
            mayOverwrite_ = false;
            sync.error = "the damaged machine data file could not be kept aside";
            return false;
        }
        return true;
    }
    for (const MachineDataStore::Entry& e : theirs) {
        const MachineDataAddress& a = e.address;
        const auto base = base_.find({a.process, a.page, a.sub, a.element});
        double mine = 0.0;
        if (base == base_.end() || e.value == base->second ||
            store.read(a, mine) != MachineDataStatus::Ok || mine != base->second)
            continue;  // not changed there, or changed here too: this program's value stays
        if (store.update(a, e.value) == MachineDataStatus::Ok) ++sync.takenOver;
    }
    return true;
}

void SharedMachineDataFile::rememberBase(const std::vector<MachineDataStore::Entry>& entries) {
    for (const MachineDataStore::Entry& e : entries)
        base_[{e.address.process, e.address.page, e.address.sub, e.address.element}] = e.value;
}

std::string SharedMachineDataFile::stamp() const {
    struct stat info {};
    if (::stat(file_.path().c_str(), &info) != 0) return "";
    return std::to_string(info.st_size) + ":" + std::to_string(info.st_mtim.tv_sec) + "." +
           std::to_string(info.st_mtim.tv_nsec) + ":" + std::to_string(info.st_ino);
}

}  // namespace mtc::core
