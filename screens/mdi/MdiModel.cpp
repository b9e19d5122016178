#include "screens/mdi/MdiModel.h"

#include "cnc_core/cell/StationStatus.h"
#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/mdi/MdiEntry.h"
#include "hmi/CellSession.h"
#include "hmi/CoreTerms.h"

namespace mtc::screens {

namespace {

QString format(double value) {
    return QString::number(value, 'f', 3);
}

}  // namespace

MdiModel::MdiModel(mtc::hmi::CellSession* session, int slot, QObject* parent)
    : QObject(parent), session_(session), slot_(slot) {
    connect(session_, &mtc::hmi::CellSession::processChanged, this, [this](int changed) {
        if (changed == slot_) emit this->changed();
    });
}

const mtc::core::MdiSession& MdiModel::mdi() const {
    return session_->station(slot_).mdi();
}

QString MdiModel::input() const {
    return QString::fromStdString(mdi().input());
}

void MdiModel::setInput(const QString& text) {
    if (text == input()) return;
    session_->station(slot_).setMdiInput(text.toStdString());
    emit changed();
}

bool MdiModel::check() {
    const bool ok = session_->station(slot_).checkMdi();
    session_->announceChanges();  // the error window takes the refusals from the log
    return ok;
}

bool MdiModel::recall(int row) {
    if (row < 0) return false;
    const bool ok = session_->station(slot_).recallMdi(static_cast<std::size_t>(row));
    session_->announceChanges();
    return ok;
}

const std::deque<mtc::core::MdiHistoryItem>& MdiModel::history() const {
    return mdi().history();
}

QString MdiModel::message() const {
    return QString::fromStdString(mdi().message());
}

bool MdiModel::messageIsError() const {
    return mdi().messageIsError();
}

QString MdiModel::modeSummary() const {
    const auto& control = session_->control(slot_);
    const std::string refusal = mtc::core::mdiRefusal(control);
    if (session_->station(slot_).mdiRunning())
        return control.programHeld() ? tr("MDI entry held: Start continues")
                                     : tr("MDI entry running");
    if (refusal.empty()) return tr("MDI mode: Start runs the input");
    if (control.mode() != mtc::core::OperatingMode::Mdi) {
        QString mode = mtc::hmi::modeLabel(control.mode());
        mode[0] = mode[0].toUpper();
        return tr("%1 mode: Start does not run this input; select MDI mode with the M key MDI "
                  "(Shift+F9)")
            .arg(mode);
    }
    return QString::fromStdString(refusal);
}

bool MdiModel::showsRunningBlock() const {
    return session_->station(slot_).executingBlockState() != nullptr;
}

QString MdiModel::positionSummary() const {
    const mtc::core::Station& station = session_->station(slot_);
    QStringList parts;
    if (showsRunningBlock()) {
        // The interpreter is the look-ahead ahead: show where the axes are,
        // as the base screen does, not where the interpreter has got to.
        for (const mtc::core::AxisStatus& axis : mtc::core::describeStation(station, 0).axes)
            parts << QString("%1 %2").arg(QString::fromStdString(axis.name)).arg(format(axis.work));
        return parts.join("   ");
    }
    auto& interpreter = session_->interpreter(slot_);
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
    const mtc::core::ModalState& modal = mtc::core::shownModalState(session_->station(slot_));
    const auto& g = modal.g;
    QStringList parts;
    for (int group :
         {mtc::core::kGroupInterpolation, mtc::core::kGroupPlane, mtc::core::kGroupDimension,
          mtc::core::kGroupFeedType, mtc::core::kGroupZeroOffset, mtc::core::kGroupToolPath})
        parts << QString("G%1").arg(g[static_cast<std::size_t>(group)]);
    parts << QString("F%1").arg(modal.feed) << QString("S%1").arg(modal.spindleSpeed[1])
          << QString("T%1").arg(modal.tool);
    return parts.join("  ");
}

}  // namespace mtc::screens
