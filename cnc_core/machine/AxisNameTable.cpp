#include "cnc_core/machine/AxisNameTable.h"

namespace mtc::core {
namespace {

/// G31/G32 renames `axis` to its designation 2 (seed 003, 4.5 and 5.2).
bool renamed(const AxisModel& a, const Transformation& transformation, int axis) {
    return transformation.transforms(axis) && a.designation2.valid();
}

}  // namespace

void AxisNameTable::put(AxisName name, int axis, AxisNameStatus status) {
    if (!name.valid() || name.letter < 'A' || name.letter > 'Z' || name.index > 3) return;
    entries_[static_cast<size_t>(name.letter - 'A') * 4 + name.index] = {axis, status};
}

AxisNameTable AxisNameTable::build(const ProcessAxes& axes, const Transformation& transformation) {
    AxisNameTable table;
    for (int i = 0; i < axes.count(); ++i) {
        const AxisModel& a = axes.axis(i);
        if (!renamed(a, transformation, i)) {
            table.put(a.designation2, i, AxisNameStatus::InactiveDesignation2);
            continue;
        }
        table.put(a.name, i,
                  a.rotary ? AxisNameStatus::TransformedRotary : AxisNameStatus::TransformedLinear);
    }
    // Valid names last so that they win over any collision with the entries above.
    for (int i = 0; i < axes.count(); ++i) {
        const AxisModel& a = axes.axis(i);
        table.put(renamed(a, transformation, i) ? a.designation2 : a.name, i, AxisNameStatus::Ok);
    }
    return table;
}

std::string programmedAxisName(const ProcessAxes& axes, const Transformation& transformation,
                               int axis) {
    const AxisModel& a = axes.axis(axis);
    return renamed(a, transformation, axis) ? a.designation2.toString() : a.displayName();
}

}  // namespace mtc::core
