#pragma once

#include <cstdint>
#include <memory>
#include <optional>

#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/removal/PartModel.h"
#include "cnc_core/removal/RemovalSink.h"

namespace mtc::core::removal {

/// What a material-removal simulation produced.
struct RemovalRunResult {
    std::optional<PartModel> part;  ///< the finished part (none: see diagnostics)
    DiagnosticList diagnostics;     ///< interpreter errors, budget, rapid cuts, the stock
    RemovalCounts counts;
    std::uint64_t blocks = 0;  ///< blocks interpreted
    bool complete = false;     ///< the program reached its end
};

/// Cuts the stock of `config` (its `stock`; GNE raw parts are not read) with
/// program `number` run from its first block to its end on a fresh
/// interpreter in check mode (a rejected block is reported and skipped),
/// as buildToolpath() runs it. The tools come from `tools` (nullptr: the
/// configuration's list). A stock the model cannot be made of (none, or more
/// cells than settings.maxCells) is an error diagnostic REMOVAL_STOCK and no
/// part. Bounded by `blockBudget`; nothing outside the result changes.
RemovalRunResult simulateRemoval(const ProcessConfig& config, const ProgramStore& programs,
                                 int number, const RemovalSettings& settings,
                                 std::shared_ptr<const ToolList> tools = nullptr,
                                 std::uint64_t blockBudget = 10'000'000);

}  // namespace mtc::core::removal
