#pragma once

#include <QPair>
#include <QVector>
#include <QWidget>

class QLabel;
class QPushButton;

#include "cnc_core/machine/ProcessControl.h"

namespace mtc::hmi {

/// The machine control keys (M keys) at the right edge of the panel.
/// Buttons are named "mkey-<n>" in bar order (see machineKeys()); every
/// press is reported through keyPressed, never handled here. Below them the
/// override switches of feed and rapid traverse (labels "feedOverrideSwitch",
/// "rapidOverrideSwitch" with the percentage, buttons "<name>Up" / "<name>Down",
/// reported through overrideStep) and the simulation's Speed key
/// ("speedKey", speedPressed).
class MachineKeyBar : public QWidget {
    Q_OBJECT
  public:
    explicit MachineKeyBar(QWidget* parent = nullptr);
    /// Shows the speed factor on the Speed key ("x10").
    void setSpeedText(const QString& text);
    /// Shows the overrides in force (percent).
    void setOverrides(int feedPercent, int rapidPercent);
    /// Lights or darkens the lamp of `key` (button property "lamp").
    void setLamp(mtc::core::ControlKey key, bool on);
    /// The button of `key` (nullptr for a key the bar does not have).
    QPushButton* button(mtc::core::ControlKey key) const;
    /// Wide enough for every M key's label on one line: the bar only wraps
    /// a label when the window leaves it less (fitLabels).
    QSize sizeHint() const override;

  signals:
    void keyPressed(mtc::core::ControlKey key);
    void speedPressed();
    /// An override button: `rapid` false = feed; `direction` +1 / -1.
    void overrideStep(bool rapid, int direction);

  protected:
    void resizeEvent(QResizeEvent* event) override;
    void changeEvent(QEvent* event) override;

  private:
    /// The M keys' labels broken at a blank where a label is wider than its
    /// key (German "Steuerung rücksetzen" on a narrow window).
    void fitLabels();

    QLabel* addOverride(const QString& name, const QString& title, bool rapid);
    QPushButton* speed_;
    QLabel* feedOverride_;
    QLabel* rapidOverride_;
    QVector<QPair<mtc::core::ControlKey, QPushButton*>> buttons_;
};

}  // namespace mtc::hmi
