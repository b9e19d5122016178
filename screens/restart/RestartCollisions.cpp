#include "screens/restart/RestartCollisions.h"

#include "cnc_core/cell/Station.h"
#include "hmi/CellSession.h"
#include "hmi/PanelLanguage.h"

namespace mtc::screens {

RestartCollisions::RestartCollisions(mtc::hmi::CellSession* session, int slot)
    : session_(session), slot_(slot) {}

void RestartCollisions::check() {
    mtc::core::Station& station = session_->station(slot_);
    // The resolution `mtc200-cli restart --check-collisions` uses by default:
    // the panel and the CLI list the same collisions.
    result_ = station.checkReentry();
}

QString RestartCollisions::summary() const {
    if (!result_) return {};
    if (!result_->checked) {
        QString why = tr("the part at the target could not be made");
        for (const auto& d : result_->diagnostics.items())
            if (d.code.rfind("REMOVAL_", 0) == 0) {
                why = hmi::coreMessageLine(d);
                break;
            }
        return tr("Way back not checked against the part: %1").arg(why);
    }
    if (result_->collisions.empty())
        return tr("Way back clear: ADJUST/REPOS moves checked against the part: %1")
            .arg(result_->moves);
    return tr("ADJUST/REPOS moves that collide with the part: %1 of %2; the first: %3, %4 at %5. "
              "Check the way back before Start.")
        .arg(result_->collisions.size())
        .arg(result_->moves)
        .arg(where(0), what(0), position(0));
}

QString RestartCollisions::where(std::size_t index) const {
    const auto& c = result_->collisions.at(index);
    QString text =
        (c.repos ? QString("REPOS") : QString("ADJUST")) +
        QString(" P%1 %2").arg(c.where.program).arg(QString::fromStdString(c.where.block));
    if (c.where.line > 0) text += " " + tr("(line %1)").arg(c.where.line);
    return text;
}

QString RestartCollisions::what(std::size_t index) const {
    return result_->collisions.at(index).rapid ? tr("rapid move touches the part")
                                               : tr("feed move cuts the part");
}

QString RestartCollisions::position(std::size_t index) const {
    const auto& c = result_->collisions.at(index);
    const mtc::core::Interpreter& live = session_->station(slot_).interpreter();
    const mtc::core::ProcessAxes& axes = live.axes();
    QStringList parts;
    for (int i = 0; i < axes.count() && i < mtc::core::kMaxAxes; ++i) {
        const mtc::core::AxisModel& axis = axes.axis(i);
        if (axis.spindle) continue;  // spindles and rotary axes on a spindle: not a place
        parts << QString::fromStdString(live.axisName(i)) +
                     QString::number(c.position[static_cast<std::size_t>(i)], 'f', 3);
    }
    return tr("%1 (machine)").arg(parts.join(' '));
}

}  // namespace mtc::screens
