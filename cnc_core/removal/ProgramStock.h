#pragma once

// The stock a program run cuts (docs/decisions/toolpath.md TP-008): the
// program's GNE drawing window WINDOW_01 / WINDOW_02 (docs/GNE-SYNTAX.md,
// the blank in workpiece coordinates) converted into machine coordinates
// with the zero offset in force at the window, or else the machine
// configuration's stock.

#include <cstdint>
#include <memory>
#include <string>

#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/toolpath/Stock.h"

namespace mtc::core::removal {

/// Where a run's stock came from.
struct StockOrigin {
    bool fromWindow = false;  ///< the program's WINDOW_0x (else the configuration's stock)
    std::string keyword;      ///< "WINDOW_01" / "WINDOW_02"
    SourceLocation where;     ///< the window's program, block and line
    int zeroOffset = 53;      ///< G53..G59 in force at the window
    /// A turning window's blank from the first RAW contour of the turning
    /// plane after it (TP-021): its number and CONT line; 0 = the whole bar.
    int rawContour = 0;
    std::uint32_t rawLine = 0;
};

/// A program's stock and what was wrong with its window.
struct ProgramStock {
    Stock stock;  ///< scene (machine) coordinates; Shape::None when there is none
    StockOrigin origin;
    /// REMOVAL_WINDOW errors: the window cannot be the stock (then `stock`
    /// is none: nothing is cut rather than the wrong blank); warnings
    /// REMOVAL_WINDOW_SIMPLIFIED: what of a usable window the part model
    /// leaves out.
    DiagnosticList diagnostics;
};

/// The stock of program `number` of `config`: its first WINDOW_01/02 when it
/// has one — a block of the program itself as the GNE writes it, or the
/// comment `;WINDOW_0x (...)` the compiler turns it into — else the
/// configuration's. The window's values are read as the GNE reads them; the
/// zero offset at the window comes from a check run of the program up to
/// the first block at or after the window's line (at most `blockBudget`
/// blocks), with `zeroOffsets` (nullptr: the configuration's).
ProgramStock programStock(const ProcessConfig& config, const ProgramStore& programs, int number,
                          std::shared_ptr<const ZeroOffsetTable> zeroOffsets = nullptr,
                          std::uint64_t blockBudget = 1'000'000);

}  // namespace mtc::core::removal
