#pragma once

#include "hmi/Screen.h"

class QListWidget;

namespace mtc::hmi {
class ScreenRegistry;
}

namespace mtc::screens {

/// The station's base screen: every registered screen, reachable by the
/// cursor keys + Enter or by its soft key (F8 pages through when there are
/// more than seven).
class MenuScreen : public mtc::hmi::Screen {
    Q_OBJECT
  public:
    MenuScreen(const mtc::hmi::ScreenContext& context, const mtc::hmi::ScreenRegistry* registry);
    QString screenName() const override { return "menu"; }
    QString title() const override {
        return QCoreApplication::translate("ScreenTitle", "Main menu");
    }
    mtc::hmi::SoftKeys softKeys() override;
    void activated() override;

  protected:
    void keyPressEvent(QKeyEvent* event) override;

  private:
    void openSelected();

    const mtc::hmi::ScreenRegistry* registry_;
    QListWidget* list_;
    QStringList targets_;
    int page_ = 0;
};

}  // namespace mtc::screens
