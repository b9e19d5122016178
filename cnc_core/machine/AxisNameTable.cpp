#include "cnc_core/machine/AxisNameTable.h"

namespace mtc::core {

void AxisNameTable::put(AxisName name, int axis, AxisNameStatus status) {
    if (!name.valid() || name.letter < 'A' || name.letter > 'Z' || name.index > 3) return;
    entries_[static_cast<size_t>((name.letter - 'A') * 4 + name.index)] = {axis, status};
}

AxisNameTable AxisNameTable::build(const ProcessAxes& axes, const Transformation& transformation) {
    AxisNameTable table;
    for (int i = 0; i < axes.count(); ++i) {
        const AxisModel& a = axes.axis(i);
        const bool renamed = transformation.transforms(i) && a.designation2.valid();
        if (!renamed) {
            table.put(a.designation2, i, AxisNameStatus::InactiveDesignation2);
            continue;
        }
        table.put(a.name, i,
                  a.rotary ? AxisNameStatus::TransformedRotary : AxisNameStatus::TransformedLinear);
    }
    // Valid names last so that they win over any collision with the entries above.
    for (int i = 0; i < axes.count(); ++i) {
        const AxisModel& a = axes.axis(i);
        const bool renamed = transformation.transforms(i) && a.designation2.valid();
        table.put(renamed ? a.designation2 : a.name, i, AxisNameStatus::Ok);
    }
    return table;
}

}  // namespace mtc::core
