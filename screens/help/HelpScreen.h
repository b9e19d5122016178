#pragma once

#include "hmi/Screen.h"

class QTextBrowser;

namespace mtc::screens {

/// F12: the help of the screen the operator was on (what it is for, the
/// seed section it reproduces, its soft keys as they are now and its other
/// keys; issue 20 §4), then the panel's global keys. Opened from the main
/// menu it lists every screen's soft keys instead. F8 goes back.
class HelpScreen : public mtc::hmi::Screen {
    Q_OBJECT
  public:
    explicit HelpScreen(const mtc::hmi::ScreenContext& context);
    QString screenName() const override { return "help"; }
    QString title() const override { return QCoreApplication::translate("ScreenTitle", "Help"); }
    mtc::hmi::SoftKeys softKeys() override;
    void activated() override;
    /// The text shown (HTML); rebuilt by activated().
    QString helpHtml() const;
    /// The screen the help is about ("" = the overview of every screen).
    const QString& subject() const { return subject_; }

  private:
    mtc::hmi::Screen* stationScreen(const QString& name) const;
    QString screenHelpHtml(mtc::hmi::Screen& screen) const;
    QString overviewHtml() const;
    /// The language shown, the desk's stored one and how to change it.
    QString languageHtml() const;
    /// F6 / F7: stores `language` as the desk's language for the next start.
    void storeLanguage(const QString& language);

    QTextBrowser* text_;
    QString subject_;
};

}  // namespace mtc::screens
