#pragma once

#include "cnc_core/machine/MachineConfig.h"
#include "cnc_core/machine_data/MachineDataPage.h"

namespace mtc::core {

/// Page 30 "Adaptive feed control", elements 001..014 with the data types,
/// ranges, units, write and password protection of seed 002, ch. 5.
MachineDataPage adaptiveFeedPage();
/// Page 60 "NC program restart and REPOS" (seed 000, 4.1): rotary axis mode
/// of spindle 1..3, transformation selection, T number in tool spindle 1..4.
MachineDataPage restartPage();
/// Page 61 "M(16) and Q function buffers" (seed 000, 4.2): sub 1 = M group
/// 16, sub 2 = Q functions, elements 1..40 each, oldest first, 0 = empty.
MachineDataPage functionBufferPage();
/// A user page of the machine configuration as a page definition. Fails
/// never: the configuration reader checked types and ranges (an unknown
/// type name is taken as REAL).
MachineDataPage userPage(const UserDataPage& page);

/// Page numbers of the pages every process has.
constexpr int kAdaptiveFeedPage = 30;
constexpr int kRestartPage = 60;
constexpr int kFunctionBufferPage = 61;

}  // namespace mtc::core
