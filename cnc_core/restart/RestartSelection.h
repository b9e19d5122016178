#pragma once

#include <cstdint>
#include <map>
#include <vector>

namespace mtc::core {

/// A block of a program of the process: program number and block index
/// (index into Program::blocks).
struct BlockRef {
    int program = 0;
    std::uint32_t block = 0;

    bool operator==(const BlockRef& other) const {
        return program == other.program && block == other.block;
    }
};

/// An event of the event table ("p:e" in BES/BER/BEV/JEV).
struct EventRef {
    int process = 0;
    int event = 0;
    bool operator<(const EventRef& other) const {
        return process != other.process ? process < other.process : event < other.event;
    }
};

/// What the operator chose on the NC program restart screen (seed 000, ch. 2),
/// handed from the search pointer (screen / CLI target path) to the computing
/// process. Contract between cnc_core/restart/SearchPointer (which builds and
/// validates it) and cnc_core/restart/ComputingProcess (which runs it).
struct RestartSelection {
    int process = 0;      ///< process number (not station slot)
    int mainProgram = 0;  ///< the selected program the restart runs in
    /// Blocks whose jump or call <Plane+> followed, outermost first (at most
    /// 9: the target may be on the 10th level, seed 000, 2.5).
    std::vector<BlockRef> path;
    BlockRef target;               ///< the target block (not interpreted)
    std::uint32_t runs = 1;        ///< number of runs 1..65536 (seed 000, 2.6)
    bool fromLastPrimary = false;  ///< start at the last ':' block before the target
    /// Variables the operator changed in the JMP/JSR variable window (@n -> value).
    std::map<int, double> variableChanges;
    /// Events the operator changed in the BES/BER/BEV/JEV event window.
    std::map<EventRef, bool> eventChanges;
};

/// Number of runs the operator may enter (seed 000, 2.6).
inline constexpr std::uint32_t kMinRuns = 1;
inline constexpr std::uint32_t kMaxRuns = 65536;
/// Deepest level a target or start block may be on (seed 000, 2.5).
inline constexpr int kMaxSearchLevels = 10;

}  // namespace mtc::core
