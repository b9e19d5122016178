#pragma once

#include <memory>

#include "hmi/Screen.h"

class QLabel;
class QTableView;

namespace mtc::screens {

class RestartController;
class RestartResultModel;

/// Result review of the computing process (seed 000, 2.8): the restored
/// state at the target block next to the machine's state before the
/// restart, differences highlighted — what the operator checks before Start
/// runs ADJUST. Soft keys: repositioning, back to the selection, only
/// differences.
class RestartResultScreen : public mtc::hmi::Screen {
    Q_OBJECT
  public:
    /// The screen of `context`'s station, rendering the station's `controller`.
    RestartResultScreen(const mtc::hmi::ScreenContext& context,
                        std::shared_ptr<RestartController> controller);
    QString screenName() const override { return "restart-result"; }
    QString title() const override {
        return QCoreApplication::translate("ScreenTitle", "NC program restart: result");
    }
    mtc::hmi::SoftKeys softKeys() override;
    void activated() override;

  private:
    void render();
    void renderCollisions();
    /// Heading rows span the table (set again after every reload).
    void spanHeadings();

    std::shared_ptr<RestartController> controller_;
    RestartResultModel* model_;
    QLabel* summary_;
    QLabel* collisions_;  ///< the way back against the part: red when it collides
    QTableView* table_;
    QLabel* hint_;
};

}  // namespace mtc::screens
