#pragma once

#include <array>
#include <cstdint>

#include "cnc_core/machine/MachineConfig.h"

/// The G code groups of the interpreter. Numbers 1, 2, 3, 4, 6, 13 and 17
/// are the seeds' group numbers (CLI-CONTRACT.md); the others are this
/// project's own (docs/decisions/interpreter.md lists them all).
namespace mtc::core {

enum GGroup : int {
    kGroupInterpolation = 1,    ///< G0 G1 G2 G3
    kGroupPlane = 2,            ///< G17 G18 G19 G20
    kGroupToolPath = 3,         ///< G40 G41 G42
    kGroupZeroOffset = 4,       ///< G53 G54 .. G59
    kGroupFeedType = 5,         ///< G94 feed per minute, G95 feed per revolution
    kGroupDimension = 6,        ///< G90 absolute, G91 incremental
    kGroupRadiusDiameter = 7,   ///< G15 radius, G16 diameter programming
    kGroupUnits = 8,            ///< G70 inch, G71 metric
    kGroupSurfaceSpeed = 9,     ///< G96 constant surface speed, G97 rpm
    kGroupAcceleration = 10,    ///< G6 / G7 (recorded only)
    kGroupExactStop = 11,       ///< G8 / G9 (recorded only)
    kGroupToolLength = 13,      ///< G47 off, G48 on
    kGroupTransformation = 17,  ///< G30 none, G31 facing, G32 lateral cylinder
};

inline constexpr int kGroupSlots = 18;  ///< group numbers 1..17 index the array directly

/// What a G number does.
enum class GKind : std::uint8_t {
    Unknown,       ///< not a G function of the MTC200 dialect we know
    Unsupported,   ///< a real MTC200 G function this simulator does not execute
    Modal,         ///< member of a modal group
    Dwell,         ///< G4 (non-modal, time in F)
    SpeedLimit,    ///< G92 (non-modal, S words are limits)
    AxisFunction,  ///< G74 homing, G75 hard stop, G77 REPOS (non-modal, act on the axis words)
    AdaptiveFeed,  ///< G25 off / G26 on: adaptive feed control (state kept by AdaptiveFeedControl)
};

struct GCodeInfo {
    GKind kind = GKind::Unknown;
    std::int8_t group = 0;
};

/// Classification table of G0..G99 (built once; see ModalGroups.cpp).
const std::array<GCodeInfo, 100>& gCodeTable();

/// Classification of G number `number` (0..99; anything else is Unknown).
inline GCodeInfo gCodeInfo(int number) {
    if (number < 0 || number > 99) return {};
    return gCodeTable()[static_cast<std::size_t>(number)];
}

/// The active G function of every group: index = group number, -1 = unused.
using GGroupValues = std::array<std::int16_t, kGroupSlots>;

/// Power-on / program-end defaults: group 2 from Bxx.004, group 7 from
/// Bxx.015 ("radius"/"diameter"), the rest fixed (see the decisions file).
GGroupValues defaultGGroups(const ProcessConfig& config);

/// The group numbers in use, ascending (for state listings).
const std::array<int, 13>& usedGGroups();

/// Names of a G group: `brief` for the base screen's narrow column
/// ("radius comp."), `full` for reports ("tool path compensation").
struct GGroupName {
    const char* brief = "";
    const char* full = "";
};

/// The names of group `group` (both "" for a number no group has).
GGroupName gGroupName(int group);

}  // namespace mtc::core
