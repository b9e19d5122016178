#include "screens/toolpath/ToolpathModel.h"

#include <QStringList>
#include <QTimer>
#include <algorithm>

#include "cnc_core/cell/StationStatus.h"
#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/removal/PartStl.h"
#include "cnc_core/removal/ProgramStock.h"
#include "cnc_core/removal/RemovalRun.h"
#include "cnc_core/restart/ReposPreview.h"
#include "hmi/CellSession.h"
#include "screens/restart/ProgramListingModel.h"
#include "screens/restart/RestartController.h"
#include "screens/restart/RestartRun.h"
#include "screens/toolpath/ToolpathLink.h"

namespace mtc::screens {

ToolpathModel::ToolpathModel(mtc::hmi::CellSession* session, int slot,
                             std::shared_ptr<RestartController> restart,
                             std::shared_ptr<ToolpathLink> link, QObject* parent)
    : QObject(parent),
      session_(session),
      slot_(slot),
      restart_(std::move(restart)),
      link_(std::move(link)) {
    mtc::core::DiagnosticList ignored;  // the interpreter reports configuration problems
    mapping_ = std::make_unique<mtc::core::ToolpathBuilder>(
        mtc::core::ProcessAxes::build(session_->processConfig(slot_), ignored));
    stock_ = mtc::core::stockOf(session_->processConfig(slot_));
    connect(restart_.get(), &RestartController::changed, this, [this] {
        updateReposPath();
        followPartner();
        emit marksChanged();
    });
    for (auto signal : {&ToolpathLink::partnerChanged, &ToolpathLink::editorCursorChanged})
        connect(link_.get(), signal, this, [this] {
            followPartner();
            emit marksChanged();
        });
}

ToolpathModel::~ToolpathModel() = default;

void ToolpathModel::setTolerance(double millimetres) {
    if (millimetres > 0) settings_.tolerance = millimetres;
}

void ToolpathModel::refresh() {
    const int number = session_->control(slot_).selectedProgram();
    const mtc::core::ProgramPtr program = number ? session_->program(slot_, number) : nullptr;
    if (program != built_ || number != number_) build(number);
    followLiveCut();
    updateReposPath();
    followPartner();
    emit marksChanged();
}

void ToolpathModel::build(int number) {
    number_ = number;
    built_ = number ? session_->program(slot_, number) : nullptr;
    problem_.clear();
    complete_ = false;
    highlighted_.clear();
    highlightProgram_ = -1;
    currentMove_ = -1;
    frameMove_ = -1;
    frameProgram_ = -1;
    if (!built_) {
        geometry_.reset();
        problem_ = number ? tr("Program %1 does not exist.").arg(number)
                          : tr("No program is selected: select one in the program directory.");
        emit geometryChanged();
        return;
    }
    auto result = mtc::core::buildToolpath(session_->processConfig(slot_), session_->store(),
                                           number, settings_);
    complete_ = result.complete;
    for (const auto& d : result.diagnostics.items())
        if (d.severity == mtc::core::Severity::Error) {
            problem_ = RestartController::describe(d);
            break;
        }
    // The program's drawing window is the stock when it has one (TP-008).
    programStock_ =
        std::make_shared<const mtc::core::removal::ProgramStock>(mtc::core::removal::programStock(
            session_->processConfig(slot_), session_->store(), number));
    stock_ = programStock_->stock;
    if (problem_.isEmpty() && programStock_->diagnostics.hasErrors())
        problem_ = RestartController::describe(programStock_->diagnostics.items().front());
    geometry_ = std::make_shared<const mtc::core::ToolpathGeometry>(std::move(result.geometry));
    cutting_ = {geometry_->cuttingBounds(false), geometry_->cuttingBounds(true)};
    part_ = {};
    partSimulated_ = false;
    if (built_->blocks.size() <= kPartBlocks)
        simulatePart();
    else
        part_.note = tr("Finished part not simulated (over %1 blocks): key M").arg(kPartBlocks);
    emit geometryChanged();
}

void ToolpathModel::simulatePart() {
    partSimulated_ = true;
    const bool turning = session_->processConfig(slot_).defaultPlane() == 18;  // as PartModel
    // 0.2 mm as mtc200-cli simulate, coarser where the stock would need
    // more cells than the view draws quickly.
    const mtc::core::removal::RemovalSettings settings =
        mtc::core::removal::fittingSettings(stock_, turning, mtc::core::removal::kViewCells);
    const auto run = mtc::core::removal::simulateRemoval(
        session_->processConfig(slot_), session_->store(), number_, *programStock_, settings);
    if (!run.part) {
        QString why = tr("no stock");
        for (const auto& d : run.diagnostics.items())
            if (d.severity == mtc::core::Severity::Error) {
                why = RestartController::describe(d);
                break;
            }
        part_.note = tr("No finished part: %1").arg(why);
        return;
    }
    if (!(run.part->removedVolume() > 0.0)) {  // an uncut block would only hide the path
        part_.note = tr("Finished part: the program removes nothing from the stock");
        return;
    }
    part_.triangles = mtc::core::removal::partTriangles(*run.part);
    part_.heightField = run.part->heightField() != nullptr;
    // Plain digits as everywhere on the panel: "69,471" would read as a
    // decimal fraction in the German panel.
    part_.note = tr("Finished part: %1 mm³ removed at %2 mm")
                     .arg(QString::number(run.part->removedVolume(), 'f', 0))
                     .arg(QString::number(settings.resolution));
}

void ToolpathModel::followLiveCut() {
    const mtc::core::Station& station = session_->station(slot_);
    const mtc::core::removal::LiveCut& cut = station.liveCut();
    const bool live = geometry_ && cut.run() != 0 && cut.program() == number_ && cut.part();
    if (!live) {
        if (showingLive_) {  // a restart, another program: the finished part again
            showingLive_ = false;
            emit partChanged();
        }
        return;
    }
    const bool newRun = cut.run() != liveRun_;
    const bool moving = station.busy();
    if (!newRun && cut.revision() == liveRevision_ && showingLive_ && moving == liveMoving_) return;
    // The whole part is meshed again: while the axes move not more often
    // than every kLiveMeshMs, and once more when they have stopped.
    if (!newRun && moving && liveMeshed_.isValid() && liveMeshed_.elapsed() < kLiveMeshMs) {
        if (!liveFollowPending_) {
            liveFollowPending_ = true;
            QTimer::singleShot(kLiveMeshMs - static_cast<int>(liveMeshed_.elapsed()), this, [this] {
                liveFollowPending_ = false;
                followLiveCut();
            });
        }
        return;
    }
    liveRun_ = cut.run();
    liveRevision_ = cut.revision();
    liveMeshed_.start();
    liveMoving_ = moving;
    showingLive_ = true;
    meshLivePart(cut, moving);
    emit partChanged();
}

void ToolpathModel::meshLivePart(const mtc::core::removal::LiveCut& cut, bool moving) {
    const mtc::core::removal::PartModel& part = *cut.part();
    livePart_.triangles = mtc::core::removal::partTriangles(part);
    livePart_.heightField = part.heightField() != nullptr;
    const QString removed = QString::number(part.removedVolume(), 'f', 0);
    const QString resolution = QString::number(part.resolution());
    if (cut.fromRestart())  // the part at the target, cut on by ADJUST, REPOS and the run
        livePart_.note = tr("Part from the restart's target block on: %1 mm³ removed at %2 mm")
                             .arg(removed, resolution);
    else if (cut.cutOnByHand())  // MDI entries or jogs after the run (TP-028)
        livePart_.note = tr("Part of the run, cut on by MDI and jogging: %1 mm³ removed at %2 mm")
                             .arg(removed, resolution);
    else if (moving)
        livePart_.note = tr("Part being cut: %1 mm³ removed at %2 mm").arg(removed, resolution);
    else
        livePart_.note =
            tr("Part as the run left it: %1 mm³ removed at %2 mm").arg(removed, resolution);
}

void ToolpathModel::togglePart() {
    if (!geometry_) return;
    if (!partSimulated_ && !showingLive_) {  // a large program: the key asks for it
        partShown_ = true;
        simulatePart();
    } else {
        partShown_ = !partShown_;
    }
    emit partChanged();
}

mtc::core::ToolpathBounds ToolpathModel::frame(bool developed, bool all) const {
    if (!geometry_) return {};
    const mtc::core::ToolpathBounds& everything =
        developed ? geometry_->developed.bounds : geometry_->scene.bounds;
    mtc::core::ToolpathBounds box = cutting_[developed ? 1 : 0];
    if (all || box.empty) box = everything;
    if (!developed) {  // the restart's marks and REPOS path are always in view
        const ToolpathMarks m = marks();
        for (const auto& [shown, p] :
             {std::pair{m.hasStart, m.start}, std::pair{m.hasTarget, m.target},
              std::pair{m.hasReentry, m.reentry}})
            if (shown) box.add(p[0], p[1], p[2]);
        for (const auto& p : m.repos)
            box.add(p[0], p[1], p[2]);
    }
    std::array<double, 3> low{}, high{};
    if (!developed && stock_.box(low, high)) {
        box.add(low[0], low[1], low[2]);
        box.add(high[0], high[1], high[2]);
    }
    return box;
}

QString ToolpathModel::summary() const {
    if (!geometry_) return problem_;
    QString text = QString("P%1").arg(number_);
    if (built_ && !built_->title.empty()) text += " " + QString::fromStdString(built_->title);
    text += " · " + tr("%1 moves · %2 segments · tolerance %3 mm")
                        .arg(geometry_->moves.size())
                        .arg(geometry_->scene.segmentCount() + geometry_->developed.segmentCount())
                        .arg(geometry_->tolerance);
    if (geometry_->cylinderAxis >= 0)
        text += " · " + tr("G32 RI %1: developed plane | cylinder").arg(geometry_->cylinderRadius);
    if (geometry_->truncated) text += " · " + tr("path cut at the segment limit");
    if (!complete_) text += " · " + tr("program end not reached");
    return text;
}

std::array<double, 3> ToolpathModel::firstPointOf(int program, std::uint32_t block,
                                                  bool& found) const {
    found = false;
    if (!geometry_) return {};
    const auto& g = *geometry_;
    // The first move of the block (or, for a block without motion, the first
    // move after it in the same program): where the tool is when it starts.
    for (std::size_t m = 0; m < g.moves.size(); ++m) {
        if (g.moves[m].program != program || g.moves[m].block < block) continue;
        const auto [first, last] = g.sceneRange(m);
        if (first == last) continue;
        found = true;
        return g.scene.vertex(g.scene.segmentStart[first]);
    }
    return {};
}

long ToolpathModel::moveAtOrAfter(int program, std::uint32_t block) const {
    if (!geometry_) return -1;
    const auto& moves = geometry_->moves;
    for (std::size_t m = 0; m < moves.size(); ++m)
        if (moves[m].program == program && moves[m].block >= block) return static_cast<long>(m);
    return -1;
}

mtc::core::ToolpathFrame ToolpathModel::workFrame() const {
    if (highlightRunning_)
        if (const mtc::core::RunTrace* run = trace()) {
            const long move = run->currentMove();
            if (move >= 0) return run->geometry().frameOf(static_cast<std::size_t>(move));
        }
    if (!geometry_ || geometry_->moves.empty()) return {};
    const std::size_t move =
        frameMove_ >= 0 ? static_cast<std::size_t>(frameMove_) : geometry_->moves.size() - 1;
    return geometry_->frameOf(move);
}

QString ToolpathModel::axisTitle(int axis) const {
    static const char* const letters[] = {"X", "Y", "Z"};
    const QString letter = letters[std::clamp(axis, 0, 2)];
    const mtc::core::ToolpathFrame frame = workFrame();
    if (axis == frame.radialAxis && frame.diameter)  // G16 (TP-020)
        return QString("%1 (mm, \u00d8, G%2)").arg(letter).arg(frame.code);
    if (axis == frame.radialAxis && turning())  // a turner reads a radius only when told
        return tr("%1 (mm, radius, G%2)").arg(letter).arg(frame.code);
    return QString("%1 (mm, G%2)").arg(letter).arg(frame.code);
}

bool ToolpathModel::turning() const {
    return session_->processConfig(slot_).defaultPlane() == 18;  // as PartModel
}

QString ToolpathModel::frameCaption() const {
    if (!geometry_) return {};
    const mtc::core::ToolpathFrame frame = workFrame();
    if (frame.code < 54) return tr("Machine coordinates (G53, no zero offset)");
    static const char* const letters[] = {"X", "Y", "Z"};
    QStringList zero;
    for (int i = 0; i < 3; ++i)
        if (mapping_->machineAxisOfScene(i) >= 0)
            zero << QString("%1%2")
                        .arg(letters[i])
                        .arg(frame.offset[static_cast<std::size_t>(i)], 0, 'f', 3);
    return tr("Workpiece coordinates G%1,\nzero point at machine %2")
        .arg(frame.code)
        .arg(zero.join(' '));
}

ToolpathMarks ToolpathModel::marks() const {
    ToolpathMarks marks;
    const auto& pointer = restart_->pointer();
    if (restart_->accepted().ok) {
        const auto& accepted = restart_->accepted();
        marks.start =
            firstPointOf(accepted.start.block.program, accepted.start.block.block, marks.hasStart);
        marks.target = firstPointOf(accepted.selection.target.program,
                                    accepted.selection.target.block, marks.hasTarget);
    } else if (pointer.active()) {
        if (const auto start = pointer.startBlock())
            marks.start = firstPointOf(start->block.program, start->block.block, marks.hasStart);
        marks.target = firstPointOf(pointer.current().program->number, pointer.current().cursor,
                                    marks.hasTarget);
    }
    const auto& reentry = restart_->run()->sequence().reentry();
    if (reentry.valid) {
        marks.hasReentry = true;
        marks.reentry = mapping_->scenePoint(reentry.machine);
    }
    if (reposPath_.size() >= 2) {
        marks.hasRepos = true;
        marks.actual = reposPath_.front();
        marks.repos = reposPath_;
        if (const auto& check = restart_->collisions().result())
            for (const auto& collision : check->collisions)
                marks.collisions.push_back(collision.scene);
    }
    markTool(marks);
    return marks;
}

void ToolpathModel::markTool(ToolpathMarks& marks) const {
    const mtc::core::Station& station = session_->station(slot_);
    const mtc::core::StationStatus status = mtc::core::describeStation(station, 0);
    std::array<double, mtc::core::kMaxAxes> machine{};
    for (const mtc::core::AxisStatus& axis : status.axes)
        if (axis.index >= 0 && axis.index < mtc::core::kMaxAxes)
            machine[static_cast<std::size_t>(axis.index)] = axis.machine;
    marks.hasTool = true;
    marks.tool = mapping_->scenePoint(machine);
    marks.toolRadius = status.edgeKnown ? status.edgeRadius : 0.0;
    marks.toolLength = status.edgeKnown ? status.edgeLength[0] : 0.0;
    marks.turning = turning();
}

void ToolpathModel::updateReposPath() {
    reposPath_.clear();
    const auto& live = session_->interpreter(slot_);
    const auto start = mtc::core::reposPreviewStart(restart_->run()->sequence(), live);
    if (!start) return;  // not between the target reached and the re-entry
    const auto preview = mtc::core::previewRepositioning(
        session_->processConfig(slot_), session_->store(), live.machineData(), *start);
    // The path starts where the simulated machine stands (the interpreter's
    // commanded position when it has not caught up yet).
    std::array<double, mtc::core::kMaxAxes> actual{};
    for (int a = 0; a < live.axes().count() && a < mtc::core::kMaxAxes; ++a)
        actual[static_cast<std::size_t>(a)] = restart_->run()->actualPosition(a);
    reposPath_.push_back(mapping_->scenePoint(actual));
    for (const auto& corner : preview.corners) {
        const auto point = mapping_->scenePoint(corner);
        if (reposPath_.empty() || point != reposPath_.back()) reposPath_.push_back(point);
    }
}

QString ToolpathModel::partnerName() const {
    return link_->partner() == ToolpathLink::Partner::Editor ? tr("editor") : tr("restart");
}

const mtc::core::RunTrace* ToolpathModel::trace() const {
    const mtc::core::RunTrace& trace = session_->station(slot_).runTrace();
    if (!geometry_ || trace.run() == 0 || trace.program() != number_) return nullptr;
    return &trace;
}

ToolpathBackplot ToolpathModel::backplot(bool developed) const {
    ToolpathBackplot backplot;
    const mtc::core::RunTrace* run = trace();
    if (!run) return backplot;
    const mtc::core::ToolpathGeometry& g = run->geometry();
    const mtc::core::ToolpathLayer& layer = developed ? g.developed : g.scene;
    const mtc::core::TracedExtent extent = run->extent(developed);
    backplot.layer = &layer;
    backplot.segments =
        std::min<std::uint32_t>(extent.segments, static_cast<std::uint32_t>(layer.segmentCount()));
    backplot.run = run->run();
    backplot.revision = run->revision();
    if (extent.share > 0.0 && backplot.segments < layer.segmentCount()) {
        const std::uint32_t v = layer.segmentStart[backplot.segments];
        backplot.partial = true;
        backplot.partialFrom = layer.vertex(v);
        const auto to = layer.vertex(v + 1);
        for (std::size_t i = 0; i < 3; ++i)
            backplot.partialTo[i] =
                backplot.partialFrom[i] + (to[i] - backplot.partialFrom[i]) * extent.share;
    }
    return backplot;
}

bool ToolpathModel::followRunningBlock() {
    if (!session_->control(slot_).programActive()) return false;
    const mtc::core::RunTrace* run = trace();
    const long move = run ? run->currentMove() : -1;
    if (move < 0 || static_cast<std::size_t>(move) >= run->geometry().moves.size()) return false;
    const mtc::core::ToolpathMove& m = run->geometry().moves[static_cast<std::size_t>(move)];
    setHighlight(m.program, m.block);
    return true;
}

void ToolpathModel::followPartner() {
    // The running block wins over the linked screen's cursor (TP-017).
    highlightRunning_ = followRunningBlock();
    if (highlightRunning_) return;
    if (link_->partner() == ToolpathLink::Partner::Editor)
        followEditorCursor();
    else
        followRestartCursor();
}

void ToolpathModel::followEditorCursor() {
    const int number = link_->editorProgram();
    const auto program = number ? session_->program(slot_, number) : nullptr;
    if (!program || program->blocks.empty()) return;
    // The block the cursor line belongs to: the last one starting on or
    // before it (continuation and comment lines belong to the block above).
    const auto& blocks = program->blocks;
    const long line = link_->editorLine();
    std::size_t low = 0, high = blocks.size();  // first block starting after the line
    while (low < high) {
        const std::size_t middle = (low + high) / 2;
        if (static_cast<long>(blocks[middle].line) <= line)
            low = middle + 1;
        else
            high = middle;
    }
    const std::size_t index = low == 0 ? 0 : low - 1;
    setHighlight(number, static_cast<std::uint32_t>(index));
}

void ToolpathModel::followRestartCursor() {
    const auto& pointer = restart_->pointer();
    if (pointer.active() && !restart_->run()->active())
        setHighlight(pointer.current().program->number, pointer.current().cursor);
    else if (session_->control(slot_).programActive()) {
        const auto& state = session_->interpreter(slot_).state();
        if (state.program) setHighlight(state.program->number, state.block);
    }
}

void ToolpathModel::setHighlight(int program, std::uint32_t block) {
    if (program == highlightProgram_ && block == highlightBlock_ && !highlighted_.empty()) return;
    highlightProgram_ = program;
    highlightBlock_ = block;
    highlighted_ =
        geometry_ ? geometry_->movesOfBlock(program, block) : std::vector<std::uint32_t>{};
    if (!highlighted_.empty()) currentMove_ = static_cast<long>(highlighted_.front());
    if (program != frameProgram_ || block != frameBlock_) {  // one search per block
        frameProgram_ = program;
        frameBlock_ = block;
        frameMove_ = highlighted_.empty() ? moveAtOrAfter(program, block)
                                          : static_cast<long>(highlighted_.front());
    }
    highlightText_.clear();
    if (const auto p = session_->program(slot_, program); p && block < p->blocks.size()) {
        const std::string id = p->blockId(block);
        highlightText_ = tr("P%1 %2 (line %3)")
                             .arg(program)
                             .arg(QString::fromStdString(id.empty() ? "-" : id))
                             .arg(p->blocks[block].line);
    }
}

void ToolpathModel::showInRestartListing(int program, std::uint32_t block) {
    const auto& pointer = restart_->pointer();
    if (!pointer.active() || restart_->run()->active() ||
        pointer.current().program->number != program)
        return;  // the restart screen shows another program (or runs): its cursor stays
    restart_->clickRow(restart_->listing()->rowOfBlock(block));
}

void ToolpathModel::pick(long move) {
    if (!geometry_ || move < 0 || static_cast<std::size_t>(move) >= geometry_->moves.size()) return;
    const auto& m = geometry_->moves[static_cast<std::size_t>(move)];
    setHighlight(m.program, m.block);
    highlightRunning_ = false;  // until the running program's next step (TP-017)
    currentMove_ = move;
    frameMove_ = move;  // this execution of the block: its zero offset (TP-019)
    if (link_->partner() == ToolpathLink::Partner::Editor) {
        const auto program = session_->program(slot_, m.program);
        if (program && m.block < program->blocks.size())
            link_->requestEditorLine(m.program, program->blocks[m.block].line);
    } else {
        restart_->preselect(m.program, m.block);
        showInRestartListing(m.program, m.block);
    }
    emit blockPicked(m.program, m.block);
    emit marksChanged();
}

void ToolpathModel::step(int direction) {
    if (!geometry_ || geometry_->moves.empty()) return;
    const long move = currentMove_ + (direction > 0 ? 1 : -1);
    const long last = static_cast<long>(geometry_->moves.size()) - 1;
    pick(std::max(0L, std::min(move, last)));
}

}  // namespace mtc::screens
