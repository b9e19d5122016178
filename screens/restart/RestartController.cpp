#include "screens/restart/RestartController.h"

#include <QLocale>

#include "cnc_core/interp/Interpreter.h"
#include "hmi/CellSession.h"
#include "hmi/PanelLanguage.h"
#include "screens/restart/ProgramListingModel.h"
#include "screens/restart/RestartRun.h"
#include "screens/restart/RestartVerification.h"

namespace mtc::screens {

namespace {

/// The values the Plane+ windows show: variables of the station's (or
/// another station's) interpreter and the events of the station.
mtc::core::SearchSources stationSources(mtc::hmi::CellSession* session, int slot) {
    mtc::core::SearchSources sources;
    sources.readVariable = [session](int process, int index, double& value) {
        const int owner = session->slotOfProcess(process);
        if (owner < 0 || index < 0 || index >= mtc::core::kVariableCount) return false;
        value =
            session->interpreter(owner).state().variables.values[static_cast<std::size_t>(index)];
        return true;
    };
    sources.readEvent = [session, slot](int process, int event) {
        return session->interpreter(slot).events().get(process, event);
    };
    return sources;
}

QString programCaption(const mtc::core::Program& program) {
    QString caption = QString("P%1").arg(program.number);
    if (!program.title.empty()) caption += " " + QString::fromStdString(program.title);
    return caption;
}

}  // namespace

RestartController::RestartController(mtc::hmi::CellSession* session, int slot, QObject* parent)
    : QObject(parent),
      session_(session),
      slot_(slot),
      pointer_(session->store(), session->processConfig(slot).index, stationSources(session, slot)),
      listing_(new ProgramListingModel(this)),
      run_(new RestartRun(session, slot, this)),
      verification_(new RestartVerification(session, slot, this)),
      collisions_(session, slot) {
    connect(run_, &RestartRun::phaseChanged, this, &RestartController::phaseChanged);
    connect(run_, &RestartRun::progressed, this, &RestartController::changed);
    connect(verification_, &RestartVerification::progressed, this, [this] {
        const mtc::core::VerifyReport* report = verification_->programReport();
        const bool clean = report && report->complete && report->targets == report->reestablished;
        setMessage(verification_->running() || clean ? RestartMessage::Level::Info
                                                     : RestartMessage::Level::Warning,
                   verification_->programText());
        emit changed();
    });
}

void RestartController::verifyProgram() {
    if (run_->active() || !pointer_.active()) {
        setMessage(RestartMessage::Level::Error,
                   run_->active() ? tr("Verification refused: an NC program restart is active.")
                                  : tr("Verification refused: no program is displayed."));
        emit changed();
        return;
    }
    QString why;
    const int main = pointer_.levels().front().program->number;
    if (!verification_->startProgram(main, why)) {
        setMessage(RestartMessage::Level::Error, tr("Verification refused: %1").arg(why));
        emit changed();
    }
}

void RestartController::verifyAcceptedTarget() {
    if (!accepted_.ok) return;
    verification_->verifyTarget(accepted_.selection, run_->before());
    collisions_.check();
    emit changed();
}

RestartController::~RestartController() = default;

QString RestartController::describe(const mtc::core::Diagnostic& d) {
    QString where;
    if (d.where.program) where += QString("P%1").arg(d.where.program);
    if (!d.where.block.empty()) where += " " + QString::fromStdString(d.where.block);
    if (d.where.line) where += " " + tr("line %1").arg(d.where.line);
    const QString text = hmi::coreMessageLine(d);
    return where.isEmpty() ? text : where.trimmed() + ": " + text;
}

void RestartController::setMessage(RestartMessage::Level level, const QString& text,
                                   std::vector<mtc::core::Diagnostic> diagnostics) {
    message_ = {level, text, std::move(diagnostics)};
}

void RestartController::setErrors(const mtc::core::DiagnosticList& diagnostics) {
    QStringList reasons;
    for (const auto& d : diagnostics.items())
        reasons << describe(d);
    setMessage(RestartMessage::Level::Error, reasons.join("  "), diagnostics.items());
}

void RestartController::reply(const mtc::core::SearchReply& reply) {
    if (reply.note) {
        mtc::core::Diagnostic note = *reply.note;
        if (!reply.ok) note.severity = mtc::core::Severity::Error;  // the request was refused
        setMessage(reply.ok ? RestartMessage::Level::Warning : RestartMessage::Level::Error,
                   describe(note), {note});
    } else
        setMessage(RestartMessage::Level::None, {});
}

QString RestartController::refusalReason() const {
    const auto& control = session_->control(slot_);
    if (control.selectedProgram() == 0)
        return tr("No program is selected: select it in the program directory first.");
    if (control.mode() != mtc::core::OperatingMode::Automatic)
        return tr("NC program restart needs automatic mode (seed 000, 2.1).");
    if (control.programActive())
        return tr(
            "A program is active: stop it with Control reset before the restart (seed 000, "
            "2.1).");
    return {};
}

void RestartController::enter() {
    if (run_->active()) {  // the restart runs: show it, keep its selection
        setMessage(RestartMessage::Level::Info, phaseText());
        emit changed();
        return;
    }
    const int number = session_->control(slot_).selectedProgram();
    // The restart searches the program the station runs: the compiled one
    // when the source has compiler keywords (seed 001 ch. 10/11, C-013).
    if (!session_->control(slot_).programActive() && number > 0) {
        const std::string refused = session_->station(slot_).prepare(number);
        if (!refused.empty()) {
            listing_->setProgram(nullptr);
            setMessage(RestartMessage::Level::Error, QString::fromStdString(refused));
            emit changed();
            return;
        }
    }
    const mtc::core::SearchReply started = pointer_.begin(number);
    const int preselected = preselectedProgram_;
    preselectedProgram_ = 0;  // used by this entry
    shownProgram_ = nullptr;
    accepted_ = {};
    if (!started.ok) {
        listing_->setProgram(nullptr);
        reply(started);
    } else {
        showLevel();
        if (preselected == number)  // a toolpath pick made outside the screen wins
            clickRow(listing_->rowOfBlock(preselectedBlock_));
        const QString reason = refusalReason();
        if (reason.isEmpty())
            setMessage(
                RestartMessage::Level::Info,
                tr("Select the target block and press Enter (Plane+ follows jumps and calls)."));
        else
            setMessage(RestartMessage::Level::Warning, reason);
    }
    emit changed();
}

void RestartController::preselect(int program, std::uint32_t block) {
    preselectedProgram_ = program;
    preselectedBlock_ = block;
}

void RestartController::showLevel() {
    if (!pointer_.active()) return;
    const auto& program = pointer_.current().program;
    if (program.get() != shownProgram_) {
        listing_->setProgram(program);
        shownProgram_ = program.get();
    }
    cursorMoved();
}

void RestartController::cursorMoved() {
    if (!pointer_.active()) return;
    std::int64_t start = -1;
    if (const auto s = pointer_.startBlock();
        s && s->block.program == pointer_.current().program->number)
        start = s->block.block;
    listing_->setMarks(pointer_.current().cursor, start);
}

void RestartController::up() {
    pointer_.up();
    cursorMoved();
    emit changed();
}

void RestartController::down() {
    pointer_.down();
    cursorMoved();
    emit changed();
}

void RestartController::pageUp(int rows) {
    pointer_.pageUp(static_cast<std::uint32_t>(std::max(1, rows)));
    cursorMoved();
    emit changed();
}

void RestartController::pageDown(int rows) {
    pointer_.pageDown(static_cast<std::uint32_t>(std::max(1, rows)));
    cursorMoved();
    emit changed();
}

void RestartController::home() {
    pointer_.home();
    cursorMoved();
    emit changed();
}

void RestartController::end() {
    pointer_.end();
    cursorMoved();
    emit changed();
}

void RestartController::clickRow(int row) {
    if (!pointer_.active()) return;
    // A comment row belongs to the block after it, as in the search.
    std::uint32_t block = listing_->blockOfRow(row);
    if (row >= listing_->rowOfBlock(block) + listing_->rowsOfBlock(block)) ++block;
    pointer_.moveTo(block);
    cursorMoved();
    emit changed();
}

void RestartController::planePlus() {
    reply(pointer_.planePlus());
    const auto& window = pointer_.window();
    if (window.kind == mtc::core::PlaneWindow::Kind::Event)
        setMessage(RestartMessage::Level::Info,
                   tr("Space changes the event, Enter follows the jump, Esc aborts."));
    else if (window.kind == mtc::core::PlaneWindow::Kind::Variable)
        setMessage(RestartMessage::Level::Info,
                   tr("Enter follows the jump with the value shown (or a new one), Esc aborts."));
    showLevel();
    emit changed();
}

void RestartController::planeMinus() {
    reply(pointer_.planeMinus());
    showLevel();
    emit changed();
}

void RestartController::confirmEvent(bool set) {
    reply(pointer_.confirmEvent(set));
    showLevel();
    emit changed();
}

bool RestartController::confirmVariable(const QString& text) {
    bool isNumber = false;
    const double value = text.trimmed().toDouble(&isNumber);
    if (!isNumber) {
        setMessage(RestartMessage::Level::Error,
                   tr("'%1' is not a program number.").arg(text.trimmed()));
        emit changed();
        return false;
    }
    const auto result = pointer_.confirmVariable(value);
    reply(result);
    showLevel();
    emit changed();
    return result.ok;
}

void RestartController::cancelWindow() {
    pointer_.cancelWindow();
    setMessage(RestartMessage::Level::Info, tr("Aborted: the cursor stays where it was."));
    emit changed();
}

bool RestartController::search(const QString& text) {
    lastSearch_ = text;
    const auto result = pointer_.search(text.toStdString());
    reply(result);
    cursorMoved();
    emit changed();
    return result.ok;
}

bool RestartController::setRuns(const QString& text) {
    const auto result = pointer_.setRuns(text.toStdString());
    reply(result);
    emit changed();
    return result.ok;
}

void RestartController::toggleFromLastPrimary() {
    reply(pointer_.setFromLastPrimary(!pointer_.fromLastPrimary()));
    cursorMoved();
    emit changed();
}

bool RestartController::accept() {
    if (run_->active()) {
        setMessage(RestartMessage::Level::Error,
                   tr("An NC program restart is already active: %1").arg(phaseText()));
        emit changed();
        return false;
    }
    const QString reason = refusalReason();
    if (!reason.isEmpty()) {
        setMessage(RestartMessage::Level::Error, reason);
        emit changed();
        return false;
    }
    mtc::core::AcceptResult result = pointer_.accept();
    if (!result.ok) {
        setErrors(result.diagnostics);
        emit changed();
        return false;
    }
    mtc::core::DiagnosticList refused;
    if (!run_->start(result.selection, refused)) {
        setErrors(refused);
        emit changed();
        return false;
    }
    QStringList notes;
    for (const auto& d : result.diagnostics.items())
        notes << describe(d);
    for (const auto& d : refused.items())
        notes << describe(d);  // warnings of the NC
    accepted_ = std::move(result);
    if (notes.isEmpty())
        setMessage(RestartMessage::Level::Info, tr("Target accepted: %1").arg(phaseText()));
    else
        setMessage(RestartMessage::Level::Warning, tr("Target accepted. %1").arg(notes.join("  ")));
    emit changed();
    return true;
}

void RestartController::abort() {
    run_->abort();
}

void RestartController::phaseChanged(mtc::core::RestartPhase phase) {
    using mtc::core::RestartPhase;
    // The result review shows the verification of the target before Start;
    // on a very large program it waits for its soft key.
    constexpr std::uint64_t kAutomaticUpTo = 500'000;
    if (phase == RestartPhase::TargetReached && run_->computedBlocks() <= kAutomaticUpTo)
        verifyAcceptedTarget();
    else if (phase == RestartPhase::Active || phase == RestartPhase::Computing) {
        verification_->clearTarget();
        collisions_.clear();
    }
    // After each computing process the number of runs is 1 again (seed 000, 2.6).
    if (phase != RestartPhase::Active && phase != RestartPhase::Computing)
        pointer_.computingProcessDone();
    emit changed();
}

QString RestartController::acceptedTarget() const {
    if (!accepted_.ok) return {};
    const auto& target = accepted_.selection.target;
    const auto program = session_->store().find(pointer_.process(), target.program);
    if (!program || target.block >= program->blocks.size()) return {};
    return tr("P%1 %2 (line %3)")
        .arg(target.program)
        .arg(QString::fromStdString(program->blockId(target.block)))
        .arg(program->blocks[target.block].line);
}

namespace {

/// What the operator reads about `phase` (seed 000, Fig. 6-8).
QString describePhase(mtc::core::RestartPhase phase, const QString& blocks, double ms) {
    using mtc::core::RestartPhase;
    switch (phase) {
        case RestartPhase::Idle:
            return {};
        case RestartPhase::Active:
            return RestartController::tr(
                "NC program restart active (PxxSBPACT = 1): the SPS starts the computing "
                "process.");
        case RestartPhase::Computing:
            return RestartController::tr(
                       "Computing process: %1 blocks interpreted. F7 or Control reset aborts.")
                .arg(blocks);
        case RestartPhase::TargetReached:
            return RestartController::tr(
                       "Target block reached after %1 blocks (%2 ms). Check the result, then "
                       "Start runs ADJUST.")
                .arg(blocks)
                .arg(ms, 0, 'f', 0);
        case RestartPhase::Adjusting:
            return RestartController::tr("ADJUST establishes the machine states.");
        case RestartPhase::ManualMode:
            return RestartController::tr(
                "Manual mode: jog the axes near the re-entry point, then Automatic and Start.");
        case RestartPhase::AutomaticAgain:
            return RestartController::tr("Automatic mode again: Start continues with REPOS.");
        case RestartPhase::Repositioning:
            return RestartController::tr("REPOS moves the axes back to the re-entry point.");
        case RestartPhase::Reestablished:
            return RestartController::tr(
                "State re-established: machining continues at the target block.");
        case RestartPhase::Failed:
            return RestartController::tr("NC program restart failed.");
        case RestartPhase::Aborted:
            return RestartController::tr(
                "NC program restart aborted: every restart signal is reset.");
    }
    return {};
}

}  // namespace

QString RestartController::phaseText() const {
    if (!run_->started()) return {};
    const QString blocks = QLocale::c().toString(static_cast<qulonglong>(run_->computedBlocks()));
    QString text = describePhase(run_->phase(), blocks, run_->computingMs());
    if (run_->phase() == mtc::core::RestartPhase::Failed) {
        for (const auto& d : run_->sequence().diagnostics().items())
            if (d.severity == mtc::core::Severity::Error) {
                text += " " + describe(d);
                break;
            }
    }
    if (run_->held()) text += heldText();
    const std::string axis = run_->sequence().waitingFor();
    if (!axis.empty() && run_->phase() == mtc::core::RestartPhase::Computing)
        text += " " + tr("Waiting for another process: %1 (%2).")
                          .arg(QString::fromStdString(axis),
                               axis.rfind("FAX", 0) == 0
                                   ? tr("until it requests the axis with GAX")
                                   : tr("until it relinquishes the axis with FAX"));
    return text;
}

QString RestartController::heldText() const {
    if (!session_->control(slot_).singleBlock()) return " " + tr("Held: Start continues.");
    // Single-block mode: say which block Start interprets next.
    const mtc::core::InterpreterState& state = run_->phase() == mtc::core::RestartPhase::Computing
                                                   ? run_->sequence().computing().state()
                                                   : session_->interpreter(slot_).state();
    const QString next = state.program
                             ? QString("P%1 %2")
                                   .arg(state.program->number)
                                   .arg(QString::fromStdString(state.program->blockId(state.block)))
                             : QString("?");
    return " " + tr("Single block: held; Start interprets the next block (%1).").arg(next);
}

QString RestartController::breadcrumb() const {
    if (!pointer_.active()) return tr("No program");
    const auto& levels = pointer_.levels();
    QString text = programCaption(*levels[0].program);
    for (std::size_t i = 1; i < levels.size(); ++i) {
        const auto& caller = levels[i - 1];
        text += QString("  ▸  %1 %2  ▸  P%3 %4")
                    .arg(QString::fromStdString(caller.program->blockId(caller.cursor)),
                         QString::fromStdString(pointer_.levelCommand(i)))
                    .arg(levels[i].program->number)
                    .arg(QString::fromStdString(levels[i].program->blockId(levels[i].entry)));
    }
    return text;
}

QString RestartController::status() const {
    if (!pointer_.active()) return {};
    const auto& level = pointer_.current();
    const auto& program = *level.program;
    QString target = tr("Target P%1 %2 (line %3), program level %4")
                         .arg(program.number)
                         .arg(QString::fromStdString(program.blockId(level.cursor)))
                         .arg(program.blocks[level.cursor].line)
                         .arg(pointer_.programLevels().size());
    QString start;
    if (const auto s = pointer_.startBlock()) {
        const auto startProgram = session_->store().find(pointer_.process(), s->block.program);
        start =
            tr("start P%1 %2%3")
                .arg(s->block.program)
                .arg(startProgram ? QString::fromStdString(startProgram->blockId(s->block.block))
                                  : QString::number(s->block.block))
                .arg(s->primary ? " " + tr("(last primary block)") : QString());
    } else {
        start = tr("start: no primary block before the target");
    }
    QString text = QString("%1  ·  %2").arg(target, start);
    QStringList changes;
    for (const auto& [variable, value] : pointer_.variableChanges())
        changes << QString("@%1=%2").arg(variable).arg(value, 0, 'g', 10);
    for (const auto& [event, set] : pointer_.eventChanges())
        changes << tr("event %1:%2=%3").arg(event.process).arg(event.event).arg(set ? 1 : 0);
    if (!changes.isEmpty()) text += "  ·  " + tr("changed %1").arg(changes.join(", "));
    return text + "  ·  " + tr("runs %1").arg(pointer_.runs());
}

}  // namespace mtc::screens
