#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "cnc_core/interp/MachineCommand.h"
#include "cnc_core/language/Diagnostic.h"

/// Everything that leaves the interpreter goes through this interface (the
/// "canonical machining functions" idea of LinuxCNC, as an interface): a
/// recording sink for tests and the CLI, a toolpath sink for the view, the
/// simulated machine for the panel. Every call carries where it came from.
namespace mtc::core {

enum class MotionType { Rapid, Linear, ArcCW, ArcCCW };

/// The move type of interpolation G0, G1, G2 or G3 (`g` 0..3).
constexpr MotionType motionTypeOf(int g) {
    return g == 0   ? MotionType::Rapid
           : g == 1 ? MotionType::Linear
           : g == 2 ? MotionType::ArcCW
                    : MotionType::ArcCCW;
}

/// Most axes a process can have (the seeds allow 9 feed axes + 3 spindles).
inline constexpr int kMaxAxes = 12;

/// One programmed move. Positions are indexed like ProcessConfig::axes (the
/// machine axis order); rotary axes in degrees. `end` holds every axis
/// position after the move (programmed position per machine axis). Fixed
/// arrays, no allocation: a 1,000,000-block run sends a million of these.
struct Motion {
    SourceLocation where;
    MotionType type = MotionType::Linear;
    int axisCount = 0;
    std::array<double, kMaxAxes> start{};
    std::array<double, kMaxAxes> end{};
    int planeAxis1 = -1, planeAxis2 = -1;  ///< arcs: machine axis indices spanning the plane
    double center1 = 0.0, center2 = 0.0;   ///< arcs: centre in those two axes
    /// Arcs: one whole turn (closesCircle() of the programmed arc, D-016);
    /// the sweep of every receiver comes from arcSweep() with this flag.
    bool fullCircle = false;
    double feed = 0.0;             ///< mm/min (0 for rapid)
    int transformation = 30;       ///< 30 none, 31 facing, 32 lateral cylinder
    double effectiveRadius = 0.0;  ///< RI while G32 is active
    /// G31/G32: machine axis indices spanning the transformed plane (-1 otherwise).
    int transformAxis1 = -1, transformAxis2 = -1;
    std::uint32_t blockIndex = 0;  ///< index of the block in Program::blocks
    /// Tool compensation (docs/decisions/compensation.md): `start`, `end` and
    /// the centre are where the axes go. When `compensated`, `programmedEnd`
    /// holds the programmed end point and `end - toolOffset` the tool centre
    /// (cutter centre, nose centre of a turning tool); otherwise both are `end`.
    bool compensated = false;
    bool inserted = false;  ///< a corner element the control inserted (runtime program's arrow)
    std::array<double, kMaxAxes> programmedEnd{};
    std::array<double, kMaxAxes> toolOffset{};  ///< axis position minus tool centre (edge, length)
    /// Block transition in force (groups 10 / 11, docs/decisions/motion.md
    /// MOT-005): G9 exact stop, G7 corners not at rest (with G9 only).
    bool exactStop = false;
    bool blendCorners = false;
    /// Zero offset in force (seed 003, 3.5): G53..G59, and per machine axis
    /// the offset of its definition now (mm, degrees): workpiece coordinate =
    /// machine position - offset (docs/decisions/toolpath.md TP-019).
    int zeroOffset = 53;
    std::array<double, kMaxAxes> zeroOffsetValues{};
    /// The linear machine axis whose definition is X now, the one G15/G16
    /// apply to (-1: none), and whether its values are diameters (G16 in
    /// force): its workpiece coordinate is then 2 x (machine - offset).
    int radialAxis = -1;
    bool diameter = false;
};

/// Programmed end position of `axis` (the contour point, without any tool compensation).
inline double programmedEndOf(const Motion& m, int axis) {
    const auto a = static_cast<std::size_t>(axis);
    return m.compensated ? m.programmedEnd[a] : m.end[a];
}

/// Tool-centre end position of `axis` (cutter centre, nose centre).
inline double toolCentreOf(const Motion& m, int axis) {
    const auto a = static_cast<std::size_t>(axis);
    return m.compensated ? m.end[a] - m.toolOffset[a] : m.end[a];
}

/// An auxiliary function sent to the SPS (M, Q, S, T, E).
struct AuxOutput {
    SourceLocation where;
    char type = 'M';
    int spindle = 0;  ///< S: 0 main, 1..3
    double value = 0;
};

class MachineSink {
  public:
    virtual ~MachineSink() = default;
    virtual void motion(const Motion& motion) = 0;
    virtual void auxiliary(const AuxOutput& output) = 0;
    virtual void dwell(const SourceLocation& where, double seconds) = 0;
    /// A command the interpreter hands to the machine (AXD, MTP, TCH, GAX, ...).
    virtual void command(const MachineCommand& command) = 0;
};

/// Keeps everything in vectors: for tests and the CLI.
class RecordingSink : public MachineSink {
  public:
    void motion(const Motion& m) override { motions.push_back(m); }
    void auxiliary(const AuxOutput& a) override { aux.push_back(a); }
    void dwell(const SourceLocation& where, double seconds) override {
        dwells.push_back({where, seconds});
    }
    void command(const MachineCommand& c) override { commands.push_back(c); }

    struct Dwell {
        SourceLocation where;
        double seconds;
    };
    std::vector<Motion> motions;
    std::vector<AuxOutput> aux;
    std::vector<Dwell> dwells;
    std::vector<MachineCommand> commands;
};

/// Discards everything (computing process, --no-motion).
class NullSink : public MachineSink {
  public:
    void motion(const Motion&) override {}
    void auxiliary(const AuxOutput&) override {}
    void dwell(const SourceLocation&, double) override {}
    void command(const MachineCommand&) override {}
};

}  // namespace mtc::core
