#pragma once

#include <QWidget>

#include "hmi/SoftKey.h"

namespace mtc::hmi {

class SoftKeyButton;

/// The row of soft keys F1..F8 at the bottom of the panel. Buttons are
/// named "softkey1".."softkey8"; clicking one or calling trigger() runs the
/// current screen's action.
class SoftKeyBar : public QWidget {
    Q_OBJECT
  public:
    explicit SoftKeyBar(QWidget* parent = nullptr);

    /// Shows the keys of a screen (missing keys become blank).
    void setKeys(const SoftKeys& keys);
    /// Runs soft key `index` (0 = F1). Returns false for a blank/disabled key.
    bool trigger(int index);
    QString label(int index) const;

  private:
    QVector<SoftKeyButton*> buttons_;
    SoftKeys keys_;
};

}  // namespace mtc::hmi
