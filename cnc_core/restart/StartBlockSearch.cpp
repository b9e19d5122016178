#include "cnc_core/restart/StartBlockSearch.h"

#include <algorithm>

namespace mtc::core {

std::optional<std::uint32_t> scanForPrimaryBlock(const ProgramPtr& program, std::uint32_t first,
                                                 std::uint32_t end) {
    if (!program) return std::nullopt;
    end = std::min<std::uint32_t>(end, static_cast<std::uint32_t>(program->blocks.size()));
    for (std::uint32_t b = end; b-- > first;)
        if (program->blocks[b].flags & kBlockPrimary) return b;
    return std::nullopt;
}

std::optional<PrimaryStart> findLastPrimaryBlock(const std::vector<LevelSegment>& segments,
                                                 const ProgramPtr& targetProgram,
                                                 std::uint32_t targetBlock,
                                                 const PrimaryLookup& lookup) {
    ProgramPtr position = targetProgram;
    std::uint32_t end = targetBlock;  // exclusive: the target itself is not a start block
    for (std::size_t s = segments.size(); s-- > 0;) {
        const std::vector<ProgramLevel>& levels = segments[s].levels;
        for (std::size_t k = levels.size(); k-- > 0;) {
            const std::uint32_t lower = position == levels[k].program ? levels[k].entry : 0;
            if (end > lower) {
                if (const auto found = lookup(position, lower, end)) {
                    PrimaryStart start{s, static_cast<int>(k), position, *found, {}};
                    for (std::size_t j = 1; j <= k; ++j)
                        start.frames.push_back(
                            {levels[j].caller, levels[j].callBlock, levels[j].callBlock + 1});
                    return start;
                }
            }
            if (k == 0) break;
            position = levels[k].caller;
            end = levels[k].callBlock + 1;  // a primary block may itself be the call
        }
        if (s == 0) break;
        position = segments[s - 1].jumpProgram;  // before the JMP, the JMP block included
        end = segments[s - 1].jumpBlock + 1;
    }
    return std::nullopt;
}

}  // namespace mtc::core
