#pragma once

#include "cnc_core/machine/MachineConfig.h"

namespace mtc::fuzz {

/// The built-in demo cell (read once; aborts when it does not load).
const core::MachineConfig& demoCell();

}  // namespace mtc::fuzz
