#pragma once

#include "hmi/Screen.h"

class QTextBrowser;

namespace mtc::screens {

/// Lists every key assignment: the panel's global keys, the machine control
/// keys and the soft keys of each screen of the station, as they are now.
class HelpScreen : public mtc::hmi::Screen {
    Q_OBJECT
  public:
    explicit HelpScreen(const mtc::hmi::ScreenContext& context);
    QString screenName() const override { return "help"; }
    QString title() const override { return "Key assignments"; }
    mtc::hmi::SoftKeys softKeys() override;
    void activated() override;
    /// The text shown (HTML); rebuilt by activated().
    QString helpHtml() const;

  private:
    QTextBrowser* text_;
};

}  // namespace mtc::screens
