#pragma once

#include <QWidget>

#include "cnc_core/machine/ProcessControl.h"

namespace mtc::hmi {

/// The machine control keys (M keys) at the right edge of the panel.
/// Buttons are named "mkey-<n>" in bar order (see machineKeys()); every
/// press is reported through keyPressed, never handled here.
class MachineKeyBar : public QWidget {
    Q_OBJECT
  public:
    explicit MachineKeyBar(QWidget* parent = nullptr);

  signals:
    void keyPressed(mtc::core::ControlKey key);
};

}  // namespace mtc::hmi
