#include "hmi/MachineKeyBar.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QStyle>
#include <QVBoxLayout>
#include <QVariant>
#include <algorithm>
#include <cstdlib>

#include "hmi/CoreTerms.h"
#include "hmi/KeyMap.h"

namespace mtc::hmi {

MachineKeyBar::MachineKeyBar(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    int n = 0;
    for (mtc::core::ControlKey key : machineKeys()) {
        auto* button = new QPushButton(keyLabel(key), this);
        button->setObjectName(QString("mkey-%1").arg(++n));
        button->setToolTip(machineKeyShortcut(key).toString(QKeySequence::NativeText));
        button->setFocusPolicy(Qt::NoFocus);
        button->setMinimumSize(110, 36);
        button->setProperty("lamp", false);
        connect(button, &QPushButton::clicked, this, [this, key] { emit keyPressed(key); });
        buttons_.push_back({key, button});
        layout->addWidget(button);
    }
    layout->addStretch();
    feedOverride_ = addOverride("feedOverrideSwitch", tr("Feed override"), false);
    rapidOverride_ = addOverride("rapidOverrideSwitch", tr("Rapid override"), true);
    setOverrides(100, 100);
    speed_ = new QPushButton(this);
    speed_->setObjectName("speedKey");
    speed_->setToolTip(
        tr("%1: simulation speed").arg(speedKeyShortcut().toString(QKeySequence::NativeText)));
    speed_->setFocusPolicy(Qt::NoFocus);
    speed_->setMinimumSize(110, 32);
    connect(speed_, &QPushButton::clicked, this, &MachineKeyBar::speedPressed);
    layout->addWidget(speed_);
    setSpeedText("\u00d71");
}

QLabel* MachineKeyBar::addOverride(const QString& name, const QString& title, bool rapid) {
    // One row: the percentage, then − and + (the bar keeps the panel's
    // 900x650 minimum window).
    auto* row = new QHBoxLayout;
    row->setSpacing(2);
    auto* label = new QLabel(this);
    label->setObjectName(name);
    label->setToolTip(title);
    // The percentage takes what the M keys leave; it never widens the bar.
    label->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    row->addWidget(label, 1);
    const auto add = [&](const char* suffix, const QString& text, int direction) {
        auto* button = new QPushButton(text, this);
        button->setObjectName(name + suffix);
        button->setFocusPolicy(Qt::NoFocus);
        button->setFixedWidth(button->fontMetrics().horizontalAdvance("+") * 5 / 2 + 8);
        const QKeySequence keys =
            rapid ? rapidOverrideShortcut(direction) : feedOverrideShortcut(direction);
        const QString shortcut = keys.toString(QKeySequence::NativeText);
        button->setToolTip(direction > 0 ? tr("%1 up (%2)").arg(title, shortcut)
                                         : tr("%1 down (%2)").arg(title, shortcut));
        connect(button, &QPushButton::clicked, this,
                [this, rapid, direction] { emit overrideStep(rapid, direction); });
        row->addWidget(button);
    };
    add("Down", QString::fromUtf8("\u2212"), -1);
    add("Up", "+", 1);
    qobject_cast<QVBoxLayout*>(layout())->addLayout(row);
    return label;
}

namespace {
/// `label` on two lines, broken at the blank nearest its middle, when it is
/// wider than `width` pixels; unchanged otherwise.
QString twoLinesIfWider(const QString& label, const QFontMetrics& metrics, int width) {
    if (metrics.horizontalAdvance(label) <= width || !label.contains(' ')) return label;
    int best = -1;
    for (int i = label.indexOf(' '); i >= 0; i = label.indexOf(' ', i + 1))
        if (best < 0 || std::abs(i - label.size() / 2) < std::abs(best - label.size() / 2))
            best = i;
    return label.left(best) + '\n' + label.mid(best + 1);
}
}  // namespace

void MachineKeyBar::fitLabels() {
    for (const auto& [key, button] : buttons_) {
        const QString label = keyLabel(key);
        // Room inside the key's 2 px frame (the style sheet has no padding).
        const QString text = twoLinesIfWider(label, button->fontMetrics(), button->width() - 6);
        if (button->text() != text) button->setText(text);
    }
}

QSize MachineKeyBar::sizeHint() const {
    QSize hint = QWidget::sizeHint();
    int widest = 0;
    for (const auto& [key, button] : buttons_)
        widest = std::max(widest, button->fontMetrics().horizontalAdvance(keyLabel(key)));
    const QMargins margins = layout()->contentsMargins();
    hint.setWidth(std::max(hint.width(), widest + 12 + margins.left() + margins.right()));
    return hint;
}

void MachineKeyBar::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    fitLabels();
}

void MachineKeyBar::changeEvent(QEvent* event) {
    QWidget::changeEvent(event);
    if (event->type() == QEvent::FontChange) fitLabels();
}

void MachineKeyBar::setOverrides(int feedPercent, int rapidPercent) {
    feedOverride_->setText(QString("F %1%").arg(feedPercent));
    rapidOverride_->setText(QString("G0 %1%").arg(rapidPercent));
}

QPushButton* MachineKeyBar::button(mtc::core::ControlKey key) const {
    for (const auto& entry : buttons_)
        if (entry.first == key) return entry.second;
    return nullptr;
}

void MachineKeyBar::setLamp(mtc::core::ControlKey key, bool on) {
    QPushButton* target = button(key);
    if (!target || target->property("lamp").toBool() == on) return;
    target->setProperty("lamp", on);
    // The style sheet selects on the property: polish again to repaint.
    target->style()->unpolish(target);
    target->style()->polish(target);
}

void MachineKeyBar::setSpeedText(const QString& text) {
    speed_->setText(tr("Speed %1").arg(text));
}

}  // namespace mtc::hmi
