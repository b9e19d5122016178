#pragma once

#include <string>

namespace mtc::core {

/// MTD(page, process, sub, element) after the defaults are filled in
/// (empty process = the running process, empty sub = 0).
struct MachineDataAddress {
    int page = 0;
    int process = 0;
    int sub = 0;
    int element = 0;
};

/// Who writes: NC program (MTD(...)=...), SPS (MTD_WR) or the operator (GUI).
enum class MachineDataWriter { Nc, Sps, Gui };

enum class MachineDataStatus {
    Ok,
    UnknownPage,       ///< no such page (or not provided by this implementation)
    UnknownProcess,    ///< the page does not exist for that process
    UnknownElement,    ///< element / sub index outside the page
    OutOfRange,        ///< value outside the element's value range
    WriteProtected,    ///< the writer may not change the element
    WrongType,         ///< not a whole number for BOOL/SINT/UINT/INT elements
    PasswordRequired,  ///< the operator must give the machine data password
    WrongPassword,     ///< the operator gave a password that does not match
};

/// Stable code for a status ("MTD_UNKNOWN_PAGE", ...; "" for Ok).
const char* machineDataStatusCode(MachineDataStatus status);
/// One sentence for the operator ("value outside the element's range", ...).
const char* machineDataStatusText(MachineDataStatus status);

/// The machine data the NC reads and writes with MTD. One object per cell,
/// shared by every process. Implementations never throw.
class MachineDataProvider {
  public:
    virtual ~MachineDataProvider() = default;
    /// Reads one element into `value`; `value` is untouched unless Ok.
    virtual MachineDataStatus read(const MachineDataAddress& address, double& value) const = 0;
    /// What write() would answer, without writing.
    virtual MachineDataStatus check(const MachineDataAddress& address, double value,
                                    MachineDataWriter writer) const = 0;
    /// Writes one element; nothing changes unless Ok.
    virtual MachineDataStatus write(const MachineDataAddress& address, double value,
                                    MachineDataWriter writer) = 0;
};

}  // namespace mtc::core
