#pragma once

#include <string>
#include <vector>

#include "cnc_core/machine/MachineDataProvider.h"
#include "cnc_core/machine_data/MachineDataType.h"

namespace mtc::core {

/// Definition of one machine data element: what the page lists and the
/// rules every write follows.
struct MachineDataElement {
    int number = 0;
    std::string designation;
    MachineDataType type = MachineDataType::Int;
    double minimum = 0.0;
    double maximum = 0.0;
    double defaultValue = 0.0;
    std::string unit;
    bool protectedNc = false;   ///< MTD(...)= in an NC program is refused
    bool protectedSps = false;  ///< MTD_WR of the SPS is refused
    bool protectedGui = false;  ///< the operator cannot change it
    bool password = false;      ///< the operator needs the machine data password

    /// True when `writer` may not change the element at all.
    bool protectedFor(MachineDataWriter writer) const;
};

/// Definition of one machine data page. Pages with sub-arrays (page 61:
/// sub 1 = M(16), sub 2 = Q) list their sub titles; the other pages have
/// sub 0 only. Every sub has the same elements.
struct MachineDataPage {
    int number = 0;
    std::string title;
    std::vector<std::string> subTitles;  ///< empty: sub 0 only; else subs 1..size()
    std::vector<MachineDataElement> elements;

    /// Sub indices of the page: {0} or {1..n}.
    std::vector<int> subs() const;
    /// Index of `sub` in subs(), or -1.
    int subSlot(int sub) const;
    /// Index of element `number` in elements, or -1.
    int elementIndex(int number) const;
    /// The element `number`, or nullptr.
    const MachineDataElement* element(int number) const;
};

}  // namespace mtc::core
