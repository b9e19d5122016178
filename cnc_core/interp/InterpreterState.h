#pragma once

#include <array>
#include <bitset>
#include <cstddef>
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
/// Member order: see assignModalState() (work and machine on 16-byte
/// boundaries, feed and time last).
struct ModalState {
    GGroupValues g{};
    PlaneSelection plane;
    Transformation transformation;
    /// Programmed (workpiece) coordinates per machine axis in mm (degrees for
    /// rotary axes outside a transformation; plane coordinates in mm for the
    /// axes a transformation maps).
    alignas(16) std::array<double, kMaxAxes> work{};
    /// Commanded machine positions (zero offsets applied, transformation
    /// applied): mm for linear axes, degrees for rotary axes.
    alignas(16) std::array<double, kMaxAxes> machine{};
    std::array<double, kSpindleSlots> spindleSpeed{};         ///< last S per spindle
    std::array<double, kSpindleSlots> spindleLimit{};         ///< G92 S limits
    std::array<std::int8_t, kSpindleSlots> rotaryAxisMode{};  ///< page 60 el. 1..3
    std::array<int, kToolSpindles> toolSpindle{};             ///< page 60 el. 5..8
    int tool = 0;                                             ///< T
    int edge = 0;                                             ///< E
    int correction = 0;                                       ///< D
    int referenceSpindle = 1;                                 ///< SPC
    bool adaptiveFeed = false;         ///< G26 on (G25 off): adaptive feed control switched on
    double lastEffectiveRadius = 0.0;  ///< RI of the last G32 (kept after G30)
    double feed = 0.0;                 ///< F in mm/min (G94) or mm/rev (G95), metric
    double time = 0.0;                 ///< simulated seconds (moves and dwells)
};

inline constexpr double kMmPerInch = 25.4;
/// Millimetres per programmed length unit under `modal`: 25.4 under G70
/// (inch), 1 under G71. Programmed lengths and feeds are multiplied by it.
inline double millimetresPerUnit(const ModalState& modal) {
    return modal.g[kGroupUnits] == 70 ? kMmPerInch : 1.0;
}

/// Copies `Size` bytes from `from` to `to` in unrolled `Step`-byte moves: for
/// a plain assignment of a few hundred bytes GCC emits `rep movs`, whose
/// start-up cost was 8 % of an NC program restart's computing process.
template <std::size_t Step, std::size_t Size>
[[gnu::always_inline]] inline void copyInSteps(void* to, const void* from) {
    static_assert(Size % Step == 0, "whole steps");
    auto* out = static_cast<unsigned char*>(to);
    const auto* in = static_cast<const unsigned char*>(from);
#pragma GCC unroll 32
    for (std::size_t i = 0; i < Size / Step; ++i)
        std::memcpy(out + i * Step, in + i * Step, Step);
}

/// Copies `Size` bytes from `from` to `to` in 8-byte moves, each through a
/// general register: the compiler would otherwise join two of them into one
/// 16-byte move (which assignModalState() must not have).
template <std::size_t Size>
[[gnu::always_inline]] inline void copyInEightByteMoves(void* to, const void* from) {
    static_assert(Size % 8 == 0, "whole moves");
    auto* out = static_cast<unsigned char*>(to);
    const auto* in = static_cast<const unsigned char*>(from);
    for (std::size_t i = 0; i < Size / 8; ++i) {
        std::uint64_t word = 0;
        std::memcpy(&word, in + i * 8, 8);
        asm("" : "+r"(word));  // no code: keeps the move 8 bytes wide
        std::memcpy(out + i * 8, &word, 8);
    }
}

/// `to = from` (the per-block commit), laid out for the CPU's store
/// forwarding: a load is served by a store still on its way to the cache
/// only when that one store covers it; a 16-byte load over a fresh 8-byte
/// store (or over two 16-byte stores) waits until the stores have reached
/// the cache (I-026).
///  - 16-byte moves up to `feed`; `work` and `machine` lie on 16-byte
///    boundaries, so that a copy of the committed machine positions (the
///    move's end) reads each 16 bytes from one store of this copy;
///  - `feed` and `time` last, in 8-byte moves: the planner writes them
///    (8-byte stores) just before the commit copies the state.
[[gnu::always_inline]] inline void assignModalState(ModalState& to, const ModalState& from) {
    static_assert(std::is_trivially_copyable_v<ModalState> &&
                  std::is_standard_layout_v<ModalState>);
    constexpr std::size_t kSize = sizeof(ModalState);
    static_assert(
        offsetof(ModalState, time) == kSize - 8 && offsetof(ModalState, feed) == kSize - 16,
        "feed and time are the last members");
    static_assert(offsetof(ModalState, work) % 16 == 0 && offsetof(ModalState, machine) % 16 == 0,
                  "positions on 16-byte boundaries");
    constexpr std::size_t kSixteens = offsetof(ModalState, feed) / 16 * 16;
    auto* out = reinterpret_cast<unsigned char*>(&to);
    const auto* in = reinterpret_cast<const unsigned char*>(&from);
    copyInSteps<16, kSixteens>(out, in);
    copyInEightByteMoves<kSize - kSixteens>(out + kSixteens, in + kSixteens);
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
