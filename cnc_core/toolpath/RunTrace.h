#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>

#include "cnc_core/toolpath/ToolpathBuilder.h"

namespace mtc::core {

namespace motion {
class TrajectoryEngine;
}

/// How far the axes have come along one layer of a RunTrace: segments
/// [0, segments) are travelled, and `share` (0 ... 1) of segment `segments`.
struct TracedExtent {
    std::uint32_t segments = 0;
    double share = 0.0;
};

/// The backplot of a station (issue 19 §2, docs/decisions/toolpath.md
/// TP-016): the moves a program run has given the machine since its Start,
/// as toolpath geometry (the same tessellation as the toolpath view), and
/// how far the axes have travelled along them — the moves the machine has
/// finished and the share of the one it executes. The look-ahead's moves are
/// in the geometry before they are travelled; extent() says where the axes
/// are. No display code; the station feeds it, the view reads it.
class RunTrace {
  public:
    /// Most segments (both layers and the contour) a run keeps: beyond it
    /// the trace stops growing and truncated() says so (a program that loops
    /// for ever on the panel's machine must not eat the memory).
    static constexpr std::size_t kSegmentLimit = 4'000'000;

    explicit RunTrace(const ProcessAxes& axes);

    /// A new run of program `program` (Start, a restart accepted): forgets
    /// the last.
    void begin(int program);
    /// A move of the run, handed to the machine; `queued` is false for a
    /// move the machine did not queue (no length: it is done at once).
    void sent(const Motion& motion, bool queued);
    /// The machine moved on: the moves it no longer has queued are done, the
    /// front one is travelled to `engine`'s share of its path.
    void follow(const motion::TrajectoryEngine& engine);
    /// Control reset: the queued moves will not run; the trace keeps where
    /// the axes stopped and takes nothing more until begin().
    void cut();

    /// Every move of the run given to the machine (look-ahead included).
    const ToolpathGeometry& geometry() const { return builder_.geometry(); }
    /// Moves the axes have finished: moves [0, doneMoves()).
    std::size_t doneMoves() const { return done_; }
    /// The move the axes are on (doneMoves() while moving), or the last one
    /// they finished when they stand; -1 before the first.
    long currentMove() const;
    /// Share (0 ... 1) of move doneMoves() travelled (0 when standing).
    double share() const { return share_; }
    /// How far the axes have come in the scene (developed) layer.
    TracedExtent extent(bool developed) const;
    /// Grows with every change of the geometry or the extent; a new run
    /// changes run().
    std::uint64_t revision() const { return revision_; }
    std::uint64_t run() const { return run_; }
    /// The program whose run it is (0 before the first).
    int program() const { return program_; }
    /// The segment limit cut the trace short.
    bool truncated() const { return truncated_; }

  private:
    ToolpathBuilder builder_;
    /// Indices of the queued moves the machine has not finished, oldest first.
    std::deque<std::size_t> pending_;
    std::size_t done_ = 0;
    double share_ = 0.0;
    bool moving_ = false;  ///< the axes are on move done_
    bool cut_ = false;
    bool truncated_ = false;
    std::uint64_t revision_ = 0;
    std::uint64_t run_ = 0;
    int program_ = 0;
};

}  // namespace mtc::core
