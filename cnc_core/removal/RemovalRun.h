#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/removal/PartModel.h"
#include "cnc_core/removal/ProgramStock.h"
#include "cnc_core/removal/RemovalSink.h"

namespace mtc::core::removal {

/// Where a removal run ends instead of the program end: before the target
/// block is interpreted (the part as the target finds it, an NC program
/// restart), at its `runs`-th arrival that `counts`.
struct RemovalStop {
    StopTarget target;  ///< program and block (its pass is not used)
    std::uint32_t runs = 1;
    /// Which arrivals count (the restart's call chain); empty: every one.
    std::function<bool(const InterpreterState&)> counts;
    /// Called once after the program is selected, before its first block
    /// (the variables and events a restart selection changes).
    std::function<void(Interpreter&)> prepare;
    /// The zero offsets the program is run with (nullptr: the configuration's).
    std::shared_ptr<const ZeroOffsetTable> zeroOffsets;
};

/// What a material-removal simulation produced.
struct RemovalRunResult {
    std::optional<PartModel> part;  ///< the finished part (none: see diagnostics)
    StockOrigin stock;              ///< the program's window or the configuration (TP-008)
    DiagnosticList diagnostics;     ///< interpreter errors, budget, rapid cuts, the stock
    RemovalCounts counts;
    std::uint64_t blocks = 0;  ///< blocks interpreted
    bool complete = false;     ///< the program reached its end (or the stop)
};

/// The blank a run of a program cuts: `stock` (programStock()) as a part
/// model at `settings`. Nullopt when the window cannot be the blank (its
/// REMOVAL_WINDOW errors) or the model cannot be made of it (none, more
/// cells than settings.maxCells: an error REMOVAL_STOCK at the window, or
/// without a place for the configuration's stock); both go to
/// `diagnostics` with the stock's warnings.
std::optional<PartModel> blankPart(const ProcessConfig& config, const ProgramStock& stock,
                                   const RemovalSettings& settings, DiagnosticList& diagnostics);

/// Cuts the stock of program `number` (programStock(): its WINDOW_01/02 in
/// machine coordinates, else `config`'s `stock`; a bad window is an error
/// REMOVAL_WINDOW and no part) with the program run from its first block to its end on a fresh
/// interpreter in check mode (a rejected block is reported and skipped),
/// as buildToolpath() runs it. The tools come from `tools` (nullptr: the
/// configuration's list). A stock the model cannot be made of (none, or more
/// cells than settings.maxCells) is an error diagnostic REMOVAL_STOCK and no
/// part. Bounded by `blockBudget`; nothing outside the result changes.
/// With `stop` the run ends before the stop's target block instead
/// (`complete` says it was reached; the program end first is a warning
/// REMOVAL_STOP_NOT_REACHED).
RemovalRunResult simulateRemoval(const ProcessConfig& config, const ProgramStore& programs,
                                 int number, const RemovalSettings& settings,
                                 std::shared_ptr<const ToolList> tools = nullptr,
                                 std::uint64_t blockBudget = 10'000'000,
                                 const RemovalStop* stop = nullptr);

/// The same with the program's stock already worked out (programStock() of
/// the same program, offsets and budget): for a caller that needs the stock
/// itself too (the toolpath view), so the run to the window is made once.
RemovalRunResult simulateRemoval(const ProcessConfig& config, const ProgramStore& programs,
                                 int number, const ProgramStock& stock,
                                 const RemovalSettings& settings,
                                 std::shared_ptr<const ToolList> tools = nullptr,
                                 std::uint64_t blockBudget = 10'000'000,
                                 const RemovalStop* stop = nullptr);

}  // namespace mtc::core::removal
