#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "cnc_core/removal/ProgramStock.h"
#include "cnc_core/removal/RemovalSink.h"

namespace mtc::core {
namespace motion {
class TrajectoryEngine;
}

namespace removal {

/// The part a station cuts while its program runs (issue 19 §3, docs/
/// decisions/toolpath.md TP-027): the run's blank, swept by the tool in
/// working position as far as the axes have really travelled — a move is
/// swept when the interpreter hands it to the machine (the tool of that
/// moment, the same ToolSweep as simulateRemoval), and cut piece by piece
/// as the machine executes it. A run to its end leaves the part
/// simulateRemoval() makes of the same program, tools and offsets. No
/// display code; the station feeds it, the view reads part().
class LiveCut {
  public:
    explicit LiveCut(const ProcessAxes& axes);

    /// A new run of program `program` from its first block: its blank
    /// (programStock() with `zeroOffsets`, blankPart()) at the finest
    /// resolution within kViewCells cells. Forgets the last run's part.
    void begin(const ProcessConfig& config, const ProgramStore& programs, int program,
               std::shared_ptr<const ZeroOffsetTable> zeroOffsets);
    /// The same on `blank` (nullopt: this run cuts nothing, `problems` say why).
    void begin(int program, std::optional<PartModel> blank, DiagnosticList problems);
    /// A restart's run of program `program` on `part`, the part at its
    /// target block: every move is cut, the first too (ADJUST starts where
    /// the axes are, a real place on the part).
    void beginAt(int program, PartModel part);
    /// The run began at a restart's target (beginAt).
    bool fromRestart() const { return fromRestart_; }
    /// Moves outside a program run (an MDI entry, a manual jog) cut on the
    /// part the last run left (TP-028): from where the axes stand, so the
    /// first is cut too. False when there is no part to cut.
    bool resume();
    /// Manual or MDI moves have cut on the part since the run (resume()).
    bool cutOnByHand() const { return byHand_; }
    /// A manual jog handed to the machine: the machine axes move, the tool
    /// centre keeps its distance to them from the moves before (length,
    /// cutting edge), since a jog changes no tool data.
    void sentJog(const Motion& motion);
    /// The machine dropped its queued moves at rest (a released continuous
    /// jog): they end where follow() last cut them.
    void dropPending() { pending_.clear(); }
    /// No part: nothing is cut until the next begin() (a run whose blank is
    /// not known, e.g. a restart's).
    void clear() { begin(0, std::nullopt, {}); }
    /// Where the tool in working position comes from when a move is sent.
    void setToolSource(std::function<ToolData()> source) { toolSource_ = std::move(source); }

    /// A move of the run handed to the machine; `queued` false: the machine
    /// did not queue it (no length). The run's first move comes from
    /// wherever the axes stood at Start: the approach, not cut (as
    /// RemovalSink does with the power-on position).
    void sent(const Motion& motion, bool queued);
    /// The machine moved on: cuts what the axes travelled since the last look.
    void follow(const motion::TrajectoryEngine& engine);
    /// Control reset: the queued moves will not run; the part stays as cut.
    void stop();

    /// The part as cut so far (nullptr: none this run, see problems()).
    const PartModel* part() const { return part_ ? &*part_ : nullptr; }
    /// Why the run has no part (REMOVAL_WINDOW, REMOVAL_STOCK errors) and
    /// what its blank leaves out (warnings).
    const DiagnosticList& problems() const { return problems_; }
    /// The program of the run (0 before the first).
    int program() const { return program_; }
    /// Grows with every change of the part; a new run changes run().
    std::uint64_t revision() const { return revision_; }
    std::uint64_t run() const { return run_; }
    /// Moves of the run the machine still has to finish (their sweeps are kept).
    std::size_t pendingMoves() const { return pending_.size(); }

  private:
    /// A queued move: its chords (none when it is not cut) and how far along
    /// them the tool has cut.
    struct PendingMove {
        /// Scene chords, or on the jacket (G32, D-027) (angle, axial, face)
        /// of each JacketPoint: both are cut in pieces along straight lines.
        std::vector<ToolChord> chords;
        bool onJacket = false;
        Cutter cutter;
        std::vector<double> ends;           ///< path length at the end of each chord
        std::size_t chord = 0;              ///< the chord the cut has reached
        std::array<double, 3> at{0, 0, 0};  ///< where on it
    };
    /// The sweep of a move that is cut (ToolSweep::sweep's result).
    void takeSweep(const Motion& motion, PendingMove& move);
    /// Cuts `move` from where its cut stands to `share` (0 ... 1) of its length.
    void cutTo(PendingMove& move, double share);
    /// Cuts one straight piece of `move`.
    bool cutPiece(const PendingMove& move, const std::array<double, 3>& from,
                  const std::array<double, 3>& to);

    ProcessAxes axes_;
    std::optional<PartModel> part_;
    std::optional<ToolSweep> sweep_;
    std::function<ToolData()> toolSource_;
    std::deque<PendingMove> pending_;
    std::uint64_t moves_ = 0;  ///< moves sent this run
    bool stopped_ = true;
    bool fromRestart_ = false;
    bool byHand_ = false;  ///< resume()d
    DiagnosticList problems_;
    int program_ = 0;
    std::uint64_t revision_ = 0;
    std::uint64_t run_ = 0;
};

}  // namespace removal
}  // namespace mtc::core
