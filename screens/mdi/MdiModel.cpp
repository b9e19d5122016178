#include "screens/mdi/MdiModel.h"

#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/mdi/MdiEntry.h"
#include "hmi/CellSession.h"
#include "hmi/ProgramWorkspace.h"

namespace mtc::screens {

using mtc::hmi::ErrorEntry;
using mtc::hmi::ErrorOrigin;

namespace {

ErrorEntry entryOf(const mtc::core::Diagnostic& d, const QString& text) {
    ErrorEntry entry;
    entry.origin = ErrorOrigin::Mdi;
    entry.warning = d.severity == mtc::core::Severity::Warning;
    entry.block = QString::fromStdString(d.where.block);
    entry.line = d.where.line;
    entry.code = QString::fromStdString(d.code);
    entry.message = QString::fromStdString(d.message);
    const QStringList lines = text.split('\n');
    if (d.where.line > 0 && d.where.line <= lines.size())
        entry.details
            << QString("MDI input line %1: %2").arg(d.where.line).arg(lines[d.where.line - 1]);
    for (const std::string& detail : d.details)
        if (detail.rfind("MDI input: ", 0) != 0) entry.details << QString::fromStdString(detail);
    return entry;
}

QString format(double value) {
    return QString::number(value, 'f', 3);
}

}  // namespace

MdiModel::MdiModel(mtc::hmi::CellSession* session, int slot,
                   std::shared_ptr<mtc::hmi::ProgramWorkspace> workspace, QObject* parent)
    : QObject(parent), session_(session), slot_(slot), workspace_(std::move(workspace)) {
    auto& station = session_->station(slot_);
    station.setMdiSource([this](mtc::core::ProgramPtr& program) { return provide(program); });
    station.setMdiEnded([this](bool completed) { ended(completed); });
    connect(session_, &mtc::hmi::CellSession::processChanged, this, [this](int changed) {
        if (changed == slot_) emit this->changed();
    });
}

MdiModel::~MdiModel() {
    session_->station(slot_).setMdiSource({});
    session_->station(slot_).setMdiEnded({});
}

void MdiModel::setInput(const QString& text) {
    if (text == input_) return;
    input_ = text;
    emit changed();
}

bool MdiModel::check() {
    const auto entry = mtc::core::prepareMdiEntry(input_.toStdString(), workspace_->globalMacros());
    if (!entry.runnable()) {
        report(entry.diagnostics, input_);
        return false;
    }
    QString expanded;
    for (const std::string& line : entry.expanded)
        expanded += (expanded.isEmpty() ? "" : " | ") + QString::fromStdString(line).trimmed();
    setMessage("Input correct: " + expanded, false);
    return true;
}

bool MdiModel::recall(int row) {
    if (row < 0 || row >= history_.size()) return false;
    input_ = history_[row].text;
    setMessage(QString("Entry %1 recalled: Start runs it").arg(row + 1), false);
    return true;
}

std::string MdiModel::provide(mtc::core::ProgramPtr& program) {
    const auto entry = mtc::core::prepareMdiEntry(input_.toStdString(), workspace_->globalMacros());
    if (!entry.runnable()) {
        report(entry.diagnostics, input_);
        for (const auto& d : entry.diagnostics.items())
            if (d.severity == mtc::core::Severity::Error) return mtc::core::formatMdiDiagnostic(d);
        return "MDI: the input cannot run";
    }
    program = entry.program;
    running_ = input_;
    history_.push_back({input_, "running"});
    if (history_.size() > kMaxHistory) history_.removeFirst();
    setMessage("Running the MDI entry", false);
    return {};
}

void MdiModel::ended(bool completed) {
    const auto& diagnostics = session_->station(slot_).lastMdiDiagnostics();
    QString outcome = completed ? "done" : "reset";
    if (diagnostics.hasErrors()) {
        report(diagnostics, running_);
        for (const auto& d : diagnostics.items())
            if (d.severity == mtc::core::Severity::Error) {
                outcome = QString("error line %1: %2")
                              .arg(d.where.line)
                              .arg(QString::fromStdString(d.message));
                break;
            }
    } else if (completed) {
        setMessage("MDI entry done", false);
        if (input_ == running_) input_.clear();  // MDI-004: ready for the next entry
    } else {
        setMessage("MDI entry abandoned (Control reset)", true);
    }
    if (!history_.isEmpty() && history_.back().outcome == "running")
        history_.back().outcome = outcome;
    running_.clear();
    emit changed();
}

void MdiModel::report(const mtc::core::DiagnosticList& diagnostics, const QString& text) {
    QString first;
    for (const auto& d : diagnostics.items()) {
        workspace_->errors().add(entryOf(d, text));
        if (first.isEmpty() && d.severity == mtc::core::Severity::Error)
            first = QString::fromStdString(mtc::core::formatMdiDiagnostic(d)).section('\n', 0, 0);
    }
    setMessage(first.isEmpty() ? QString("MDI: the input cannot run") : first, true);
}

void MdiModel::setMessage(const QString& text, bool error) {
    message_ = text;
    messageIsError_ = error;
    emit changed();
}

QString MdiModel::modeSummary() const {
    const auto& control = session_->control(slot_);
    const std::string refusal = mtc::core::mdiRefusal(control);
    if (session_->station(slot_).mdiRunning())
        return control.programHeld() ? "MDI entry held: Start continues" : "MDI entry running";
    if (refusal.empty()) return "MDI mode: Start runs the input";
    if (control.mode() != mtc::core::OperatingMode::Mdi) {
        QString mode = QString::fromUtf8(mtc::core::modeName(control.mode()));
        mode[0] = mode[0].toUpper();
        return mode +
               " mode: Start does not run this input; select MDI mode with the M key MDI "
               "(Shift+F9)";
    }
    return QString::fromStdString(refusal);
}

QString MdiModel::positionSummary() const {
    auto& interpreter = session_->interpreter(slot_);
    QStringList parts;
    for (int axis = 0; axis < interpreter.axes().count(); ++axis) {
        const auto& model = interpreter.axes().axis(axis);
        if (model.spindle && !model.rotary) continue;  // a plain spindle has no position
        parts << QString("%1 %2")
                     .arg(QString::fromStdString(interpreter.axisName(axis)))
                     .arg(format(interpreter.programmedPosition(axis)));
    }
    return parts.join("   ");
}

QString MdiModel::modalSummary() const {
    const auto& state = session_->interpreter(slot_).state();
    const auto& g = state.modal.g;
    QStringList parts;
    for (int group :
         {mtc::core::kGroupInterpolation, mtc::core::kGroupPlane, mtc::core::kGroupDimension,
          mtc::core::kGroupFeedType, mtc::core::kGroupZeroOffset, mtc::core::kGroupToolPath})
        parts << QString("G%1").arg(g[static_cast<std::size_t>(group)]);
    parts << QString("F%1").arg(state.modal.feed) << QString("S%1").arg(state.modal.spindleSpeed[1])
          << QString("T%1").arg(state.modal.tool);
    return parts.join("  ");
}

}  // namespace mtc::screens
