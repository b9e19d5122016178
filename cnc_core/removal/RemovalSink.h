#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "cnc_core/compensation/ToolData.h"
#include "cnc_core/interp/MachineSink.h"
#include "cnc_core/removal/PartModel.h"
#include "cnc_core/toolpath/ToolpathBuilder.h"

namespace mtc::core::removal {

/// What a removal run counted.
struct RemovalCounts {
    std::uint64_t moves = 0;             ///< moves the sink got
    std::uint64_t approachMoves = 0;     ///< the first move, from the power-on position: not cut
    std::uint64_t cuttingMoves = 0;      ///< moves that removed material
    std::uint64_t rapidCuts = 0;         ///< rapid (G0) moves that removed material
    std::uint64_t transformedMoves = 0;  ///< G31 / G32 moves not simulated (see RemovalSink)
    std::uint64_t developedMoves = 0;    ///< G32 moves swept over the jacket (cutting or not)
    std::uint64_t insideToolMoves = 0;   ///< lathe moves of inside (boring) tools: not simulated
};

/// One straight piece of the tool path as the part model sweeps it (scene
/// points of the nose centre / face centre).
struct ToolChord {
    std::array<double, 3> a{0, 0, 0};
    std::array<double, 3> b{0, 0, 0};
};

/// Turns a move into what the part model sweeps: the tool-centre chords of
/// the path the toolpath view draws and the cutter of the tool (the rules
/// below, RemovalSink). Shared by the cut and by the collision check of a
/// restart's way back (ReentryCollisions), so both sweep the same.
class ToolSweep {
  public:
    /// What became of a move.
    enum class Kind {
        Swept,        ///< chords() and cutter() hold it
        Developed,    ///< G32 on a turned part: jacketChords() and cutter() hold it
        Transformed,  ///< G31, G32 elsewhere: not simulated
        InsideTool,   ///< lathe, inside tool: not simulated
    };
    ToolSweep(const ProcessAxes& axes, const PartModel& part);

    /// The chords of `motion` with `tool` in working position.
    Kind sweep(const Motion& motion, const ToolData& tool);
    /// Takes a move into the path's memory (offsets) without sweeping it.
    void pass(const Motion& motion);
    /// Gives `motion` (a manual jog: machine axes only) the tool offsets of
    /// the move before it: the tool centre keeps its distance to the axes.
    void carryOffsets(Motion& motion) const;
    const std::vector<ToolChord>& chords() const { return chords_; }
    /// A G32 move's chords on the turned part's jacket (D-027).
    const std::vector<std::array<JacketPoint, 2>>& jacketChords() const { return jacketChords_; }
    const Cutter& cutter() const { return cutter_; }
    /// Scene axis (0 X, 1 Y, 2 Z) machine axis `axis` draws on, or -1.
    int sceneAxis(int axis) const { return path_.sceneAxis(axis); }

  private:
    using Position = std::array<double, kMaxAxes>;
    /// The developed layer's chords of G32 move `m` as jacketChords(); false
    /// when the move cannot be laid on the part's jacket (no turned part, or
    /// the plane's linear axis is not the part's axis).
    bool developedChords(const Motion& m, const Position& previousOffset);
    /// Tool offsets (Motion::toolOffset) of `m`; zero when not compensated.
    static Position offsetOf(const Motion& m);

    const PartModel& part_;
    ProcessAxes axes_;
    ToolpathBuilder path_;
    Position lastOffset_{};
    bool lastCompensated_ = false;
    std::vector<ToolChord> chords_;
    std::vector<std::array<JacketPoint, 2>> jacketChords_;
    Cutter cutter_;
};

/// The material-removal sink: takes the interpreter's moves, turns each into
/// the tool-centre path the toolpath view draws (a ToolpathBuilder with a
/// chordal tolerance of a quarter of the resolution: the same tool
/// compensation, arcs and helices) and sweeps the tool in working position
/// (radius from the tool list) along it through the part. A turning tool
/// (cutting edge orientation 1..8) outside G41/G42 is programmed by its
/// theoretical tip: its nose centre lies at - radius x edge vector from it
/// (compensation.md TC-010); its insert stands opposite the edge vector. A
/// tool without a cutting edge orientation on the lathe (driven end mill,
/// drill) stands radially: a flat tip of the tool's radius to either side.
/// The first move starts at the simulator's power-on position (machine
/// zero, no real place of the tool: on the lathe it lies on the spindle
/// axis): it is not cut. G32 moves on the lathe sweep the tool (a driven end
/// mill standing radially) over the turned part's jacket (D-027, made at the
/// first one). G31 moves, G32 moves elsewhere, and an inside tool's moves
/// on the lathe (orientation 1, 2, 6: the profile has no bores), are
/// counted, not cut.
class RemovalSink : public MachineSink {
  public:
    /// `part` must outlive the sink.
    RemovalSink(const ProcessAxes& axes, PartModel& part);

    /// Where the tool in working position comes from (the interpreter's tool
    /// list and modal state); without a source the tool has radius 0.
    void setToolSource(std::function<ToolData()> source) { toolSource_ = std::move(source); }

    void motion(const Motion& motion) override;
    void auxiliary(const AuxOutput&) override {}
    void dwell(const SourceLocation&, double) override {}
    void command(const MachineCommand&) override {}

    const RemovalCounts& counts() const { return counts_; }
    /// A warning per rapid move that cut (the first 20): program, block, line.
    const DiagnosticList& notes() const { return notes_; }

  private:
    /// Cuts the move's chords; counts what it removed.
    void cutChords(const Motion& motion);
    /// Cuts a G32 move's chords into the jacket (made at the first).
    void cutJacket(const Motion& motion);
    /// Counts a move that removed material (a rapid: a warning).
    void countCut(const Motion& motion);

    PartModel& part_;
    ToolSweep sweep_;
    std::function<ToolData()> toolSource_;
    RemovalCounts counts_;
    DiagnosticList notes_;
};

}  // namespace mtc::core::removal
