#pragma once

#include "cnc_core/machine_data/MachineDataStore.h"

namespace mtc::core {

/// The machine data an interpreter uses when the cell gives it none: the
/// full MachineDataStore (pages 30, 60, 61 and the user pages, with write
/// protection, password and ranges), without persistence. The name stays
/// for the callers that made the earlier stand-in.
class InMemoryMachineData : public MachineDataStore {
  public:
    using MachineDataStore::MachineDataStore;
};

}  // namespace mtc::core
