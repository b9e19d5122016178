#pragma once

#include <cstdint>

#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/toolpath/ToolpathBuilder.h"

namespace mtc::core {

/// What a toolpath run produced: the geometry and what the interpreter said.
struct ToolpathRunResult {
    ToolpathGeometry geometry;
    DiagnosticList diagnostics;  ///< errors of rejected blocks, the budget, ...
    std::uint64_t blocks = 0;    ///< blocks interpreted
    bool complete = false;       ///< the program reached its end
};

/// Runs `interpreter` (a program selected, check mode) in chunks until the
/// program ends or `blockBudget` blocks were interpreted; the first 100
/// diagnostics go to `diagnostics`, the blocks to `blocks`. True when the
/// program reached its end. The loop of every whole-program simulation
/// (toolpath, material removal).
bool runToProgramEnd(Interpreter& interpreter, std::uint64_t blockBudget,
                     DiagnosticList& diagnostics, std::uint64_t& blocks);

/// Interprets program `number` of `config`'s process from its first block to
/// its end on a fresh interpreter (check mode: a rejected block is reported
/// and skipped, M00/M01 go on) and collects its moves with a ToolpathBuilder.
/// Bounded by `blockBudget`; nothing outside the result changes.
ToolpathRunResult buildToolpath(const ProcessConfig& config, const ProgramStore& programs,
                                int number, const ToolpathSettings& settings = {},
                                std::uint64_t blockBudget = 2'000'000);

}  // namespace mtc::core
