#pragma once

#include <array>
#include <cstdint>

#include "cnc_core/compensation/CompensationFrame.h"
#include "cnc_core/compensation/OutputQueue.h"
#include "cnc_core/compensation/RadiusCompensation.h"
#include "cnc_core/interp/BlockContext.h"
#include "cnc_core/interp/InterpreterState.h"
#include "cnc_core/interp/ModalGroups.h"
#include "cnc_core/machine/MachineConfig.h"
#include "cnc_core/machine/ProcessAxes.h"

namespace mtc::core {

/// What tool compensation needs of one checked block.
struct CompensationBlock {
    const ModalState& current;  ///< state before the block
    const ModalState& next;     ///< state after the block
    bool hasMotion = false;
    MotionType type = MotionType::Linear;
    std::uint32_t programmedAxes = 0;     ///< axis words of the block (mask of machine axes)
    bool machineMove = false;             ///< G74 / G75 / G77: the axes go to machine positions
    double centre1 = 0.0, centre2 = 0.0;  ///< arcs: centre in plane coordinates
    bool fullCircle = false;              ///< arcs: one whole turn
    /// G77 (REPOS): the re-entry point the axes go to (TC-013); else nullptr.
    const ReentryPoint* reentry = nullptr;
};

/// Axis positions with tool compensation applied (tool reference: radius,
/// cutting edge and length), and the G48 length offsets they contain.
struct CompensatedPosition {
    std::array<double, kMaxAxes> axes{};
    std::array<double, kMaxAxes> lengthOffsets{};
    bool compensated = false;  ///< the stage followed the axes (else `axes` = programmed)
    /// The block does not move in the plane while an element is held: that
    /// element ends at its perpendicular, as at a programmed stop (TC-013).
    bool interrupted = false;
};

/// The tool compensation stage between the interpreter and the machine
/// (docs/decisions/compensation.md): radius compensation G40/G41/G42 of the
/// working plane with the runtime program's inserted corner elements, the
/// cutting edge position of turning tools, and length compensation G47/G48.
/// The interpreter hands it every move (programmed) and every other output
/// (through output()); it sends the compensated moves, holding one move back
/// while compensation needs the next one, with everything after it in order.
/// Like the interpreter: plan() checks a block without changing anything,
/// the commit calls (beginOutputs, motion, endBlock) carry it out.
class ToolCompensation {
  public:
    /// Blocks without motion in the plane the look-ahead goes through while a
    /// move is held; beyond that the held move ends at its perpendicular.
    static constexpr int kLookAheadBlocks = 10;

    ToolCompensation(MachineSink& downstream, const ProcessConfig& config, const ProcessAxes& axes);

    /// The sink for everything but the moves (S, T, M, Q, dwells, commands).
    MachineSink& output() { return queue_; }
    /// Reads radius, lengths and edge orientation from `tools` (the process's
    /// tool list; it must outlive the stage); nullptr = the configuration's.
    void useTools(const ToolList* tools) { tools_ = tools ? tools : &configTools_; }

    /// Whether the block needs the stage (cheap; otherwise plan() is skipped
    /// and the move passes unchanged).
    bool involved(const ModalState& current, const ModalState& next) const {
        return tracking_ || current.g[kGroupToolPath] != 40 || next.g[kGroupToolPath] != 40 ||
               next.g[kGroupToolLength] == 48;
    }
    /// Plan stage: false, with the diagnostic at the block the tool cannot
    /// follow, when the compensated path is impossible. Changes nothing.
    bool plan(const BlockContext& context, const CompensationBlock& block);

    /// Commit stage, before the block's outputs: what a change of the
    /// coordinate frame releases (the held move ends at its perpendicular).
    /// `output` false: positions are followed, nothing is sent.
    void beginOutputs(bool output);
    /// Commit stage: the block's move (programmed positions in `motion`).
    /// `output` false: positions are followed, nothing is sent. Inline: the
    /// usual move (the stage not tracking) passes with no call of its own.
    void motion(Motion& motion, bool output) {
        if (planned_.valid) return plannedMotion(motion, output);
        ++released_;  // not tracking: the move goes as programmed
        if (output) queue_.motion(motion);
    }
    /// Commit stage, after the block's outputs: look-ahead count; a
    /// programmed stop (`stopping`) ends the held move at its perpendicular.
    /// False (diagnostic) when that tool path crosses an earlier one.
    bool endBlock(bool stopping, DiagnosticList& diagnostics);
    /// Program end (G40 and G47 by reset): the held move ends at its
    /// perpendicular, the tool stays where it is. False (diagnostic into
    /// `diagnostics` when given) when that tool path crosses an earlier one.
    bool programEnd(DiagnosticList* diagnostics);
    /// Control reset: what is held is dropped (the machine never got it).
    void controlReset();
    /// The interpreter state was replaced (restart, restored snapshot): the
    /// stage starts again from its commanded positions.
    void restart();

    /// A move is held back (its end waits for the next block).
    bool holding() const { return engine_.holding(); }
    /// Moves sent (or followed) so far.
    std::uint64_t released() const { return released_; }
    /// The stage follows the axes (compensation or a length offset in effect).
    bool tracking() const { return tracking_; }
    /// Where the moves sent so far put the axes (valid while tracking()).
    const std::array<double, kMaxAxes>& axisPositions() const { return axisPosition_; }
    /// plan() accepted the block being committed.
    bool planned() const { return planned_.valid; }

    /// Where the axes stand when a block's own move begins in an
    /// uninterrupted run (the restart's re-entry point, TC-013), after plan()
    /// of that block (`planned`) or without it (false: the block could not be
    /// planned; a held move then ends at its perpendicular). `current`: the
    /// state before the block. Changes nothing; call discardPlan() after it.
    CompensatedPosition entryOfPlannedBlock(const ModalState& current, bool planned) const;
    /// Forgets a plan() that will not be committed.
    void discardPlan() { planned_.valid = false; }

  private:
    static constexpr int kLocations = 16;

    /// What plan() found for the block, carried out by the commit calls.
    struct Planned {
        bool valid = false;
        comp::RadiusCompensation engine;  ///< the engine after the block
        comp::Release before;             ///< released by a change of frame
        bool frameChange = false;
        CompensationFrame frame;                 ///< frame after the block
        bool viaEngine = false;                  ///< the move went through the engine
        comp::Release release;                   ///< what the move released
        int id = 0;                              ///< the move's id
        std::array<double, kMaxAxes> applied{};  ///< length offsets after the block
        bool relocateAfterMove = false;          ///< machine move: the tool is found again after it
        bool compensationOn = false;             ///< G41/G42 after the block
        std::uint32_t movedAxes = 0;             ///< axis words of the block
        bool reentry = false;                    ///< G77 to a re-entry point (TC-013)
        bool reentryCompensated = false;         ///< ... where compensation was in effect
        std::array<double, kMaxAxes> reentryAxes{};     ///< its axis positions
        std::array<double, kMaxAxes> reentryLengths{};  ///< its G48 offsets
    };

    /// motion() of a block plan() accepted.
    void plannedMotion(Motion& motion, bool output);
    bool report(const BlockContext& context, const comp::Problem& problem) const;
    SourceLocation locationOf(int id, const BlockContext& context) const;
    /// A change of plane axes, transformation or tool, or a machine move:
    /// the held move ends at its perpendicular, the tool is found again.
    bool planFrameChange(const BlockContext& context, const CompensationBlock& block);
    bool planMove(const BlockContext& context, const CompensationBlock& block);
    /// G47/G48: the length offset of every axis the block programs.
    bool planLengths(const BlockContext& context, const CompensationBlock& block);
    comp::ContourMove contourMove(const CompensationBlock& block) const;
    /// Ends the held move at its perpendicular (`stop`: and switches off).
    bool interrupt(DiagnosticList& diagnostics, bool stop);
    /// Sends the pieces of `release` (the queued outputs after the first
    /// `beforeQueued`); `current` is the template of move `currentId`.
    void sendRelease(const comp::Release& release, const Motion* current, int currentId);
    void emitPiece(const comp::ToolPiece& piece, const Motion& shape, double feed);
    /// A move without motion in the plane: the plane axes stay where the tool is.
    void placeInPlane(Motion& motion, const comp::Vec2& tool);
    /// The axes are at `motion`'s end now (it is marked compensated only
    /// where the tool leaves the programmed path).
    void follow(Motion& motion);
    /// follow() and send it to the machine.
    void send(Motion& motion);
    /// Positions of the plane axes with the tool centre at `point` (current frame).
    void placePlaneAxes(std::array<double, kMaxAxes>& axes, const comp::Vec2& point,
                        const std::array<double, kMaxAxes>& applied) const;
    /// Tool centre of axis positions `axes` in `frame`.
    comp::Vec2 centreIn(const CompensationFrame& frame, std::array<double, kMaxAxes> axes,
                        const std::array<double, kMaxAxes>& applied) const;
    /// Tool centre of the axis positions in the current frame.
    comp::Vec2 toolCentre() const;

    const ProcessAxes& axes_;
    ToolList configTools_;   ///< the configuration's tools (until useTools())
    const ToolList* tools_;  ///< where the tool data come from
    OutputQueue queue_;
    comp::RadiusCompensation engine_;
    CompensationFrame frame_;
    bool tracking_ = false;
    std::array<double, kMaxAxes> axisPosition_{};  ///< where the axes stand (tool reference)
    std::array<double, kMaxAxes> applied_{};       ///< length offset per axis in effect
    Motion held_;                                  ///< template of the held move
    int nextId_ = 0;
    std::array<SourceLocation, kLocations> locations_{};  ///< by id % kLocations
    int lookAhead_ = 0;
    bool output_ = true;  ///< the block's outputs are sent (not only followed)
    std::uint64_t released_ = 0;
    Planned planned_;
};

}  // namespace mtc::core
