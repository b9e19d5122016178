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

namespace detail {

constexpr GCodeInfo classify(int number) {
    switch (number) {
        case 0:
        case 1:
        case 2:
        case 3:
            return {GKind::Modal, kGroupInterpolation};
        case 4:
            return {GKind::Dwell, 0};
        case 6:
        case 7:
            return {GKind::Modal, kGroupAcceleration};
        case 8:
        case 9:
            return {GKind::Modal, kGroupExactStop};
        case 15:
        case 16:
            return {GKind::Modal, kGroupRadiusDiameter};
        case 17:
        case 18:
        case 19:
        case 20:
            return {GKind::Modal, kGroupPlane};
        case 30:
        case 31:
        case 32:
            return {GKind::Modal, kGroupTransformation};
        case 40:
        case 41:
        case 42:
            return {GKind::Modal, kGroupToolPath};
        case 47:
        case 48:
            return {GKind::Modal, kGroupToolLength};
        case 53:
        case 54:
        case 55:
        case 56:
        case 57:
        case 58:
        case 59:
            return {GKind::Modal, kGroupZeroOffset};
        case 70:
        case 71:
            return {GKind::Modal, kGroupUnits};
        case 90:
        case 91:
            return {GKind::Modal, kGroupDimension};
        case 92:
            return {GKind::SpeedLimit, 0};
        case 74:  // homing
        case 75:  // driving against hard stop
        case 77:  // REPOS: back to the re-entry point (seed 000, 2.9 / 7)
            return {GKind::AxisFunction, 0};
        case 94:
        case 95:
            return {GKind::Modal, kGroupFeedType};
        case 96:
        case 97:
            return {GKind::Modal, kGroupSurfaceSpeed};
        case 25:
        case 26:  // adaptive feed control (seed 002)
            return {GKind::AdaptiveFeed, 0};
        // Named in the seeds, not executed by this simulator (yet):
        case 33:
        case 63:
        case 64:
        case 65:  // thread cutting, tapping
        case 50:
        case 51:
        case 52:  // programmable / incremental zero offsets
        case 72:
        case 73:
        case 76:
        case 78:
        case 79:
            return {GKind::Unsupported, 0};
        default:
            return {GKind::Unknown, 0};
    }
}

/// G0..G99 classified at compile time.
constexpr std::array<GCodeInfo, 100> buildGCodeTable() {
    std::array<GCodeInfo, 100> t{};
    for (int g = 0; g < 100; ++g)
        t[static_cast<std::size_t>(g)] = classify(g);
    return t;
}

}  // namespace detail

/// Classification table of G0..G99: a constant, so that the decoder reads it
/// without a call (and without an initialisation guard).
inline constexpr std::array<GCodeInfo, 100> kGCodeTable = detail::buildGCodeTable();

/// The same table (kept for callers that take it by reference).
inline const std::array<GCodeInfo, 100>& gCodeTable() {
    return kGCodeTable;
}

/// Classification of G number `number` (0..99; anything else is Unknown).
inline GCodeInfo gCodeInfo(int number) {
    if (number < 0 || number > 99) return {};
    return kGCodeTable[static_cast<std::size_t>(number)];
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
