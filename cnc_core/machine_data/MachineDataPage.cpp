#include "cnc_core/machine_data/MachineDataPage.h"

namespace mtc::core {

bool MachineDataElement::protectedFor(MachineDataWriter writer) const {
    switch (writer) {
        case MachineDataWriter::Nc:
            return protectedNc;
        case MachineDataWriter::Sps:
            return protectedSps;
        case MachineDataWriter::Gui:
            return protectedGui;
    }
    return true;
}

std::vector<int> MachineDataPage::subs() const {
    if (subTitles.empty()) return {0};
    std::vector<int> result;
    for (int sub = 1; sub <= static_cast<int>(subTitles.size()); ++sub)
        result.push_back(sub);
    return result;
}

int MachineDataPage::subSlot(int sub) const {
    if (subTitles.empty()) return sub == 0 ? 0 : -1;
    return sub >= 1 && sub <= static_cast<int>(subTitles.size()) ? sub - 1 : -1;
}

int MachineDataPage::elementIndex(int number) const {
    for (std::size_t i = 0; i < elements.size(); ++i)
        if (elements[i].number == number) return static_cast<int>(i);
    return -1;
}

const MachineDataElement* MachineDataPage::element(int number) const {
    const int index = elementIndex(number);
    return index < 0 ? nullptr : &elements[static_cast<std::size_t>(index)];
}

}  // namespace mtc::core
