#include "cnc_core/removal/ReentryCollisions.h"

#include <algorithm>
#include <cmath>

#include "cnc_core/removal/RemovalRun.h"
#include "cnc_core/removal/RemovalSink.h"
#include "cnc_core/restart/RestartSequence.h"

namespace mtc::core::removal {

namespace {

/// How near a move may come to the material (D-021): the part model is
/// exact at cell centres only, so half a cell either way is noise.
double toleranceOf(const PartModel& part) {
    return part.resolution() / 2.0;
}

/// The margin PartModel::touches is asked with: a rapid must stay more than
/// the tolerance above the material, a feed move may not cut more than it.
double marginFor(const Motion& m, double tolerance) {
    return m.type == MotionType::Rapid ? tolerance : -tolerance;
}

double distance(const std::array<double, 3>& p, const std::array<double, 3>& q) {
    double sum = 0.0;
    for (std::size_t k = 0; k < 3; ++k)
        sum += (q[k] - p[k]) * (q[k] - p[k]);
    return std::sqrt(sum);
}

std::array<double, 3> midpoint(const std::array<double, 3>& p, const std::array<double, 3>& q) {
    std::array<double, 3> m{};
    for (std::size_t k = 0; k < 3; ++k)
        m[k] = p[k] + (q[k] - p[k]) / 2.0;
    return m;
}

/// The first point along `chord` up to which the sweep from its start
/// touches (the chord as a whole does): bisection on the growing
/// sub-sweep, which touches from some point on. Halved as points, not as a
/// fraction, so a point near the far end of a huge chord keeps its
/// precision. Within a quarter of the resolution, at most kMaxBisections
/// sub-sweeps.
std::array<double, 3> firstTouch(const PartModel& part, const ToolChord& chord,
                                 const Cutter& cutter, double margin) {
    std::array<double, 3> lo = chord.a, hi = chord.b;  // to lo: no touch; to hi: touch
    for (int i = 0; i < kMaxBisections && distance(lo, hi) > part.resolution() / 4.0; ++i) {
        const std::array<double, 3> mid = midpoint(lo, hi);
        if (mid == lo || mid == hi) break;  // as fine as doubles go
        if (part.touches(chord.a, mid, cutter, margin))
            hi = mid;
        else
            lo = mid;
    }
    return hi;
}

/// Machine positions of every axis at the scene point `touch` on chord
/// `index` of move `m`: the axes drawn in the scene from the point with the
/// offset between scene and machine at the nearer end of the move (the
/// tool offset, the lathe's nose shift; the nearer end keeps the float
/// rounding of a far end out), the others in proportion.
std::array<double, kMaxAxes> machinePositionAt(const Motion& m, const ToolSweep& sweep,
                                               const std::array<double, 3>& touch,
                                               std::size_t index) {
    const std::vector<ToolChord>& chords = sweep.chords();
    const ToolChord& chord = chords[index];
    const double length = distance(chord.a, chord.b);
    const double t = length > 0.0 ? std::min(1.0, distance(chord.a, touch) / length) : 0.0;
    const double fraction = (static_cast<double>(index) + t) / static_cast<double>(chords.size());
    const bool nearStart = distance(touch, chords.front().a) < distance(touch, chords.back().b);
    const std::array<double, 3>& sceneEnd = nearStart ? chords.front().a : chords.back().b;
    const std::array<double, kMaxAxes>& machineEnd = nearStart ? m.start : m.end;
    std::array<double, kMaxAxes> position = m.end;
    for (int a = 0; a < m.axisCount && a < kMaxAxes; ++a) {
        const auto i = static_cast<std::size_t>(a);
        const int s = sweep.sceneAxis(a);
        if (s >= 0) {
            const auto k = static_cast<std::size_t>(s);
            position[i] = machineEnd[i] + (touch[k] - sceneEnd[k]);
        } else {
            position[i] = m.start[i] + (m.end[i] - m.start[i]) * fraction;
        }
    }
    return position;
}

JacketPoint between(const JacketPoint& p, const JacketPoint& q) {
    return {p.angle + (q.angle - p.angle) / 2.0, p.axial + (q.axial - p.axial) / 2.0,
            p.face + (q.face - p.face) / 2.0};
}

/// Distance of two jacket points on the developed plane at the larger face
/// radius, and radially.
double jacketDistance(const JacketPoint& p, const JacketPoint& q) {
    const double scale = std::max(std::fabs(p.face), std::fabs(q.face));
    return std::hypot(scale * (q.angle - p.angle), q.axial - p.axial, q.face - p.face);
}

/// firstTouch() of a G32 chord on the jacket.
JacketPoint firstJacketTouch(const PartModel& part, const std::array<JacketPoint, 2>& chord,
                             double toolRadius, double margin) {
    JacketPoint lo = chord[0], hi = chord[1];
    for (int i = 0; i < kMaxBisections && jacketDistance(lo, hi) > part.resolution() / 4.0; ++i) {
        const JacketPoint mid = between(lo, hi);
        if (part.touchesJacket(chord[0], mid, toolRadius, margin))
            hi = mid;
        else
            lo = mid;
    }
    return hi;
}

/// Checks a G32 move against the jacket (D-027): the collision at its first
/// touch, the machine positions in proportion along the move.
std::optional<ReentryCollision> checkDevelopedMove(const PartModel& part, const ToolSweep& sweep,
                                                   const PreviewMove& move, double margin) {
    const auto& chords = sweep.jacketChords();
    const double radius = sweep.cutter().radius;
    for (std::size_t c = 0; c < chords.size(); ++c) {
        if (!part.touchesJacket(chords[c][0], chords[c][1], radius, margin)) continue;
        const JacketPoint touch = firstJacketTouch(part, chords[c], radius, margin);
        const double length = jacketDistance(chords[c][0], chords[c][1]);
        const double t =
            length > 0.0 ? std::min(1.0, jacketDistance(chords[c][0], touch) / length) : 0.0;
        const double fraction = (static_cast<double>(c) + t) / static_cast<double>(chords.size());
        ReentryCollision collision;
        collision.repos = move.repos;
        collision.rapid = move.motion.type == MotionType::Rapid;
        collision.where = move.motion.where;
        const Motion& m = move.motion;
        collision.position = m.end;
        for (int a = 0; a < m.axisCount && a < kMaxAxes; ++a) {
            const auto i = static_cast<std::size_t>(a);
            collision.position[i] = m.start[i] + (m.end[i] - m.start[i]) * fraction;
        }
        const auto axial = static_cast<std::size_t>(part.axialAxis());
        const auto radial = static_cast<std::size_t>(part.radialAxis());
        collision.scene[axial] = touch.axial;
        collision.scene[radial] = touch.face * std::cos(touch.angle);
        collision.scene[(radial + 1) % 3] = touch.face * std::sin(touch.angle);
        return collision;
    }
    return std::nullopt;
}

/// Checks one move; the collision when it meets the part.
std::optional<ReentryCollision> checkMove(const PartModel& part, ToolSweep& sweep,
                                          const PreviewMove& move, double tolerance) {
    const ToolSweep::Kind kind = sweep.sweep(move.motion, move.tool);
    const double margin = marginFor(move.motion, tolerance);
    if (kind == ToolSweep::Kind::Developed) return checkDevelopedMove(part, sweep, move, margin);
    if (kind != ToolSweep::Kind::Swept) return std::nullopt;
    const std::vector<ToolChord>& chords = sweep.chords();
    for (std::size_t c = 0; c < chords.size(); ++c) {
        if (!part.touches(chords[c].a, chords[c].b, sweep.cutter(), margin)) continue;
        ReentryCollision collision;
        collision.repos = move.repos;
        collision.rapid = move.motion.type == MotionType::Rapid;
        collision.where = move.motion.where;
        collision.scene = firstTouch(part, chords[c], sweep.cutter(), margin);
        collision.position = machinePositionAt(move.motion, sweep, collision.scene, c);
        return collision;
    }
    return std::nullopt;
}

bool hasDevelopedMove(const ReposPreview& preview) {
    return std::any_of(preview.moves.begin(), preview.moves.end(),
                       [](const PreviewMove& m) { return m.motion.transformation == 32; });
}

/// The stop of the removal run: the target block at the selected arrival
/// with the route's call chain, after the operator's variable and event changes.
RemovalStop stopAtTarget(const ReentryCheckInput& in) {
    RemovalStop stop;
    stop.target = {in.route->targetProgram->number, in.selection->target.block, 1};
    stop.runs = in.selection->runs;
    const RestartRoute* route = in.route;
    stop.counts = [route](const InterpreterState& state) { return atRouteLevel(state, *route); };
    const RestartSelection* selection = in.selection;
    stop.prepare = [selection](Interpreter& interpreter) {
        for (const auto& [variable, value] : selection->variableChanges)
            interpreter.writeVariable(variable, value);
        for (const auto& [event, value] : selection->eventChanges)
            interpreter.events().set(event.process, event.event, value);
    };
    stop.zeroOffsets = in.zeroOffsets;
    return stop;
}

}  // namespace

ReentryCheck checkReentry(const ReentryCheckInput& in) {
    ReentryCheck check;
    if (!in.config || !in.programs || !in.selection || !in.route || !in.route->targetProgram ||
        !in.preview) {
        check.diagnostics.error("REENTRY_NOT_CHECKED", {}, "no restart target to check against");
        return check;
    }
    const RemovalStop stop = stopAtTarget(in);
    RemovalRunResult run = simulateRemoval(*in.config, *in.programs, in.selection->mainProgram,
                                           in.settings, in.tools, in.blockBudget, &stop);
    check.diagnostics.append(run.diagnostics);
    check.blocks = run.blocks;
    if (!run.part || !run.complete) return check;
    if (hasDevelopedMove(*in.preview)) {  // the jacket, also where G32 has cut nothing yet
        std::string note;
        run.part->makeJacket(note);
        if (!note.empty()) check.diagnostics.warning("REMOVAL_DEVELOPED_COARSER", {}, note);
    }
    const PartModel& part = *run.part;
    check.removedVolume = part.removedVolume();
    check.resolution = part.resolution();
    check.tolerance = toleranceOf(part);
    DiagnosticList axisProblems;
    ToolSweep sweep(ProcessAxes::build(*in.config, axisProblems), part);
    const std::vector<PreviewMove>& moves = in.preview->moves;
    for (std::size_t i = 0; i < moves.size(); ++i) {
        auto collision = checkMove(part, sweep, moves[i], check.tolerance);
        if (!collision) continue;
        collision->move = i;
        check.collisions.push_back(*collision);
    }
    check.moves = moves.size();
    check.checked = true;
    check.partAtTarget = std::make_shared<const PartModel>(std::move(*run.part));
    return check;
}

std::optional<ReentryCheck> checkRestartReentry(const RestartSequence& sequence,
                                                const Interpreter& live,
                                                const ProgramStore& programs,
                                                const RemovalSettings& settings) {
    const std::optional<ReposPreviewStart> start = reposPreviewStart(sequence, live);
    if (!start) return std::nullopt;
    const ReposPreview preview =
        previewRepositioning(live.config(), programs, live.machineData(), *start);
    ReentryCheckInput input;
    input.config = &live.config();
    input.programs = &programs;
    input.selection = &sequence.computing().selection();
    input.route = &sequence.computing().route();
    input.preview = &preview;
    // Not owned: the check ends before this function returns.
    input.tools = std::shared_ptr<const ToolList>(std::shared_ptr<void>(), &live.tools());
    input.zeroOffsets =
        std::shared_ptr<const ZeroOffsetTable>(std::shared_ptr<void>(), &live.zeroOffsets());
    input.settings = settings;
    ReentryCheck check = checkReentry(input);
    check.diagnostics.append(preview.diagnostics);
    return check;
}

}  // namespace mtc::core::removal
