#pragma once

#include <array>
#include <bitset>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

#include "cnc_core/interp/MachineSink.h"
#include "cnc_core/interp/ModalGroups.h"
#include "cnc_core/language/Program.h"
#include "cnc_core/machine/PlaneSelection.h"
#include "cnc_core/machine/Transformation.h"

namespace mtc::core {

inline constexpr int kSpindleSlots = 4;      ///< index 1..3 = S1..S3
inline constexpr int kToolSpindles = 4;      ///< page 60 elements 5..8
inline constexpr int kVariableCount = 1000;  ///< @0 .. @999
inline constexpr int kMaxCallLevels = 10;    ///< main program + 9 nested calls (seed 000, 2.5)

/// Everything a block may change except variables, aux groups and program
/// flow. Plain data: the interpreter copies it to validate a block and
/// assigns it back to commit, so a rejected block changes nothing.
struct ModalState {
    GGroupValues g{};
    PlaneSelection plane;
    Transformation transformation;
    /// Programmed (workpiece) coordinates per machine axis in mm (degrees for
    /// rotary axes outside a transformation; plane coordinates in mm for the
    /// axes a transformation maps).
    std::array<double, kMaxAxes> work{};
    /// Commanded machine positions (zero offsets applied, transformation
    /// applied): mm for linear axes, degrees for rotary axes.
    std::array<double, kMaxAxes> machine{};
    double feed = 0.0;  ///< F in mm/min (G94) or mm/rev (G95), metric
    std::array<double, kSpindleSlots> spindleSpeed{};         ///< last S per spindle
    std::array<double, kSpindleSlots> spindleLimit{};         ///< G92 S limits
    std::array<std::int8_t, kSpindleSlots> rotaryAxisMode{};  ///< page 60 el. 1..3
    std::array<int, kToolSpindles> toolSpindle{};             ///< page 60 el. 5..8
    int tool = 0;                                             ///< T
    int edge = 0;                                             ///< E
    int correction = 0;                                       ///< D
    int referenceSpindle = 1;                                 ///< SPC
    bool adaptiveFeed = false;         ///< G26 on (G25 off): adaptive feed control switched on
    double time = 0.0;                 ///< simulated seconds (moves and dwells)
    double lastEffectiveRadius = 0.0;  ///< RI of the last G32 (kept after G30)
};

inline constexpr double kMmPerInch = 25.4;
/// Millimetres per programmed length unit under `modal`: 25.4 under G70
/// (inch), 1 under G71. Programmed lengths and feeds are multiplied by it.
inline double millimetresPerUnit(const ModalState& modal) {
    return modal.g[kGroupUnits] == 70 ? kMmPerInch : 1.0;
}

/// `to = from` in 16-byte steps. The interpreter commits one modal state
/// per block; for a plain assignment of its ~400 bytes GCC emits `rep movsq`,
/// whose start-up cost was 8 % of an NC program restart's computing process.
inline void assignModalState(ModalState& to, const ModalState& from) {
    static_assert(std::is_trivially_copyable_v<ModalState>);
    constexpr std::size_t kSize = sizeof(ModalState);
    constexpr std::size_t kStep = 16;
    auto* out = reinterpret_cast<unsigned char*>(&to);
    const auto* in = reinterpret_cast<const unsigned char*>(&from);
#pragma GCC unroll 32
    for (std::size_t i = 0; i < kSize / kStep; ++i)
        std::memcpy(out + i * kStep, in + i * kStep, kStep);
    if constexpr (kSize % kStep != 0)
        std::memcpy(out + kSize - kSize % kStep, in + kSize - kSize % kStep, kSize % kStep);
}

/// One saved return point of BSR / JSR / BEV / JEV.
struct CallFrame {
    ProgramPtr program;
    std::uint32_t callBlock = 0;    ///< block index of the call
    std::uint32_t returnBlock = 0;  ///< block index to continue with after RTS
};

/// The interpreter's variables @0..@999 and which of them were written.
struct Variables {
    std::array<double, kVariableCount> values{};
    std::bitset<kVariableCount> written;
};

/// Where G77 (REPOS) brings axes and spindles back to: the commanded state
/// at the re-entry point (the target block of an NC program restart, seed
/// 000, 2.9). Set by the restart sequence; cleared by program end and control reset.
struct ReentryPoint {
    bool valid = false;
    std::array<double, kMaxAxes> machine{};                   ///< machine positions (mm, degrees)
    std::array<double, kSpindleSlots> spindleSpeed{};         ///< S per spindle
    std::array<std::int8_t, kSpindleSlots> rotaryAxisMode{};  ///< page 60 el. 1..3
    /// Tool compensation was in effect at the target (compensation.md
    /// TC-013): G77 brings the axes to `axes`, where they stood before the
    /// target block in an uninterrupted run (radius, cutting edge and length
    /// applied), while `machine` stays the programmed point.
    bool compensated = false;
    std::array<double, kMaxAxes> axes{};           ///< axis positions (compensated)
    std::array<double, kMaxAxes> lengthOffsets{};  ///< G48 offsets contained in `axes`
};

/// The complete state of one interpreter: copy it to snapshot a run, assign
/// it back with Interpreter::restoreState. No pointers into the interpreter.
struct InterpreterState {
    ModalState modal;
    /// Last M function of each group; index 1..16 (0 unused). Group 16 is
    /// "every M not in a configured group".
    std::array<int, 17> mGroups{};
    int lastQ = -1;  ///< last Q function (-1 = none since reset)
    Variables variables;
    double condition = 0.0;            ///< result of the last arithmetic (BEQ/BNE/BPL/BMI)
    ProgramPtr program;                ///< program being executed (nullptr = none selected)
    std::uint32_t block = 0;           ///< index of the next block to execute
    std::vector<CallFrame> callStack;  ///< saved return points, innermost last
    bool ended = false;                ///< the selected program reached its end
    ProgramPtr selected;               ///< program chosen with select(); program end returns to it
    ReentryPoint reentry;              ///< target of G77 (REPOS)
};

}  // namespace mtc::core
