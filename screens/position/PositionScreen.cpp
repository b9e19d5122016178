#include "screens/position/PositionScreen.h"

#include <algorithm>

#include <QFontDatabase>
#include <QFrame>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QStringList>
#include <QVBoxLayout>
#include <QWheelEvent>

#include "hmi/CellSession.h"
#include "hmi/CoreTerms.h"

namespace mtc::screens {

using mtc::core::ProgramState;

namespace {

constexpr int kAxisColumns = 4;  // name, workpiece, machine, to go

QLabel* makeLabel(QWidget* parent, const QString& name, const QFont& font) {
    auto* label = new QLabel(parent);
    label->setObjectName(name);
    label->setFont(font);
    label->setTextInteractionFlags(Qt::NoTextInteraction);
    return label;
}

QFrame* makeBox(QWidget* parent, const QString& title, QWidget* content) {
    auto* box = new QFrame(parent);
    box->setFrameShape(QFrame::StyledPanel);
    box->setStyleSheet("QFrame { background: white; }");
    auto* layout = new QVBoxLayout(box);
    layout->setContentsMargins(6, 2, 6, 2);
    layout->setSpacing(1);
    auto* heading = new QLabel(title, box);
    QFont bold = heading->font();
    bold.setBold(true);
    heading->setFont(bold);
    heading->setStyleSheet("color: #00307a;");
    layout->addWidget(heading);
    layout->addWidget(content);
    layout->addStretch();
    return box;
}

QFont fixedFont(double scale, bool bold = false) {
    QFont font = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    font.setPointSizeF(font.pointSizeF() * scale);
    font.setBold(bold);
    return font;
}

/// "+123.456": three decimals, sign always shown (positions jump sides).
QString position(double value) {
    if (value == 0.0) value = 0.0;  // no "-0.000"
    return QString::asprintf("%+.3f", value);
}

QString percent(double value) {
    return QString("%1 %").arg(value, 0, 'f', 0);
}

QString stateText(ProgramState state) {
    QString text = mtc::hmi::programStateDescription(state);
    if (!text.isEmpty()) text[0] = text[0].toUpper();
    return text;
}

/// Status colour: green running, amber held or waiting, red error.
QString stateStyle(ProgramState state) {
    switch (state) {
        case ProgramState::Running:
        case ProgramState::Restart:
            return "background: #1c7c2c; color: white;";
        case ProgramState::FeedHold:
        case ProgramState::ProgrammedStop:
        case ProgramState::SingleBlock:
        case ProgramState::WaitingForAxis:
        case ProgramState::WaitingForSps:
            return "background: #e0a800; color: black;";
        case ProgramState::Error:
            return "background: #b00000; color: white;";
        case ProgramState::NoProgram:
        case ProgramState::Ready:
            break;
    }
    return "background: #dfe6ef; color: black;";
}

}  // namespace

PositionScreen::PositionScreen(const mtc::hmi::ScreenContext& context) : Screen(context) {
    const QFont normal = fixedFont(1.0);
    auto* outer = new QVBoxLayout(this);
    outer->setContentsMargins(2, 2, 2, 2);
    outer->setSpacing(4);

    auto* top = new QHBoxLayout;
    state_ = makeLabel(this, "programState", fixedFont(1.1, true));
    state_->setMargin(2);
    blockContext_ = makeLabel(this, "blockContext", fixedFont(1.1, true));
    top->addWidget(state_, 1);
    top->addWidget(blockContext_, 1);
    outer->addLayout(top);

    auto* middle = new QHBoxLayout;
    auto* axes = new QFrame(this);
    axes->setObjectName("axisDisplay");
    axes->setFrameShape(QFrame::StyledPanel);
    axes->setStyleSheet("QFrame#axisDisplay { background: white; }");
    axisGrid_ = new QGridLayout(axes);
    axisGrid_->setHorizontalSpacing(12);
    axisGrid_->setVerticalSpacing(2);
    axisGrid_->setContentsMargins(8, 4, 8, 4);
    const QString headings[kAxisColumns] = {tr("Axis"), tr("Workpiece"), tr("Machine"),
                                            tr("To go")};
    for (int column = 0; column < kAxisColumns; ++column) {
        auto* heading = new QLabel(headings[column], axes);
        heading->setStyleSheet("color: #00307a; font-weight: bold;");
        axisGrid_->addWidget(heading, 0, column, column == 0 ? Qt::AlignLeft : Qt::AlignRight);
    }
    axisGrid_->setRowStretch(100, 1);
    jogLine_ = makeLabel(axes, "jogLine", normal);
    jogLine_->setWordWrap(true);
    jogLine_->setStyleSheet("color: #00307a;");
    jogLine_->setVisible(false);
    axisGrid_->addWidget(jogLine_, 101, 0, 1, kAxisColumns);
    middle->addWidget(axes, 3);

    auto* side = new QVBoxLayout;
    feeds_ = makeLabel(this, "feedValues", normal);
    feedOverride_ = makeLabel(this, "feedOverride", fixedFont(1.0, true));
    rapidOverride_ = makeLabel(this, "rapidOverride", fixedFont(1.0, true));
    auto* feedBox = new QWidget(this);
    auto* feedLayout = new QVBoxLayout(feedBox);
    feedLayout->setContentsMargins(0, 0, 0, 0);
    feedLayout->setSpacing(0);
    feedLayout->addWidget(feeds_);
    auto* overrides = new QHBoxLayout;  // side by side: the side column stays low
    overrides->addWidget(feedOverride_);
    overrides->addWidget(rapidOverride_);
    feedLayout->addLayout(overrides);
    side->addWidget(makeBox(this, tr("Feed and override"), feedBox));
    spindles_ = makeLabel(this, "spindleValues", normal);
    side->addWidget(makeBox(this, tr("Spindles (programmed / actual)"), spindles_));
    tool_ = makeLabel(this, "toolValues", normal);
    side->addWidget(makeBox(this, tr("Tool and edge"), tool_));
    middle->addLayout(side, 2);
    outer->addLayout(middle, 3);

    auto* bottom = new QHBoxLayout;
    blocks_ = makeLabel(this, "blockList", normal);
    blocks_->setTextFormat(Qt::RichText);
    bottom->addWidget(makeBox(this, tr("Program"), blocks_), 1);
    gFunctions_ = makeLabel(this, "gFunctions", normal);
    zeroOffset_ = makeLabel(this, "zeroOffset", normal);
    auto* modal = new QWidget(this);
    auto* modalLayout = new QVBoxLayout(modal);
    modalLayout->setContentsMargins(0, 0, 0, 0);
    modalLayout->addWidget(gFunctions_);
    modalLayout->addWidget(zeroOffset_);
    bottom->addWidget(makeBox(this, tr("Active G functions and zero offset"), modal), 1);
    outer->addLayout(bottom, 2);

    // Long block texts and offset lines are cut at the right edge instead
    // of widening the panel (the window keeps its size at 96 dpi).
    for (QLabel* label : {blocks_, gFunctions_, zeroOffset_, spindles_, tool_})
        label->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    setFocusPolicy(Qt::StrongFocus);
    connect(context.session, &mtc::hmi::CellSession::processChanged, this, [this](int slot) {
        if (slot == this->context().process && isVisible()) refresh();
    });
    refresh();
}

void PositionScreen::activated() {
    refresh();
}

void PositionScreen::showEvent(QShowEvent* event) {
    Screen::showEvent(event);
    refresh();  // changes while hidden were not drawn
}

mtc::hmi::SoftKeys PositionScreen::softKeys() {
    mtc::hmi::SoftKeys keys(8);
    if (manualMode()) {
        const double step = jogStep();
        keys[5] = {step == 0.0 ? tr("Jog step\ncontinuous")
                               : tr("Jog step\n%1").arg(step, 0, 'f', step < 1 ? 3 : 0),
                   [this] {
                       stepIndex_ =
                           stepIndex_ + 1 >= static_cast<int>(mtc::core::kJogIncrements.size())
                               ? -1
                               : stepIndex_ + 1;
                       refresh();
                       emit softKeysChanged();
                   }};
        keys[6] = {rapid_ ? tr("Rapid\non") : tr("Rapid\noff"), [this] {
                       rapid_ = !rapid_;
                       refresh();
                       emit softKeysChanged();
                   }};
    }
    keys[0] = {tr("Program\ndirectory"), [this] { emit navigateTo("programs"); }};
    keys[1] = {tr("Error\ndisplay"), [this] { emit navigateTo("errors"); }};
    keys[2] = {tr("MDI"), [this] { emit navigateTo("mdi"); }};
    keys[3] = {tr("Toolpath"), [this] { emit navigateTo("toolpath"); }};
    keys[4] = {tr("NC program\nrestart"), [this] { emit navigateTo("restart"); }};
    keys[7] = {tr("Main menu"), [this] { emit navigateTo("menu"); }};
    return keys;
}

void PositionScreen::refresh() {
    const auto& station = context().session->station(context().process);
    status_ = mtc::core::describeStation(station);
    showAxes();
    showFeedsAndSpindles();
    showModal();
    showBlocks();
    state_->setText(stateText(status_.state));
    state_->setStyleSheet(stateStyle(status_.state));
    showJogLine();
}

bool PositionScreen::manualMode() const {
    const auto& station = context().session->station(context().process);
    return station.control().mode() == mtc::core::OperatingMode::Manual;
}

int PositionScreen::jogAxis() const {
    if (status_.axes.empty()) return -1;
    const int row = std::clamp(jogRow_, 0, static_cast<int>(status_.axes.size()) - 1);
    return status_.axes[static_cast<std::size_t>(row)].index;
}

double PositionScreen::jogStep() const {
    return stepIndex_ < 0 ? 0.0 : mtc::core::kJogIncrements[static_cast<std::size_t>(stepIndex_)];
}

void PositionScreen::showJogLine() {
    const bool manual = manualMode();
    jogLine_->setVisible(manual);
    if (!manual || status_.axes.empty()) return;
    const int row = std::clamp(jogRow_, 0, static_cast<int>(status_.axes.size()) - 1);
    const double step = jogStep();
    const QString spindle =
        status_.spindles.empty()
            ? QString()
            : "\n" + tr("%1: 3 / 4 / 5 = M3 / M4 / M5, PgUp / PgDn = speed ±100 rpm")
                         .arg(QString::fromStdString(status_.spindles.front().name));
    jogLine_->setText(
        tr("Manual: jog %1 with + / − (↑/↓ axis), %2%3; wheel = handwheel%4")
            .arg(QString::fromStdString(status_.axes[static_cast<std::size_t>(row)].name))
            .arg(step == 0.0 ? tr("continuous while held") : tr("step %1").arg(step, 0, 'f', 3))
            .arg(rapid_ ? tr(", rapid") : QString())
            .arg(spindle));
}

void PositionScreen::keyPressEvent(QKeyEvent* event) {
    if (!manualMode() || status_.axes.empty()) return Screen::keyPressEvent(event);
    auto& station = context().session->station(context().process);
    const int key = event->key();
    if (key == Qt::Key_Up || key == Qt::Key_Down) {
        const int count = static_cast<int>(status_.axes.size());
        jogRow_ = (jogRow_ + (key == Qt::Key_Down ? 1 : count - 1)) % count;
        refresh();
        return;
    }
    if (spindleKey(key)) return;
    if (key != Qt::Key_Plus && key != Qt::Key_Minus) return Screen::keyPressEvent(event);
    if (event->isAutoRepeat()) return;  // a held key is one continuous jog, not many steps
    const int direction = key == Qt::Key_Plus ? 1 : -1;
    const double step = jogStep();
    if (step == 0.0) {
        jogKeyHeld_ = station.jogStart(jogAxis(), direction, rapid_);
    } else {
        station.jogBy(jogAxis(), direction * step, rapid_);
    }
    context().session->notifyChanged(context().process);
}

bool PositionScreen::spindleKey(int key) {
    // 3 / 4 / 5: M3 / M4 / M5 of the station's first spindle; PgUp / PgDn:
    // its speed (MOT-018). The station decides what each key does.
    using mtc::core::SpindleKey;
    if (status_.spindles.empty()) return false;
    SpindleKey spindleKey = SpindleKey::Stop;  // every case below sets it or returns
    switch (key) {
        case Qt::Key_3:
            spindleKey = SpindleKey::Clockwise;
            break;
        case Qt::Key_4:
            spindleKey = SpindleKey::CounterClockwise;
            break;
        case Qt::Key_5:
            spindleKey = SpindleKey::Stop;
            break;
        case Qt::Key_PageUp:
            spindleKey = SpindleKey::Faster;
            break;
        case Qt::Key_PageDown:
            spindleKey = SpindleKey::Slower;
            break;
        default:
            return false;
    }
    auto& station = context().session->station(context().process);
    station.manualSpindleKey(status_.spindles.front().index, spindleKey);
    context().session->notifyChanged(context().process);
    return true;
}

void PositionScreen::keyReleaseEvent(QKeyEvent* event) {
    const int key = event->key();
    if (jogKeyHeld_ && !event->isAutoRepeat() && (key == Qt::Key_Plus || key == Qt::Key_Minus)) {
        jogKeyHeld_ = false;
        context().session->station(context().process).jogRelease();
        context().session->notifyChanged(context().process);
        return;
    }
    Screen::keyReleaseEvent(event);
}

void PositionScreen::wheelEvent(QWheelEvent* event) {
    const int detents = event->angleDelta().y() / 120;
    if (!manualMode() || status_.axes.empty() || detents == 0) return Screen::wheelEvent(event);
    const double step = jogStep() == 0.0 ? 0.01 : jogStep();
    context().session->station(context().process).jogBy(jogAxis(), detents * step, rapid_);
    context().session->notifyChanged(context().process);
    event->accept();
}

void PositionScreen::addAxisRow(int row) {
    const QFont large = fixedFont(1.7, true);
    const char* names[kAxisColumns] = {"axisName", "axisWork", "axisMachine", "axisToGo"};
    QVector<QLabel*> labels;
    for (int column = 0; column < kAxisColumns; ++column) {
        auto* label =
            makeLabel(axisGrid_->parentWidget(), QString("%1-%2").arg(names[column]).arg(row),
                      column == 3 ? fixedFont(1.3) : large);
        label->setAlignment(column == 0 ? Qt::AlignLeft | Qt::AlignVCenter
                                        : Qt::AlignRight | Qt::AlignVCenter);
        axisGrid_->addWidget(label, row + 1, column);
        labels.push_back(label);
    }
    axisRows_.push_back(labels);
}

void PositionScreen::showAxes() {
    const int count = static_cast<int>(status_.axes.size());
    while (axisRows_.size() < count)
        addAxisRow(axisRows_.size());
    for (int row = 0; row < axisRows_.size(); ++row) {
        const bool shown = row < count;
        for (QLabel* label : axisRows_[row])
            label->setVisible(shown);
        if (!shown) continue;
        const auto& axis = status_.axes[static_cast<std::size_t>(row)];
        const QString unit = axis.rotary ? QString("\u00b0") : QString();
        const bool jogged = row == std::clamp(jogRow_, 0, count - 1) && manualMode();
        axisRows_[row][0]->setText((jogged ? QString("\u25b8") : QString()) +
                                   QString::fromStdString(axis.name));
        axisRows_[row][1]->setText(position(axis.work) + unit);
        axisRows_[row][2]->setText(position(axis.machine) + unit);
        axisRows_[row][3]->setText(position(axis.toGo) + unit);
    }
}

void PositionScreen::showFeedsAndSpindles() {
    const QString unit = status_.feedPerRevolution ? tr("mm/rev") : QString("mm/min");
    feeds_->setText(tr("F programmed %1 %2\nF actual     %3 mm/min")
                        .arg(status_.programmedFeed, 9, 'f', status_.feedPerRevolution ? 3 : 1)
                        .arg(unit)
                        .arg(status_.actualFeed, 9, 'f', 1));
    feedOverride_->setText(tr("Override F %1").arg(percent(status_.feedOverride)));
    rapidOverride_->setText("G0 " + percent(status_.rapidOverride));
    QStringList spindles;
    for (const auto& s : status_.spindles) {
        QString line = tr("%1 %2 / %3 rpm %4")
                           .arg(QString::fromStdString(s.name))
                           .arg(s.programmed, 0, 'f', 0)
                           .arg(s.actual, 0, 'f', 0)
                           .arg(mtc::hmi::coreTerm(mtc::core::spindleTurnName(s.turn)));
        if (s.rotaryAxisMode) line += " " + tr("(rotary axis)");
        spindles << line;
    }
    spindles_->setText(spindles.isEmpty() ? tr("none") : spindles.join('\n'));
    QString tool = QString("T%1  E%2").arg(status_.tool).arg(status_.edge);
    if (status_.tool <= 0)
        tool = tr("no tool (T0)");
    else if (!status_.edgeKnown)
        tool += "  " + tr("(not in the tool list)");
    else
        tool += "  " + tr("R %1  position %5\nL1 %2  L2 %3  L3 %4")
                           .arg(status_.edgeRadius, 0, 'f', 3)
                           .arg(status_.edgeLength[0], 0, 'f', 3)
                           .arg(status_.edgeLength[1], 0, 'f', 3)
                           .arg(status_.edgeLength[2], 0, 'f', 3)
                           .arg(status_.edgeOrientation);
    tool_->setText(tool);
}

void PositionScreen::showModal() {
    QStringList cells;
    for (const auto& g : status_.gFunctions)
        cells << QString("G%1 %2").arg(g.code).arg(mtc::hmi::coreTerm(g.topic));
    // Two columns: narrow and low enough for the bottom row at 96 dpi.
    constexpr int kColumns = 2;
    QStringList lines;
    const int rows = (cells.size() + kColumns - 1) / kColumns;
    for (int row = 0; row < rows; ++row) {
        QString line;
        for (int column = 0; column < kColumns; ++column) {
            const int i = column * rows + row;
            if (i < cells.size()) line += QString("%1").arg(cells[i], -22);
        }
        lines << line.trimmed();
    }
    gFunctions_->setText(lines.join('\n'));
    QString offsets;  // three axes a line
    for (std::size_t i = 0; i < status_.axes.size() && i < status_.zeroOffsetValues.size(); ++i)
        offsets += QString(i % 3 == 0 ? "\n" : "  ") +
                   QString("%1 %2")
                       .arg(QString::fromStdString(status_.axes[i].name))
                       .arg(status_.zeroOffsetValues[i], 0, 'f', 3);
    zeroOffset_->setText(status_.zeroOffset == 53
                             ? tr("Zero offset G53 (machine coordinates)")
                             : tr("Zero offset G%1:%2").arg(status_.zeroOffset).arg(offsets));
}

void PositionScreen::showBlocks() {
    if (status_.program == 0 && status_.blocks.empty()) {
        blockContext_->setText(tr("No block"));
        blocks_->setText(QString());
        return;
    }
    QString where = status_.inLibrary ? tr("Program 99 (subroutine library)")
                                      : tr("Program %1").arg(status_.program);
    where +=
        status_.callLevel == 0 ? tr(", main level") : tr(", call level %1").arg(status_.callLevel);
    blockContext_->setText(where);
    QStringList rows;
    for (const auto& block : status_.blocks) {
        const QString text = QString::fromStdString(block.text).toHtmlEscaped();
        rows << (block.current ? QString("<span style='background:#00307a; color:white;'>"
                                         "&#9658; %1</span>")
                                     .arg(text)
                               : QString("&nbsp;&nbsp;%1").arg(text));
    }
    blocks_->setText("<pre style='margin:0'>" + rows.join('\n') + "</pre>");
}

}  // namespace mtc::screens
