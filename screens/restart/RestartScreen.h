#pragma once

#include <memory>

#include "hmi/Screen.h"

class QLabel;
class QListView;

namespace mtc::screens {

class RestartController;
class RestartPrompt;

/// NC program restart screen (seed 000, Fig. 2-1): the listing of the
/// displayed program with the cursor, the levels <Plane+> opened, the target
/// / start block / number of runs, and the soft keys Plane+, Plane-, Search
/// string, Restart from last primary block, Number of runs. Enter accepts
/// the target. Renders its RestartController and forwards keys to it.
class RestartScreen : public mtc::hmi::Screen {
    Q_OBJECT
  public:
    /// The screen of `context`'s station, rendering the station's `controller`.
    RestartScreen(const mtc::hmi::ScreenContext& context,
                  std::shared_ptr<RestartController> controller);
    QString screenName() const override { return "restart"; }
    QString title() const override {
        return QCoreApplication::translate("ScreenTitle", "NC program restart");
    }
    mtc::hmi::SoftKeys softKeys() override;
    /// A fresh entry (from another screen of the station) starts a new
    /// selection; coming back from another station keeps it (seed 000, 2.2).
    void activated() override;
    /// The model this screen renders (shared with the station's other restart screens).
    RestartController* controller() const { return controller_.get(); }

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    void hideEvent(QHideEvent* event) override;

  private:
    bool listKey(int key);
    bool promptKey(int key);
    void openSearch();
    void openRuns();
    void openWindow();
    void closePrompt();
    void render();
    void scrollToCursor();
    int pageRows() const;

    std::shared_ptr<RestartController> controller_;
    QLabel* breadcrumb_;
    QListView* list_;
    RestartPrompt* prompt_;
    QLabel* status_;
    QLabel* message_;
    QLabel* progress_;
    bool entered_ = false;   ///< the current visit has started its selection
    bool eventSet_ = false;  ///< state shown in the event window
};

}  // namespace mtc::screens
