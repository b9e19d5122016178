#pragma once

#include <array>
#include <cstddef>

#include "cnc_core/interp/MachineSink.h"
#include "cnc_core/machine/ProcessAxes.h"
#include "cnc_core/toolpath/ToolpathGeometry.h"

namespace mtc::core {

/// Settings of the toolpath geometry.
struct ToolpathSettings {
    /// Chordal tolerance (mm): no chord of a tessellated arc, and no chord of
    /// a G32 move wrapped onto its cylinder, is farther than this from the
    /// true path. Arcs under G32 split it between the arc and the wrap.
    double tolerance = 0.01;
    /// The path stops growing at this many segments (both layers together);
    /// ToolpathGeometry::truncated then says so.
    std::size_t segmentLimit = 20'000'000;
};

/// The toolpath sink: turns the interpreter's moves into ToolpathGeometry
/// (no display dependency). Rapid, feed and arc moves keep their kind and
/// their program, block and line. Scene coordinates are machine positions of
/// the linear axes whose base definition is X, Y or Z; other axes (rotary
/// axes outside G31/G32, U/V/W axes, spindles) do not move the picture.
/// G31 moves are drawn in their fictitious cartesian plane; G32 moves in the
/// developed plane (developed layer) and wrapped onto the cylinder of radius
/// RI around the linear plane axis (scene layer). Under tool compensation the
/// layers draw the tool centre, the contour layers the programmed contour of
/// the compensated moves. Decisions: docs/decisions/toolpath.md.
class ToolpathBuilder : public MachineSink {
  public:
    ToolpathBuilder(const ProcessAxes& axes, ToolpathSettings settings = {});

    /// Adds one move (segments to the scene layer, G32 moves also to the
    /// developed layer). Never fails; beyond the segment limit only the move
    /// record is kept and the geometry is marked truncated.
    void motion(const Motion& motion) override;
    void auxiliary(const AuxOutput&) override {}
    void dwell(const SourceLocation&, double) override {}
    void command(const MachineCommand&) override {}

    const ToolpathGeometry& geometry() const { return geometry_; }
    /// Hands the geometry over (the builder starts empty again).
    ToolpathGeometry take();
    /// Empties the geometry but keeps its memory, and the offsets of the last
    /// move: for a sink that consumes the path move by move (material removal).
    void clearGeometry() { geometry_.clear(); }
    /// Scene point of machine positions without transformation (re-entry
    /// point, actual position).
    std::array<double, 3> scenePoint(const std::array<double, kMaxAxes>& machine) const;
    /// Scene axis (0 X, 1 Y, 2 Z) machine axis `axis` draws on, or -1.
    int sceneAxis(int axis) const;
    /// Machine axis drawn on scene axis `scene` (0..2), or -1 (no such axis).
    int machineAxisOfScene(int scene) const {
        return scene >= 0 && scene < 3 ? machineAxisOfScene_[static_cast<std::size_t>(scene)] : -1;
    }

  private:
    using Position = std::array<double, kMaxAxes>;
    struct Transform;
    Transform transformOf(const Motion& m) const;
    void toPlaneSpace(const Transform& t, const Position& machine, Position& plane) const;
    bool scenePointOf(const Transform& t, const Position& plane, std::array<double, 3>& p) const;
    enum class Layers { Scene, Developed, Both };
    /// One chord from `from` to `to` (plane space) into the layers asked for
    /// (the developed layer takes G32 moves only).
    void addChord(const Transform& t, const Position& from, const Position& to, Layers layers);
    void addLine(const Transform& t, const Position& start, const Position& end);
    /// `c1`, `c2`: the centre in machine positions (rotary axes in degrees).
    void addArc(const Motion& m, double c1, double c2, const Transform& t, const Position& start,
                const Position& end);
    /// The programmed contour of a compensated move into the contour layers.
    void addContour(const Motion& m, const Transform& t);
    int wrapChords(const Transform& t, double circumferentialTravel, double tolerance) const;
    /// The frames entry of the motion's zero offset (added when new, TP-019).
    std::uint16_t frameIndex(const Motion& m);

    ProcessAxes axes_;
    ToolpathSettings settings_;
    std::array<int, 3> machineAxisOfScene_{-1, -1, -1};
    ToolpathGeometry geometry_;
    bool contourPass_ = false;   ///< addChord draws into the contour layers
    Position lastOffset_{};      ///< tool offset (Motion::toolOffset) of the last move
    Position lastProgrammed_{};  ///< programmed end point of the last move
};

}  // namespace mtc::core
