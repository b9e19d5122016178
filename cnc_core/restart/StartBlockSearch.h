#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "cnc_core/interp/InterpreterState.h"
#include "cnc_core/language/Program.h"

namespace mtc::core {

/// A program level as the running program would have it (seed 000, 2.5):
/// calls (BSR, JSR, BEV, JEV) open one, JMP replaces all of them, branches
/// stay on theirs. The 10-level limit counts these.
struct ProgramLevel {
    ProgramPtr program;
    std::uint32_t entry = 0;      ///< block the level was entered at
    ProgramPtr caller;            ///< program of the call (level > 0)
    std::uint32_t callBlock = 0;  ///< block of the call in `caller`
};

/// The program levels of a target path up to a JMP: a JMP leaves every
/// level and starts a new segment in the program it leads to.
struct LevelSegment {
    std::vector<ProgramLevel> levels;  ///< level 0 first
    ProgramPtr jumpProgram;            ///< program of the JMP that ended it (null: last segment)
    std::uint32_t jumpBlock = 0;       ///< block of that JMP
};

/// A start block found before the target (seed 000, 2.4 and 5.1).
struct PrimaryStart {
    std::size_t segment = 0;  ///< segment of the start block
    int level = 0;            ///< program level of the start block in its segment
    ProgramPtr program;
    std::uint32_t block = 0;
    std::vector<CallFrame> frames;  ///< call stack in force at the start block
};

/// The last primary block of `program` in [first, end), if any.
using PrimaryLookup = std::function<std::optional<std::uint32_t>(
    const ProgramPtr& program, std::uint32_t first, std::uint32_t end)>;

/// The one rule for "the last primary block before the target" (restart.md
/// backwards from the block before the target on its level down to
/// the level's entry, then from each calling block (inclusive) outwards,
/// level by level; at the first level of a segment the search goes on from
/// the JMP that led there (inclusive) in the segment before, as the program
/// ran through it. std::nullopt: there is none. `lookup` answers one program
/// range (a linear scan or the screen's primary index).
std::optional<PrimaryStart> findLastPrimaryBlock(const std::vector<LevelSegment>& segments,
                                                 const ProgramPtr& targetProgram,
                                                 std::uint32_t targetBlock,
                                                 const PrimaryLookup& lookup);

/// A PrimaryLookup that scans the blocks of the range backwards.
std::optional<std::uint32_t> scanForPrimaryBlock(const ProgramPtr& program, std::uint32_t first,
                                                 std::uint32_t end);

}  // namespace mtc::core
