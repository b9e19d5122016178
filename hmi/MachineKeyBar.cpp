#include "hmi/MachineKeyBar.h"

#include <QPushButton>
#include <QVBoxLayout>

#include "hmi/KeyMap.h"

namespace mtc::hmi {

MachineKeyBar::MachineKeyBar(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    int n = 0;
    for (mtc::core::ControlKey key : machineKeys()) {
        auto* button = new QPushButton(QString::fromUtf8(mtc::core::keyName(key)), this);
        button->setObjectName(QString("mkey-%1").arg(++n));
        button->setToolTip(machineKeyShortcut(key).toString(QKeySequence::NativeText));
        button->setFocusPolicy(Qt::NoFocus);
        button->setMinimumSize(110, 40);
        connect(button, &QPushButton::clicked, this, [this, key] { emit keyPressed(key); });
        layout->addWidget(button);
    }
    layout->addStretch();
}

}  // namespace mtc::hmi
