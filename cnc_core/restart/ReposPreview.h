#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "cnc_core/compensation/ToolData.h"
#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/interp/InterpreterState.h"
#include "cnc_core/machine/MachineDataProvider.h"
#include "cnc_core/restart/RestartRoute.h"

namespace mtc::core {

/// One move of the preview as the machine would get it.
struct PreviewMove {
    Motion motion;
    ToolData tool;       ///< the tool in working position during the move
    bool repos = false;  ///< a move of REPOS (from the .REPOS label on), else of ADJUST
};

/// The way the axes will go from where they stand to the re-entry point, as
/// the rest of ADJUST and the REPOS subroutine command it (seed 000, 2.8,
/// 2.9; decisions TP-007): machine positions, nothing moved.
struct ReposPreview {
    /// Where the axes stand now, then the end of every move (G77 or other).
    std::vector<std::array<double, kMaxAxes>> corners;
    /// The block of each move (corners[i + 1]).
    std::vector<SourceLocation> blocks;
    /// Every move in full (moves[i] ends at corners[i + 1]).
    std::vector<PreviewMove> moves;
    /// REPOS returned to the target block (else the preview stopped early:
    /// an error, a program end, M00 or the block budget; see diagnostics).
    bool reachesTarget = false;
    DiagnosticList diagnostics;
};

/// What previewRepositioning starts from.
struct ReposPreviewStart {
    InterpreterState state;  ///< the station's interpreter state now
    InterpreterOptions options;
    StopTarget target;                    ///< the target block (the re-entry)
    std::vector<RouteFrame> targetChain;  ///< the call stack at the target
    bool beforeAdjust = false;            ///< at the target, ADJUST not started: begin at .ADJUST
    bool inRepos = false;                 ///< REPOS already runs: every move is a REPOS move
    /// The tool list and zero offsets the station's interpreter reads (not
    /// owned; nullptr: the machine configuration's).
    const ToolList* tools = nullptr;
    const ZeroOffsetTable* zeroOffsets = nullptr;
};

class RestartSequence;

/// The preview's start for `sequence` of the station whose interpreter is
/// `live`: from the target reached (beforeAdjust) to REPOS running, with the
/// live tool list and zero offsets; nullopt in the other phases.
std::optional<ReposPreviewStart> reposPreviewStart(const RestartSequence& sequence,
                                                   const Interpreter& live);

/// Interprets the remaining ADJUST / REPOS blocks from `start` on a private
/// interpreter whose sink only records (nothing of the station changes;
/// machine data are read from `data`, never written) until REPOS returns to
/// the target block, at most `budget` blocks. Q9500 (manual mode) does not
/// stop it: the preview assumes the operator jogs nothing.
ReposPreview previewRepositioning(const ProcessConfig& config, const ProgramStore& programs,
                                  const MachineDataProvider& data, const ReposPreviewStart& start,
                                  std::uint64_t budget = 10'000);

}  // namespace mtc::core
