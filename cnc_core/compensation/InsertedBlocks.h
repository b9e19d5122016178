#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "cnc_core/language/Diagnostic.h"
#include "cnc_core/machine/MachineConfig.h"
#include "cnc_core/machine/ZeroOffsetTable.h"
#include "cnc_core/program/ProgramStore.h"
#include "cnc_core/tooldata/ToolList.h"

namespace mtc::core {

/// A block the control inserts into the runtime program while it runs (seed
/// 001 ch. 1: "during tool path compensation, the CPU inserts additional
/// intermediate blocks", shown with an arrow): a corner element of tool
/// radius compensation, after the block before the corner.
struct InsertedBlock {
    int program = 0;
    std::uint32_t afterBlock = 0;  ///< index into Program::blocks of the block it follows
    std::string text;              ///< "G2 X12.5 Y7 I10 J5" in the program's coordinates
};

struct InsertedBlocks {
    std::vector<InsertedBlock> blocks;  ///< in the order they were inserted
    DiagnosticList diagnostics;         ///< what the run said (check mode), the first 100
};

/// Runs program `number` of `config`'s process in check mode, without a
/// machine (as the toolpath does), and collects the elements tool
/// compensation inserts, each block's on its first execution. Nothing
/// outside the result changes; bounded by `blockBudget`.
/// `tools` / `zeroOffsets`: the process's tool list and zero offsets (nullptr:
/// the configuration's).
InsertedBlocks insertedBlocks(const ProcessConfig& config, const ProgramStore& programs, int number,
                              std::uint64_t blockBudget = 2'000'000,
                              std::shared_ptr<const ToolList> tools = nullptr,
                              std::shared_ptr<const ZeroOffsetTable> zeroOffsets = nullptr);

/// True when the program (or one it may call) can use radius compensation:
/// it has a G41 or G42 word (a cheap check before insertedBlocks()).
bool usesRadiusCompensation(const Program& program);

}  // namespace mtc::core
