#include "hmi/SoftKeyBar.h"

#include <QHBoxLayout>

#include "hmi/SoftKeyButton.h"

namespace mtc::hmi {

SoftKeyBar::SoftKeyBar(QWidget* parent) : QWidget(parent) {
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->setSpacing(3);
    for (int i = 0; i < 8; ++i) {
        auto* button = new SoftKeyButton(QString("F%1").arg(i + 1), this);
        button->setObjectName(QString("softkey%1").arg(i + 1));
        button->setFocusPolicy(Qt::NoFocus);  // the panel is driven by F keys
        button->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);  // equal widths
        connect(button, &QPushButton::clicked, this, [this, i] { trigger(i); });
        layout->addWidget(button);
        buttons_.push_back(button);
    }
    setKeys({});
}

void SoftKeyBar::setKeys(const SoftKeys& keys) {
    keys_ = keys;
    keys_.resize(8);
    for (int i = 0; i < 8; ++i) {
        const SoftKey& key = keys_[i];
        buttons_[i]->setLabel(key.label);
        buttons_[i]->setEnabled(key.enabled && key.action != nullptr);
    }
}

bool SoftKeyBar::trigger(int index) {
    if (index < 0 || index >= keys_.size()) return false;
    const SoftKey key = keys_[index];  // copy: the action may replace the keys
    if (!key.enabled || !key.action) return false;
    key.action();
    return true;
}

QString SoftKeyBar::label(int index) const {
    return index >= 0 && index < keys_.size() ? keys_[index].label : QString();
}

}  // namespace mtc::hmi
