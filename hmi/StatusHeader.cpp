#include "hmi/StatusHeader.h"

#include <QGridLayout>
#include <QLabel>

#include "cnc_core/cell/StationStatus.h"
#include "hmi/CellSession.h"
#include "hmi/CoreTerms.h"

namespace mtc::hmi {

namespace {
QLabel* makeLabel(QWidget* parent, const char* name) {
    auto* label = new QLabel(parent);
    label->setObjectName(name);
    label->setTextInteractionFlags(Qt::NoTextInteraction);
    return label;
}

/// setStyleSheet polishes and repaints the label even when the sheet is the
/// same. The header is shown at every tick of a running program, and with
/// the toolpath screen's OpenGL view in the window every repaint of any
/// widget composes the whole window again (on llvmpipe: about half of the
/// panel's CPU while a program ran, TP-029).
void setStyleOf(QLabel* label, const QString& sheet) {
    if (label->styleSheet() != sheet) label->setStyleSheet(sheet);
}
}  // namespace

StatusHeader::StatusHeader(QWidget* parent) : QWidget(parent) {
    setObjectName("statusHeader");
    setAttribute(Qt::WA_StyledBackground, true);
    station_ = makeLabel(this, "headerStation");
    mode_ = makeLabel(this, "headerMode");
    program_ = makeLabel(this, "headerProgram");
    screen_ = makeLabel(this, "headerScreen");
    speed_ = makeLabel(this, "headerSpeed");
    alarm_ = makeLabel(this, "headerAlarm");
    alarm_->setWordWrap(true);
    auto* grid = new QGridLayout(this);
    grid->setContentsMargins(6, 3, 6, 3);
    grid->addWidget(station_, 0, 0);
    grid->addWidget(mode_, 0, 1);
    grid->addWidget(program_, 0, 2);
    grid->addWidget(speed_, 0, 3);
    grid->addWidget(screen_, 0, 4, Qt::AlignRight);
    grid->addWidget(alarm_, 1, 0, 1, 5);
    QFont bold = station_->font();
    bold.setBold(true);
    station_->setFont(bold);
    screen_->setFont(bold);
}

void StatusHeader::show(const CellSession& session, int slot, const QString& title) {
    const auto& control = session.control(slot);
    const auto& process = session.processConfig(slot);
    station_->setText(
        tr("Station %1: %2").arg(process.index).arg(QString::fromStdString(process.name)));
    mode_->setText(tr("Mode: %1").arg(modeLabel(control.mode())));
    QString program = control.selectedProgram() == 0
                          ? tr("Program: none")
                          : tr("Program: %1").arg(control.selectedProgram());
    if (!control.currentBlock().empty())
        program += "  " + tr("Block: %1").arg(QString::fromStdString(control.currentBlock()));
    const QString state = programStateLabel(mtc::core::programStateOf(session.station(slot)));
    if (!state.isEmpty()) program += QString("  (%1)").arg(state);
    program_->setText(program);
    screen_->setText(title);
    speed_->setText(tr("Speed %1").arg(session.speedText()));
    // An alarm says what went wrong; a prompt what the operator does next
    // in an ordinary state (single block, programmed stop): not an alarm.
    const QString alarm = QString::fromStdString(control.alarm());
    const QString prompt = QString::fromStdString(control.prompt());
    if (!alarm.isEmpty()) {
        alarm_->setText(tr("Alarm: %1").arg(alarm));
        setStyleOf(alarm_, "color: #ffd000; font-weight: bold;");
    } else if (!prompt.isEmpty()) {
        alarm_->setText(prompt);
        setStyleOf(alarm_, "color: #b8e0ff; font-weight: normal;");
    } else {
        alarm_->setText(tr("No alarm"));
        setStyleOf(alarm_, QString());
    }
}

}  // namespace mtc::hmi
