#include "cnc_core/compensation/RadiusCompensation.h"

#include <cmath>
#include <cstdio>

#include "cnc_core/text/Numbers.h"

namespace mtc::core::comp {
namespace {

/// A re-entry point on a tool path: the restart computed it from the same
/// numbers, so only rounding separates them (mm).
constexpr double kOnPath = 1e-6;

double sideSign(Side side) {
    return static_cast<double>(static_cast<signed char>(side));
}

PlanePath straight(const Vec2& from, const Vec2& to) {
    PlanePath path;
    path.start = from;
    path.end = to;
    return path;
}

std::string mm(double value) {
    return formatFixed(value, 4);
}

/// An outer corner: the contour turns away from the tool side (or reverses).
bool outerCorner(const Vec2& before, const Vec2& after, Side side) {
    const double turn = cross(before, after);
    if (std::abs(turn) <= 1e-12) return true;  // straight on or a reversal: around the end
    return sideSign(side) * turn < 0.0;
}

Problem problem(const char* code, std::string message, int id, int otherId = 0) {
    return Problem{code, std::move(message), id, otherId};
}

}  // namespace

bool RadiusCompensation::ignores(const ContourMove& m) const {
    if (m.side == Side::None || !m.path.degenerate()) return false;
    const State& s = state_;
    return (s.phase == Phase::Active || s.phase == Phase::Resume) && s.held.side == m.side;
}

bool RadiusCompensation::apply(const ContourMove& move, Release& release, Problem& problem) {
    release = Release{};
    release.queuedAt = state_.tool;
    return step(state_, move, release, problem);
}

bool RadiusCompensation::step(State& s, const ContourMove& m, Release& r, Problem& p) const {
    bool ok = true;
    switch (s.phase) {
        case Phase::Off:
            ok = off(s, m, r, p);
            break;
        case Phase::Startup:
            if (m.side == Side::None) {
                s.phase = Phase::Off;
                ok = off(s, m, r, p);
            } else {
                ok = startup(s, m, p);
            }
            break;
        case Phase::Active:
            if (m.side == s.held.side) {
                ok = s.held.startup ? firstElement(s, m, r, p) : join(s, m, r, p);
                break;
            }
            // A cancel or a change of side: the contour ends here.
            if (!finishHeld(s, r, &p)) return false;
            r.beforeQueued = r.count;
            s.phase = m.side == Side::None ? Phase::Off : Phase::Startup;
            ok = m.side == Side::None ? off(s, m, r, p) : startup(s, m, p);
            break;
        case Phase::Resume:
            if (m.side == s.held.side) {
                ok = resume(s, m, r, p);
                break;
            }
            s.phase = m.side == Side::None ? Phase::Off : Phase::Startup;
            ok = m.side == Side::None ? off(s, m, r, p) : startup(s, m, p);
            break;
    }
    if (r.beforeQueued > 0)
        r.queuedAt = r.pieces[static_cast<std::size_t>(r.beforeQueued - 1)].path.end;
    return ok;
}

bool RadiusCompensation::off(State& s, const ContourMove& m, Release& r, Problem& p) const {
    if (m.side != Side::None) {  // G41/G42 selected: this move starts up
        if (!s.toolKnown) s.tool = m.path.start;
        s.toolKnown = true;
        s.phase = Phase::Startup;
        return startup(s, m, p);
    }
    PlanePath path = m.path;
    if (s.toolKnown) {
        if (path.isArc() && (s.tool - path.start).norm() >= kSamePoint) {
            p = problem("COMP_CANCEL_ARC",
                        "the tool is still offset from the programmed contour: leave it with a "
                        "straight move (G0/G1 with G40), not with a circle",
                        m.id);
            return false;
        }
        if (!path.isArc()) path.start = s.tool;
    }
    r.add({path, m.id, false});
    s.phase = Phase::Off;
    s.toolKnown = false;
    s.holding = false;
    s.tool = path.end;
    return true;
}

bool RadiusCompensation::startup(State& s, const ContourMove& m, Problem& p) const {
    const bool reentry = s.reentry;
    s.reentry = false;
    if (reentry && reenter(s, m)) return true;
    if (m.path.isArc()) {
        p = problem("COMP_STARTUP_ARC",
                    "G41/G42 start up with a straight move (G0/G1); a circle cannot be the "
                    "start-up move",
                    m.id);
        return false;
    }
    s.windowCount = 0;
    s.windowNext = 0;
    hold(s, m, straight(s.tool, s.tool), true);
    return true;
}

bool RadiusCompensation::reenter(State& s, const ContourMove& m) const {
    PlanePath element;
    Problem ignored;
    if (!offsetElement(m, element, ignored)) return false;
    const Vec2& tool = s.tool;
    double off = 0.0;  // distance of the tool from the element's carrier
    if (element.isArc()) {
        off = std::abs((tool - element.centre).norm() - element.radius());
    } else {
        const Vec2 d = element.end - element.start;
        if (d.norm() < kSamePoint) return false;
        off = std::abs(cross(d.normalized(), tool - element.start));
    }
    if (off > kOnPath) return false;
    const bool atStart = (tool - element.start).norm() < kOnPath;
    if (!atStart) {
        const double u = element.parameterOf(tool);
        if (!(u >= 0.0 && u < 1.0 - 1e-9)) return false;
        element.fullCircle = false;
    }
    element.start = tool;
    s.windowCount = 0;
    s.windowNext = 0;
    hold(s, m, element, false);
    return true;
}

bool RadiusCompensation::firstElement(State& s, const ContourMove& m, Release& r,
                                      Problem& p) const {
    PlanePath element;
    if (!offsetElement(m, element, p)) return false;
    // Start-up: the tool goes straight to the perpendicular of the element's start.
    r.add({straight(s.held.tool.start, element.start), s.held.id, false});
    r.beforeQueued = r.count;
    hold(s, m, element, false);
    return true;
}

bool RadiusCompensation::join(State& s, const ContourMove& m, Release& r, Problem& p) const {
    PlanePath element;
    if (!offsetElement(m, element, p)) return false;
    PlanePath held = s.held.tool;
    const Vec2 corner = m.path.start;
    ToolPiece corner_piece;
    bool inserted = false;
    if ((held.end - element.start).norm() < kSamePoint) {
        element.start = held.end;  // tangent: the offsets meet
    } else if (outerCorner(s.held.programmed.endTangent(), m.path.startTangent(), m.side)) {
        PlanePath arc;  // around the programmed corner with the tool radius
        arc.kind = m.side == Side::Left ? PathKind::ArcCw : PathKind::ArcCcw;
        arc.start = held.end;
        arc.end = element.start;
        arc.centre = corner;
        if (s.held.rapid && m.rapid) arc = straight(held.end, element.start);  // positioning only
        corner_piece = {arc, s.held.id, true};
        inserted = true;
    } else {
        Vec2 points[2];
        const int count = carrierIntersections(held, element, points);
        if (count == 0) {
            p = problem("COMP_NO_INTERSECTION",
                        "at the inside corner the tool paths of this block and the one before do "
                        "not meet: the tool cannot follow this contour",
                        m.id, s.held.id);
            return false;
        }
        Vec2 best = points[0];
        if (count == 2 && (points[1] - corner).norm() < (best - corner).norm()) best = points[1];
        const double u = held.parameterOf(best), v = element.parameterOf(best);
        if (!(u > 1e-9 && u <= 1.0 + 1e-9) || !(v >= -1e-9 && v < 1.0 - 1e-9)) {
            const bool heldVanishes = !(u > 1e-9 && u <= 1.0 + 1e-9);
            p = problem("COMP_ELEMENT_TOO_SHORT",
                        "the block is too short for the tool radius " + mm(m.radius) +
                            " at an inside corner: the tool would cut into the contour",
                        heldVanishes ? s.held.id : m.id, heldVanishes ? m.id : s.held.id);
            return false;
        }
        held.end = best;
        held.fullCircle = false;
        element.start = best;
        element.fullCircle = false;
    }
    if (!bottleneck(s, held, s.held.id, p)) return false;
    r.add({held, s.held.id, false});
    if (inserted) r.add(corner_piece);
    r.beforeQueued = r.count;
    remember(s, held, s.held.id);
    hold(s, m, element, false);
    return true;
}

bool RadiusCompensation::resume(State& s, const ContourMove& m, Release& r, Problem& p) const {
    PlanePath element;
    if (!offsetElement(m, element, p)) return false;
    if ((s.tool - element.start).norm() >= kSamePoint) {
        if (!outerCorner(s.held.programmed.endTangent(), m.path.startTangent(), m.side)) {
            p = problem("COMP_CORNER_INTERRUPTED",
                        "the contour was interrupted before this inside corner (programmed stop, "
                        "or too many blocks without motion in the plane): the tool stopped at the "
                        "perpendicular of the previous end and has cut into this block's contour",
                        m.id, s.held.id);
            return false;
        }
        PlanePath arc;
        arc.kind = m.side == Side::Left ? PathKind::ArcCw : PathKind::ArcCcw;
        arc.start = s.tool;
        arc.end = element.start;
        arc.centre = m.path.start;
        if (s.held.rapid && m.rapid) arc = straight(s.tool, element.start);
        r.add({arc, s.held.id, true});
    } else {
        element.start = s.tool;
    }
    r.beforeQueued = r.count;
    hold(s, m, element, false);
    return true;
}

bool RadiusCompensation::finishHeld(State& s, Release& r, Problem* p) const {
    const Held& h = s.held;
    PlanePath path = h.tool;
    if (h.startup) {  // a start-up move without an element after it: perpendicular to itself
        path = straight(h.tool.start, h.tool.start);
        const Vec2 direction = h.programmed.end - h.programmed.start;
        if (direction.norm() >= kSamePoint)
            path.end =
                h.programmed.end + sideSign(h.side) * h.radius * leftNormal(direction.normalized());
    }
    Problem found;
    const bool ok = h.startup || bottleneck(s, path, h.id, found);
    if (!ok && p) *p = found;
    r.add({path, h.id, false});
    if (!h.startup) remember(s, path, h.id);
    s.held.tool = path;
    s.tool = path.end;
    s.holding = false;
    s.toolKnown = true;
    return ok;
}

Release RadiusCompensation::interrupt(Problem* problem) {
    Release r;
    r.queuedAt = state_.tool;
    if (!state_.holding) return r;
    const bool noDirection = state_.held.startup && state_.held.programmed.degenerate();
    finishHeld(state_, r, problem);
    r.beforeQueued = r.count;
    r.queuedAt = state_.tool;
    state_.phase = noDirection ? Phase::Startup : Phase::Resume;
    return r;
}

Release RadiusCompensation::stop(Problem* problem) {
    if (idle()) return Release{};
    Release r = interrupt(problem);
    state_.phase = Phase::Off;
    state_.toolKnown = true;
    return r;
}

void RadiusCompensation::relocate(const Vec2& tool, bool compensationOn, bool reentry) {
    state_ = State{};
    state_.tool = tool;
    state_.toolKnown = true;
    state_.phase = compensationOn ? Phase::Startup : Phase::Off;
    state_.reentry = compensationOn && reentry;
}

bool RadiusCompensation::offsetElement(const ContourMove& m, PlanePath& out, Problem& p) const {
    if (offsetPath(m.path, sideSign(m.side) * m.radius, out)) return true;
    p = problem("COMP_ARC_TOO_SMALL",
                "the tool radius " + mm(m.radius) + " is not smaller than the radius " +
                    mm(m.path.radius()) +
                    " of this circle on the inside: the tool cannot follow it",
                m.id);
    return false;
}

bool RadiusCompensation::bottleneck(const State& s, const PlanePath& tool, int id,
                                    Problem& p) const {
    // The newest entry is the element just before: their corner is joined, not checked.
    const int newest = (s.windowNext + kWindow - 1) % kWindow;
    for (int i = 0; i < s.windowCount; ++i) {
        if (i == newest) continue;
        const WindowEntry& entry = s.window[static_cast<std::size_t>(i)];
        Vec2 where;
        if (!pathsCross(entry.tool, tool, where)) continue;
        p = problem("COMP_BOTTLENECK",
                    "the contour is too narrow for the tool: the tool path of this block crosses "
                    "the one of an earlier block at " +
                        mm(where.x()) + " " + mm(where.y()),
                    id, entry.id);
        return false;
    }
    return true;
}

void RadiusCompensation::remember(State& s, const PlanePath& tool, int id) {
    s.window[static_cast<std::size_t>(s.windowNext)] = {tool, id};
    s.windowNext = (s.windowNext + 1) % kWindow;
    if (s.windowCount < kWindow) ++s.windowCount;
}

void RadiusCompensation::hold(State& s, const ContourMove& m, const PlanePath& tool, bool startup) {
    s.held = {m.path, tool, m.side, m.radius, m.rapid, startup, m.id};
    s.holding = true;
    s.phase = Phase::Active;
    s.tool = tool.start;
}

}  // namespace mtc::core::comp
