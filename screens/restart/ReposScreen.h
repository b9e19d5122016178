#pragma once

#include <memory>

#include "hmi/Screen.h"

class QLabel;
class QTableView;

namespace mtc::screens {

class RestartController;
class ReposModel;

/// Repositioning screen (seed 000, Fig. 2-4): distance of every axis to the
/// re-entry point while ADJUST and REPOS run, and jogging in manual mode
/// between them (seed 000, 2.9): ↑/↓ choose the axis, + / − (or F1 / F2)
/// jog it by the step F3 chooses.
class ReposScreen : public mtc::hmi::Screen {
    Q_OBJECT
  public:
    /// The screen of `context`'s station, rendering the station's `controller`.
    ReposScreen(const mtc::hmi::ScreenContext& context,
                std::shared_ptr<RestartController> controller);
    QString screenName() const override { return "repos"; }
    QString title() const override {
        return QCoreApplication::translate("ScreenTitle", "Repositioning");
    }
    mtc::hmi::SoftKeys softKeys() override;
    void activated() override;

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    void jog(double direction);
    void render();

    std::shared_ptr<RestartController> controller_;
    ReposModel* model_;
    QLabel* phase_;
    QTableView* table_;
    QLabel* message_;
    double step_ = 1.0;
};

}  // namespace mtc::screens
