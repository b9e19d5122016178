#pragma once

#include "hmi/Screen.h"

class QTableView;

namespace mtc::screens {

class SignalModel;

/// Signal monitor: the interface signals of the station with their current
/// values, and the step log of every change (newest first).
class SignalsScreen : public mtc::hmi::Screen {
    Q_OBJECT
  public:
    explicit SignalsScreen(const mtc::hmi::ScreenContext& context);
    QString screenName() const override { return "signals"; }
    QString title() const override {
        return QCoreApplication::translate("ScreenTitle", "Interface signals");
    }
    mtc::hmi::SoftKeys softKeys() override;
    void activated() override;

  private:
    SignalModel* values_;
    SignalModel* log_;
    QTableView* valueView_;
    QTableView* logView_;
};

}  // namespace mtc::screens
