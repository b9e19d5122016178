#pragma once

#include <array>

#include "cnc_core/interp/InterpreterState.h"

namespace mtc::core {

/// What a block will do, computed from the BlockInput without touching the
/// interpreter state. The interpreter commits it only when no error occurred.
struct BlockPlan {
    ModalState next;  ///< modal state after the block

    bool hasMotion = false;
    MotionType motionType = MotionType::Linear;
    int planeAxis1 = -1, planeAxis2 = -1;  ///< arcs
    double center1 = 0.0, center2 = 0.0;   ///< arcs: machine units (G31: plane coordinates)
    /// Arcs: centre in plane coordinates (zero offsets applied, before G31/G32; tool compensation).
    double planeCenter1 = 0.0, planeCenter2 = 0.0;
    bool fullCircle = false;  ///< arcs: start and end coincide, one whole turn
    double feedRate = 0.0;    ///< mm/min, 0 for rapid

    double dwellSeconds = -1.0;  ///< G4 time; < 0 = no dwell
    int programControl = -1;     ///< M00, M01, M02 or M30 of this block; -1 = none
    bool auxChanged = false;     ///< M or Q words present: mGroups/lastQ below are valid
    std::array<int, 17> mGroups{};
    int lastQ = -1;
};

}  // namespace mtc::core
