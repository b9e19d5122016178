#include "cnc_core/removal/LiveCut.h"

#include <algorithm>
#include <cmath>

#include "cnc_core/motion/QueueFollower.h"
#include "cnc_core/motion/TrajectoryEngine.h"
#include "cnc_core/removal/RemovalRun.h"

namespace mtc::core::removal {

namespace {

double distance(const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return std::sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) +
                     (b[2] - a[2]) * (b[2] - a[2]));
}

std::array<double, 3> between(const std::array<double, 3>& a, const std::array<double, 3>& b,
                              double t) {
    return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
}

}  // namespace

LiveCut::LiveCut(const ProcessAxes& axes) : axes_(axes) {}

void LiveCut::begin(const ProcessConfig& config, const ProgramStore& programs, int program,
                    std::shared_ptr<const ZeroOffsetTable> zeroOffsets) {
    const ProgramStock stock = programStock(config, programs, program, std::move(zeroOffsets));
    const bool turning = config.defaultPlane() == 18;  // as PartModel decides
    DiagnosticList problems;
    std::optional<PartModel> blank =
        blankPart(config, stock, fittingSettings(stock.stock, turning, kViewCells), problems);
    begin(program, std::move(blank), std::move(problems));
}

void LiveCut::begin(int program, std::optional<PartModel> blank, DiagnosticList problems) {
    pending_.clear();
    sweep_.reset();  // it refers to the part
    part_ = std::move(blank);
    if (part_) sweep_.emplace(axes_, *part_);
    problems_ = std::move(problems);
    program_ = program;
    moves_ = 0;
    stopped_ = !part_;
    fromRestart_ = false;
    byHand_ = false;
    ++run_;
    ++revision_;
}

void LiveCut::beginAt(int program, PartModel part) {
    begin(program, std::move(part), {});
    fromRestart_ = true;
    moves_ = 1;  // no approach: the first move is cut
}

bool LiveCut::resume() {
    if (!part_) return false;
    if (stopped_ || moves_ == 0) {
        stopped_ = false;
        moves_ = std::max<std::uint64_t>(moves_, 1);  // no approach: the axes are on the part
        ++revision_;
    }
    byHand_ = true;
    return true;
}

void LiveCut::sentJog(const Motion& motion) {
    if (stopped_) return;
    Motion move = motion;
    sweep_->carryOffsets(move);
    sent(move, true);
}

void LiveCut::sent(const Motion& motion, bool queued) {
    if (stopped_) return;
    PendingMove move;
    if (++moves_ == 1)
        sweep_->pass(motion);  // the approach from where the axes stood
    else
        takeSweep(motion, move);
    if (!queued) return;  // no length: nothing to cut
    double length = 0.0;
    for (const ToolChord& chord : move.chords)
        move.ends.push_back(length += distance(chord.a, chord.b));
    if (!move.chords.empty()) move.at = move.chords.front().a;
    pending_.push_back(std::move(move));
}

void LiveCut::takeSweep(const Motion& motion, PendingMove& move) {
    switch (sweep_->sweep(motion, toolSource_ ? toolSource_() : ToolData{})) {
        case ToolSweep::Kind::Swept:
            move.chords = sweep_->chords();
            break;
        case ToolSweep::Kind::Developed: {
            std::string coarser;
            if (!part_->makeJacket(coarser)) return;
            if (!coarser.empty())  // the jacket is made at the run's first G32 move
                problems_.warning("REMOVAL_DEVELOPED_COARSER", motion.where, coarser);
            move.onJacket = true;
            for (const auto& [a, b] : sweep_->jacketChords())
                move.chords.push_back({{a.angle, a.axial, a.face}, {b.angle, b.axial, b.face}});
            break;
        }
        case ToolSweep::Kind::Transformed:
        case ToolSweep::Kind::InsideTool:
            return;  // not simulated (RemovalSink counts them)
    }
    move.cutter = sweep_->cutter();
}

bool LiveCut::cutPiece(const PendingMove& move, const std::array<double, 3>& from,
                       const std::array<double, 3>& to) {
    if (!move.onJacket) return part_->cut(from, to, move.cutter);
    return part_->cutJacket({from[0], from[1], from[2]}, {to[0], to[1], to[2]}, move.cutter.radius);
}

void LiveCut::follow(const motion::TrajectoryEngine& engine) {
    if (stopped_) return;
    const std::optional<double> travelled = motion::followMachineQueue(
        engine, pending_, [this](PendingMove& finished) { cutTo(finished, 1.0); });
    if (travelled) cutTo(pending_.front(), *travelled);
}

void LiveCut::stop() {
    pending_.clear();
    stopped_ = true;
}

void LiveCut::cutTo(PendingMove& move, double share) {
    if (move.chords.empty() || !(share > 0.0)) return;
    const double target = std::min(share, 1.0) * move.ends.back();
    bool removed = false;
    // Chords end to end: the disc swept along a-p and then p-b is the one
    // swept along a-b, so cutting in pieces leaves the part a whole cut does
    // (on the jacket the piece's length mixes degrees and millimetres: it
    // only spreads the share over the chords of one move).
    while (move.chord < move.chords.size()) {
        const ToolChord& chord = move.chords[move.chord];
        const double end = move.ends[move.chord];
        if (target < end) {
            const double chordLength = end - (move.chord ? move.ends[move.chord - 1] : 0.0);
            const double t = 1.0 - (end - target) / chordLength;
            const std::array<double, 3> to = between(chord.a, chord.b, t);
            if (to != move.at) removed = cutPiece(move, move.at, to) || removed;
            move.at = to;
            break;
        }
        removed = cutPiece(move, move.at, chord.b) || removed;
        if (++move.chord < move.chords.size()) move.at = move.chords[move.chord].a;
    }
    if (removed) ++revision_;
}

}  // namespace mtc::core::removal
