#include "cnc_core/compensation/ToolCompensation.h"

#include <cmath>
#include <cstdio>

#include "cnc_core/interp/ModalGroups.h"
#include "cnc_core/text/Numbers.h"

namespace mtc::core {
namespace {

using comp::Vec2;

comp::Side sideOf(const ModalState& modal) {
    switch (modal.g[kGroupToolPath]) {
        case 41:
            return comp::Side::Left;
        case 42:
            return comp::Side::Right;
        default:
            return comp::Side::None;
    }
}

bool anyOffset(const std::array<double, kMaxAxes>& offsets) {
    for (double d : offsets)
        if (d != 0.0) return true;
    return false;
}

bool samePlane(const PlaneSelection& a, const PlaneSelection& b) {
    return a.plane() == b.plane() && a.firstAxis() == b.firstAxis() &&
           a.secondAxis() == b.secondAxis() && a.perpendicularAxis() == b.perpendicularAxis();
}

std::string describe(const SourceLocation& where) {
    std::string text = where.block.empty() ? "the block" : where.block;
    return text + " (program " + std::to_string(where.program) + ", line " +
           std::to_string(where.line) + ")";
}

std::string mm(double value) {
    return formatFixed(value, 4);
}

}  // namespace

ToolCompensation::ToolCompensation(MachineSink& downstream, const ProcessConfig& config,
                                   const ProcessAxes& axes)
    : axes_(axes),
      configTools_(ToolList::fromConfig(config)),
      tools_(&configTools_),
      queue_(downstream) {}

// ---------------------------------------------------------------- plan stage

bool ToolCompensation::plan(const BlockContext& context, const CompensationBlock& block) {
    Planned& p = planned_;
    p.valid = false;
    if (!tracking_) {  // until now the axes stood where they were programmed
        axisPosition_ = block.current.machine;
        applied_ = {};
        engine_.reset();
        frame_ = CompensationFrame::of(block.current, activeToolData(*tools_, block.current));
        tracking_ = true;
    }
    const ToolData tool = activeToolData(*tools_, block.next);
    if (tool.edgeMissing &&
        (sideOf(block.next) != comp::Side::None || block.next.g[kGroupToolLength] == 48))
        return context.error("COMP_EDGE_UNKNOWN",
                             "tool T" + std::to_string(tool.number) + " has no cutting edge E" +
                                 std::to_string(tool.edge) +
                                 " in the tool list: radius and lengths are unknown");
    p.engine = engine_;
    p.before = comp::Release{};
    p.release = comp::Release{};
    p.frame = CompensationFrame::of(block.next, tool);
    p.frameChange = false;
    p.viaEngine = false;
    p.relocateAfterMove = false;
    p.compensationOn = sideOf(block.next) != comp::Side::None;
    p.applied = applied_;
    p.movedAxes = block.programmedAxes;
    p.reentry = block.machineMove && block.reentry != nullptr;
    p.reentryCompensated = p.reentry && block.reentry->compensated;
    if (p.reentryCompensated) {
        p.reentryAxes = block.reentry->axes;
        p.reentryLengths = block.reentry->lengthOffsets;
    }
    p.id = nextId_ + 1;
    if (!planFrameChange(context, block) || !planMove(context, block) ||
        !planLengths(context, block))
        return false;
    p.valid = true;
    return true;
}

bool ToolCompensation::planFrameChange(const BlockContext& context,
                                       const CompensationBlock& block) {
    Planned& p = planned_;
    const bool compensating = sideOf(block.current) != comp::Side::None || p.compensationOn;
    if (compensating && !samePlane(block.current.plane, block.next.plane))
        return context.error("COMP_PLANE_CHANGE",
                             "the working plane cannot change while G41/G42 is active: switch "
                             "compensation off with G40 first");
    const bool geometry = !p.frame.sameGeometry(frame_);
    const bool toolChanged = !p.frame.sameTool(frame_);
    if (!geometry && !toolChanged && !block.machineMove) return true;
    const comp::Phase phase = p.engine.phase();
    if (toolChanged && (phase == comp::Phase::Active || phase == comp::Phase::Resume))
        return context.error("COMP_TOOL_CHANGE",
                             "the tool in working position changes while G41/G42 is active "
                             "(radius " +
                                 mm(frame_.radius) + " to " + mm(p.frame.radius) +
                                 "): change tools with G40");
    p.frameChange = true;
    if (p.engine.idle()) {
        // REPOS: the tool is found again where G77 puts it (TC-013).
        p.relocateAfterMove = p.reentry;
        return true;
    }
    comp::Problem problem;
    p.before = p.engine.interrupt(&problem);  // the held move ends at its perpendicular
    if (problem.code) return report(context, problem);
    if (block.machineMove) {
        p.relocateAfterMove = true;
        return true;
    }
    // Where the tool centre stands in the new frame (the axes do not move).
    std::array<double, kMaxAxes> axes = axisPosition_;
    if (p.before.count > 0)
        placePlaneAxes(axes, p.before.pieces[static_cast<std::size_t>(p.before.count - 1)].path.end,
                       applied_);
    p.engine.relocate(centreIn(p.frame, axes, applied_), p.compensationOn);
    return true;
}

bool ToolCompensation::planMove(const BlockContext& context, const CompensationBlock& block) {
    Planned& p = planned_;
    if (!block.hasMotion || block.machineMove) return true;
    const int a1 = p.frame.axis1, a2 = p.frame.axis2;
    const bool arc = block.type == MotionType::ArcCW || block.type == MotionType::ArcCCW;
    const bool inPlane = arc || (a1 >= 0 && ((block.programmedAxes >> a1) & 1u)) ||
                         (a2 >= 0 && ((block.programmedAxes >> a2) & 1u));
    if (!inPlane) return true;
    const comp::Side side = sideOf(block.next);
    if (p.engine.idle() && side == comp::Side::None) return true;  // as programmed
    if (a1 < 0 || a2 < 0)
        return context.error("COMP_PLANE", "radius compensation needs a working plane of two axes");
    if (side != comp::Side::None && p.frame.rotaryUntransformed(axes_))
        return context.error("COMP_ROTARY_PLANE",
                             "radius compensation in a plane with a rotary axis needs G31 or G32 "
                             "first (seed 003, 4.2)");
    const comp::ContourMove move = contourMove(block);
    if (p.engine.ignores(move)) return true;  // no direction: like a block without plane motion
    comp::Problem problem;
    if (!p.engine.apply(move, p.release, problem)) return report(context, problem);
    p.viaEngine = true;
    return true;
}

bool ToolCompensation::planLengths(const BlockContext& context, const CompensationBlock& block) {
    Planned& p = planned_;
    if (!block.hasMotion) return true;
    const bool on = block.next.g[kGroupToolLength] == 48 && !block.machineMove;
    for (int a = 0; block.programmedAxes >> a; ++a) {
        if (!((block.programmedAxes >> a) & 1u)) continue;
        const auto i = static_cast<std::size_t>(a);
        p.applied[i] = on && a == p.frame.lengthAxis ? p.frame.length : 0.0;
        // REPOS to a compensated re-entry point: the axis takes the tool
        // length it had there (TC-013).
        if (p.reentryCompensated) p.applied[i] = p.reentryLengths[i];
        const AxisModel& model = axes_.axis(a);
        const double position = block.next.machine[i] + p.applied[i];
        if (p.applied[i] != 0.0 && model.limited() &&
            (position < model.minPosition - 1e-9 || position > model.maxPosition + 1e-9))
            return context.error("TRAVEL_LIMIT",
                                 "axis " + model.displayName() + " would move to " + mm(position) +
                                     " with the tool length " + mm(p.frame.length) +
                                     " (G48), outside its travel range " + mm(model.minPosition) +
                                     " .. " + mm(model.maxPosition));
    }
    return true;
}

comp::ContourMove ToolCompensation::contourMove(const CompensationBlock& block) const {
    const CompensationFrame& f = planned_.frame;
    comp::ContourMove move;
    move.side = sideOf(block.next);
    move.radius = f.radius;
    move.rapid = block.type == MotionType::Rapid;
    move.id = planned_.id;
    comp::PlanePath& path = move.path;
    path.kind = block.type == MotionType::ArcCW    ? comp::PathKind::ArcCw
                : block.type == MotionType::ArcCCW ? comp::PathKind::ArcCcw
                                                   : comp::PathKind::Line;
    path.start = f.toPlane(axes_, block.current.machine);
    path.end = f.toPlane(axes_, block.next.machine);
    if (path.isArc()) {
        path.centre = Vec2(block.centre1, block.centre2);
        path.fullCircle = block.fullCircle;
    }
    if (move.side ==
        comp::Side::None) {  // G40: the nose centre is the tool reference minus the edge
        path.start -= f.edge;
        path.end -= f.edge;
        path.centre -= f.edge;
    }
    return move;
}

bool ToolCompensation::report(const BlockContext& context, const comp::Problem& problem) const {
    const SourceLocation here = blockLocation(context.program, context.blockIndex);
    const SourceLocation at = locationOf(problem.id, context);
    std::vector<std::string> details;
    if (problem.otherId != 0)
        details.push_back("the other block: " + describe(locationOf(problem.otherId, context)));
    if (at.program != here.program || at.line != here.line || at.block != here.block)
        details.push_back("found while preparing " + describe(here));
    details.push_back("tool radius " + mm(planned_.frame.radius) + " mm");
    context.diagnostics.error(problem.code, at, problem.message, details);
    return false;
}

SourceLocation ToolCompensation::locationOf(int id, const BlockContext& context) const {
    if (id == planned_.id) return blockLocation(context.program, context.blockIndex);
    return locations_[static_cast<std::size_t>(id % kLocations)];
}

CompensatedPosition ToolCompensation::entryOfPlannedBlock(const ModalState& current,
                                                          bool planned) const {
    CompensatedPosition entry;
    entry.axes = current.machine;
    if (!tracking_) return entry;
    entry.compensated = true;
    entry.lengthOffsets = applied_;
    if (!engine_.holding()) {
        entry.axes = axisPosition_;
        return entry;
    }
    // A move is held: its end is where the block's own move begins. The
    // axes outside the plane stand at their programmed point (+ length).
    for (std::size_t a = 0; a < kMaxAxes; ++a)
        entry.axes[a] = current.machine[a] + applied_[a];
    const Planned& p = planned_;
    comp::Release release;
    int own = -1;  // pieces of the block's own move are not before it
    if (planned && p.valid && p.frameChange && p.before.count > 0) {
        release = p.before;
    } else if (planned && p.valid && p.viaEngine) {
        release = p.release;
        own = p.id;
    } else {  // no plane move follows in this block: as at a programmed stop
        comp::RadiusCompensation engine = engine_;
        release = engine.interrupt();
        entry.interrupted = true;
    }
    const comp::Vec2* end = nullptr;
    for (int i = 0; i < release.count; ++i)
        if (release.pieces[static_cast<std::size_t>(i)].id != own)
            end = &release.pieces[static_cast<std::size_t>(i)].path.end;
    placePlaneAxes(entry.axes, end ? *end : engine_.tool(), applied_);
    return entry;
}

// -------------------------------------------------------------- commit stage

void ToolCompensation::beginOutputs(bool output) {
    if (!planned_.valid) return;
    output_ = output;
    if (planned_.frameChange) {
        sendRelease(planned_.before, nullptr, 0);
        frame_ = planned_.frame;
    }
    engine_ = planned_.engine;
}

void ToolCompensation::plannedMotion(Motion& m, bool output) {
    output_ = output;
    const Planned& p = planned_;
    m.compensated = true;
    m.inserted = false;
    m.programmedEnd = m.end;
    m.toolOffset = p.applied;
    for (std::size_t a = 0; a < kMaxAxes; ++a)
        m.end[a] += p.applied[a];
    if (p.relocateAfterMove) {  // G74 / G75 / G77: machine positions, other axes stay
        m.start = axisPosition_;
        for (int a = 0; a < axes_.count(); ++a) {
            const auto i = static_cast<std::size_t>(a);
            if (!((p.movedAxes >> a) & 1u))
                m.end[i] = axisPosition_[i];
            else if (p.reentryCompensated)  // REPOS: to the compensated re-entry point
                m.end[i] = p.reentryAxes[i];
        }
        send(m);
        applied_ = p.applied;
        engine_.relocate(toolCentre(), p.compensationOn, p.reentry);
        return;
    }
    if (p.viaEngine) {
        locations_[static_cast<std::size_t>(p.id % kLocations)] = m.where;
        nextId_ = p.id;
        sendRelease(p.release, &m, p.id);
        if (engine_.holding()) {
            held_ = m;
            queue_.hold();
            lookAhead_ = 0;
        }
        return;
    }
    if (!engine_.idle()) {  // no motion in the plane: the plane axes stay with the tool
        if (engine_.holding()) {
            if (output) queue_.motion(m);  // placed when the held move is released
            return;
        }
        placeInPlane(m, engine_.tool());
        send(m);
        return;
    }
    m.start = axisPosition_;
    send(m);
}

bool ToolCompensation::endBlock(bool stopping, DiagnosticList& diagnostics) {
    if (!planned_.valid) return true;
    planned_.valid = false;
    applied_ = planned_.applied;
    bool ok = true;
    if (engine_.holding()) {
        if (!planned_.viaEngine) ++lookAhead_;
        if (stopping || lookAhead_ > kLookAheadBlocks) ok = interrupt(diagnostics, false);
    }
    if (engine_.idle() && !anyOffset(applied_) && !queue_.holding()) tracking_ = false;
    return ok;
}

bool ToolCompensation::programEnd(DiagnosticList* diagnostics) {
    if (!tracking_) return true;
    planned_.valid = false;
    DiagnosticList local;
    const bool ok = interrupt(diagnostics ? *diagnostics : local, true);
    return ok;
}

bool ToolCompensation::interrupt(DiagnosticList& diagnostics, bool stop) {
    comp::Problem problem;
    const comp::Release release = stop ? engine_.stop(&problem) : engine_.interrupt(&problem);
    sendRelease(release, nullptr, 0);
    if (!problem.code) return true;
    std::vector<std::string> details;
    if (problem.otherId != 0)
        details.push_back(
            "the other block: " +
            describe(locations_[static_cast<std::size_t>(problem.otherId % kLocations)]));
    details.push_back("tool radius " + mm(frame_.radius) + " mm");
    diagnostics.error(problem.code, locations_[static_cast<std::size_t>(problem.id % kLocations)],
                      problem.message, details);
    return false;
}

void ToolCompensation::controlReset() {
    queue_.clear();
    planned_.valid = false;
    lookAhead_ = 0;
    if (tracking_) engine_.relocate(toolCentre(), false);  // the held move never went out
}

void ToolCompensation::restart() {
    queue_.clear();
    engine_.reset();
    planned_.valid = false;
    tracking_ = false;
    applied_ = {};
    lookAhead_ = 0;
}

// ------------------------------------------------------------------ emission

void ToolCompensation::sendRelease(const comp::Release& release, const Motion* current,
                                   int currentId) {
    const double feed = current ? current->feed : 0.0;
    auto shapeOf = [&](int id) -> const Motion& {
        return current && id == currentId ? *current : held_;
    };
    for (int i = 0; i < release.beforeQueued; ++i) {
        const comp::ToolPiece& piece = release.pieces[static_cast<std::size_t>(i)];
        emitPiece(piece, shapeOf(piece.id), feed);
    }
    if (queue_.holding())
        queue_.release([&](Motion& queued) {
            placeInPlane(queued, release.queuedAt);
            follow(queued);
        });
    for (int i = release.beforeQueued; i < release.count; ++i) {
        const comp::ToolPiece& piece = release.pieces[static_cast<std::size_t>(i)];
        emitPiece(piece, shapeOf(piece.id), feed);
    }
}

void ToolCompensation::emitPiece(const comp::ToolPiece& piece, const Motion& shape, double feed) {
    Motion m = shape;
    m.start = axisPosition_;
    m.compensated = true;
    m.inserted = piece.inserted;
    const auto a1 = static_cast<std::size_t>(frame_.axis1);
    const auto a2 = static_cast<std::size_t>(frame_.axis2);
    m.toolOffset[a1] += frame_.edge.x();
    m.toolOffset[a2] += frame_.edge.y();
    double e1 = 0.0, e2 = 0.0;
    frame_.toMachine(axes_, piece.path.end, axisPosition_, e1, e2);
    m.end[a1] = e1 + m.toolOffset[a1];
    m.end[a2] = e2 + m.toolOffset[a2];
    if (piece.path.isArc()) {
        m.type = piece.path.kind == comp::PathKind::ArcCw ? MotionType::ArcCW : MotionType::ArcCCW;
        m.planeAxis1 = frame_.axis1;
        m.planeAxis2 = frame_.axis2;
        double c1 = 0.0, c2 = 0.0;
        frame_.centreToMotion(axes_, piece.path.centre, axisPosition_, c1, c2);
        m.center1 = c1 + m.toolOffset[a1];
        m.center2 = c2 + m.toolOffset[a2];
        m.fullCircle = piece.path.fullCircle;
        if (piece.inserted && m.feed <= 0.0) m.feed = feed;
    } else {
        m.type = piece.inserted || shape.type == MotionType::Rapid ? MotionType::Rapid
                                                                   : MotionType::Linear;
        m.planeAxis1 = m.planeAxis2 = -1;
        m.center1 = m.center2 = 0.0;
        m.fullCircle = false;
    }
    if (m.type == MotionType::Rapid) m.feed = 0.0;
    send(m);
}

void ToolCompensation::placeInPlane(Motion& m, const Vec2& tool) {
    m.start = axisPosition_;
    m.compensated = true;
    if (frame_.axis1 < 0 || frame_.axis2 < 0) return;
    const auto a1 = static_cast<std::size_t>(frame_.axis1);
    const auto a2 = static_cast<std::size_t>(frame_.axis2);
    m.toolOffset[a1] += frame_.edge.x();
    m.toolOffset[a2] += frame_.edge.y();
    double e1 = 0.0, e2 = 0.0;
    frame_.toMachine(axes_, tool, axisPosition_, e1, e2);
    m.end[a1] = e1 + m.toolOffset[a1];
    m.end[a2] = e2 + m.toolOffset[a2];
}

void ToolCompensation::follow(Motion& m) {
    if (m.compensated && !m.inserted) {  // marked only where the tool leaves the programmed path
        bool differs = false;
        for (std::size_t a = 0; a < kMaxAxes && !differs; ++a)
            differs = m.toolOffset[a] != 0.0 || std::fabs(m.end[a] - m.programmedEnd[a]) > 1e-9;
        m.compensated = differs;
    }
    axisPosition_ = m.end;
    ++released_;
}

void ToolCompensation::send(Motion& m) {
    follow(m);
    if (output_) queue_.downstream().motion(m);
}

void ToolCompensation::placePlaneAxes(std::array<double, kMaxAxes>& axes, const Vec2& point,
                                      const std::array<double, kMaxAxes>& applied) const {
    const auto a1 = static_cast<std::size_t>(frame_.axis1);
    const auto a2 = static_cast<std::size_t>(frame_.axis2);
    double e1 = 0.0, e2 = 0.0;
    frame_.toMachine(axes_, point, axes, e1, e2);
    axes[a1] = e1 + frame_.edge.x() + applied[a1];
    axes[a2] = e2 + frame_.edge.y() + applied[a2];
}

Vec2 ToolCompensation::centreIn(const CompensationFrame& frame, std::array<double, kMaxAxes> axes,
                                const std::array<double, kMaxAxes>& applied) const {
    if (frame.axis1 < 0 || frame.axis2 < 0) return Vec2::Zero();
    for (std::size_t a = 0; a < kMaxAxes; ++a)
        axes[a] -= applied[a];
    return frame.toPlane(axes_, axes) - frame.edge;
}

Vec2 ToolCompensation::toolCentre() const {
    return centreIn(frame_, axisPosition_, applied_);
}

}  // namespace mtc::core
