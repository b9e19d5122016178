#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "cnc_core/removal/PartModel.h"
#include "cnc_core/restart/ReposPreview.h"
#include "cnc_core/restart/RestartRoute.h"
#include "cnc_core/restart/RestartSelection.h"

namespace mtc::core {
class RestartSequence;
}

namespace mtc::core::removal {

/// A move of ADJUST or REPOS that meets the part as the target block finds
/// it (docs/DECISIONS.md D-021): a feed move that would cut more than the
/// tolerance, or a rapid that comes within the tolerance of the material.
struct ReentryCollision {
    bool repos = false;                       ///< a REPOS move, else an ADJUST move
    bool rapid = false;                       ///< a G0 that touches (else a feed move that cuts)
    SourceLocation where;                     ///< the block of the move
    std::size_t move = 0;                     ///< index into the preview's moves
    std::array<double, kMaxAxes> position{};  ///< machine positions at the first touch
    std::array<double, 3> scene{0, 0, 0};     ///< the tool centre there (scene point)
};

/// The outcome of checkReentry.
struct ReentryCheck {
    bool checked = false;  ///< the part at the target was made and every move checked
    std::vector<ReentryCollision> collisions;
    DiagnosticList diagnostics;  ///< why not checked (REMOVAL_STOCK, ...), removal notes
    double removedVolume = 0.0;  ///< mm^3 cut before the target block
    double resolution = 0.0;     ///< mm, of the part model
    double tolerance = 0.0;      ///< mm, half the resolution
    std::uint64_t blocks = 0;    ///< blocks interpreted up to the target
    std::size_t moves = 0;       ///< ADJUST / REPOS moves checked
    /// The part the moves were checked against (set when checked).
    std::shared_ptr<const PartModel> partAtTarget;
};

/// What the check reads.
struct ReentryCheckInput {
    const ProcessConfig* config = nullptr;
    const ProgramStore* programs = nullptr;
    const RestartSelection* selection = nullptr;  ///< main program, runs, variable/event changes
    const RestartRoute* route = nullptr;          ///< target program and call chain
    const ReposPreview* preview = nullptr;        ///< the ADJUST / REPOS moves
    std::shared_ptr<const ToolList> tools;        ///< nullptr: the configuration's
    std::shared_ptr<const ZeroOffsetTable> zeroOffsets;
    RemovalSettings settings;
    std::uint64_t blockBudget = 10'000'000;  ///< for the run up to the target
};

/// Cuts the stock with the selected program from its first block up to,
/// not including, the target block at its selected arrival (simulateRemoval
/// with a RemovalStop), then checks every move of the preview against that
/// part without changing it. Work: the run to the target, plus per move the
/// cells its sweep covers and at most kMaxBisections sub-sweeps of the first
/// chord that touches (the touch point within a quarter of the resolution).
ReentryCheck checkReentry(const ReentryCheckInput& input);

/// Halvings of a chord to find where it first touches: enough to come
/// within a quarter of the finest resolution from any chord a scene point
/// can hold (the toolpath's vertices are floats, below 3.4e38 mm).
inline constexpr int kMaxBisections = 160;

/// checkReentry for the restart of a station: the preview from
/// reposPreviewStart(sequence, live) (what the toolpath view draws and the
/// machine will run), the selection and route of its computing process, the
/// live tool list and zero offsets. Nullopt when the restart is not between
/// the target reached and the re-entry.
std::optional<ReentryCheck> checkRestartReentry(const RestartSequence& sequence,
                                                const Interpreter& live,
                                                const ProgramStore& programs,
                                                const RemovalSettings& settings = {});

}  // namespace mtc::core::removal
