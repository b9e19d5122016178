#include "cnc_core/machine/InMemoryMachineData.h"

#include <cmath>

namespace mtc::core {

const char* machineDataStatusCode(MachineDataStatus status) {
    switch (status) {
        case MachineDataStatus::Ok:
            return "";
        case MachineDataStatus::UnknownPage:
            return "MTD_UNKNOWN_PAGE";
        case MachineDataStatus::UnknownProcess:
            return "MTD_UNKNOWN_PROCESS";
        case MachineDataStatus::UnknownElement:
            return "MTD_UNKNOWN_ELEMENT";
        case MachineDataStatus::OutOfRange:
            return "MTD_OUT_OF_RANGE";
        case MachineDataStatus::WriteProtected:
            return "MTD_WRITE_PROTECTED";
    }
    return "MTD_ERROR";
}

InMemoryMachineData::InMemoryMachineData(const MachineConfig& config) {
    for (const auto& process : config.processes) {
        ProcessData& data = processes_[process.index];
        data.page60[3] = 30;  // element 4: transformation selection defaults to 30
        for (const auto& page : process.userPages) {
            auto& elements = data.userPages[page.number];
            for (const auto& e : page.elements)
                elements.push_back({e, e.defaultValue});
        }
    }
}

template <class Processes, class Slot>
MachineDataStatus InMemoryMachineData::locate(Processes& processes, const MachineDataAddress& a,
                                              Slot*& slot, const UserDataElement*& user) {
    slot = nullptr;
    user = nullptr;
    const bool knownPage = a.page == 60 || a.page == 61 || (a.page >= 100 && a.page <= 999);
    if (!knownPage) return MachineDataStatus::UnknownPage;
    auto data = processes.find(a.process);
    if (data == processes.end()) return MachineDataStatus::UnknownProcess;
    if (a.page == 60) {
        if (a.sub != 0 || a.element < 1 || a.element > kPage60Elements)
            return MachineDataStatus::UnknownElement;
        slot = &data->second.page60[static_cast<size_t>(a.element - 1)];
        return MachineDataStatus::Ok;
    }
    if (a.page == 61) {
        if (a.sub < 1 || a.sub > 2 || a.element < 1 || a.element > kBufferLength)
            return MachineDataStatus::UnknownElement;
        slot = &data->second
                    .page61[static_cast<size_t>(a.sub - 1)][static_cast<size_t>(a.element - 1)];
        return MachineDataStatus::Ok;
    }
    auto page = data->second.userPages.find(a.page);
    if (page == data->second.userPages.end()) return MachineDataStatus::UnknownPage;
    if (a.sub != 0) return MachineDataStatus::UnknownElement;
    for (auto& e : page->second)
        if (e.definition.number == a.element) {
            user = &e.definition;
            slot = &e.value;
            return MachineDataStatus::Ok;
        }
    return MachineDataStatus::UnknownElement;
}

MachineDataStatus InMemoryMachineData::read(const MachineDataAddress& address,
                                            double& value) const {
    const double* slot = nullptr;
    const UserDataElement* user = nullptr;
    const MachineDataStatus status = locate(processes_, address, slot, user);
    if (status == MachineDataStatus::Ok) value = *slot;
    return status;
}

bool InMemoryMachineData::page60ValueValid(int element, double value) {
    if (value != std::floor(value)) return false;
    if (element <= 3) return value == 0 || value == 1;
    if (element == 4) return value == 30 || value == 31 || value == 32;
    return value >= 0 && value <= 9999999;
}

MachineDataStatus InMemoryMachineData::check(const MachineDataAddress& address, double value,
                                             MachineDataWriter /*writer*/) const {
    const double* slot = nullptr;
    const UserDataElement* user = nullptr;
    const MachineDataStatus status = locate(processes_, address, slot, user);
    if (status != MachineDataStatus::Ok) return status;
    if (!std::isfinite(value)) return MachineDataStatus::OutOfRange;
    if (user && (value < user->minimum || value > user->maximum))
        return MachineDataStatus::OutOfRange;
    if (address.page == 60 && !page60ValueValid(address.element, value))
        return MachineDataStatus::OutOfRange;
    if (address.page == 61 && (value < 0 || value != std::floor(value)))
        return MachineDataStatus::OutOfRange;
    return MachineDataStatus::Ok;
}

MachineDataStatus InMemoryMachineData::write(const MachineDataAddress& address, double value,
                                             MachineDataWriter writer) {
    const MachineDataStatus status = check(address, value, writer);
    if (status != MachineDataStatus::Ok) return status;
    double* slot = nullptr;
    const UserDataElement* user = nullptr;
    locate(processes_, address, slot, user);
    *slot = value;
    return MachineDataStatus::Ok;
}

}  // namespace mtc::core
