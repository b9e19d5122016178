#pragma once

#include <array>
#include <map>
#include <vector>

#include "cnc_core/machine/MachineConfig.h"
#include "cnc_core/machine/MachineDataProvider.h"

namespace mtc::core {

/// A simple machine data store, enough for the interpreter and its tests:
///  - user pages (100..999) from the configuration, per process, with each
///    element's value range and default (writes outside the range fail);
///  - page 60 "NC program restart and REPOS" as a plain array of elements
///    1..8 (sub 0): 1-3 rotary axis mode of spindle 1-3 (0/1), 4 transformation
///    selection (30/31/32), 5-8 T number in tool spindle 1-4 (0..9999999);
///  - page 61 "M(16) and Q function buffers" as plain arrays: sub 1 = M group
///    16, sub 2 = Q functions, elements 1..40, initialised to 0.
/// Page 30 (adaptive feed control) and the write protection rules of the
/// real pages are NOT modelled here: a later machine-data layer implements
/// them behind the same MachineDataProvider interface. Any writer may write.
class InMemoryMachineData : public MachineDataProvider {
  public:
    explicit InMemoryMachineData(const MachineConfig& config);

    MachineDataStatus read(const MachineDataAddress& address, double& value) const override;
    MachineDataStatus check(const MachineDataAddress& address, double value,
                            MachineDataWriter writer) const override;
    MachineDataStatus write(const MachineDataAddress& address, double value,
                            MachineDataWriter writer) override;

    static constexpr int kPage60Elements = 8;
    static constexpr int kBufferLength = 40;

  private:
    struct UserElement {
        UserDataElement definition;
        double value = 0.0;
    };
    struct ProcessData {
        std::array<double, kPage60Elements> page60{};
        std::array<std::array<double, kBufferLength>, 2> page61{};
        std::map<int, std::vector<UserElement>> userPages;
    };

    /// Finds the storage of `address` in `processes` (const or not).
    template <class Processes, class Slot>
    static MachineDataStatus locate(Processes& processes, const MachineDataAddress& address,
                                    Slot*& slot, const UserDataElement*& user);
    static bool page60ValueValid(int element, double value);

    std::map<int, ProcessData> processes_;
};

}  // namespace mtc::core
