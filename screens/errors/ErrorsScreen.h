#pragma once

#include <QSet>
#include <memory>

#include "hmi/Screen.h"

class QLabel;
class QListWidget;

namespace mtc::hmi {
class ProgramWorkspace;
struct ErrorEntry;
}  // namespace mtc::hmi

namespace mtc::screens {

class RestartController;

/// Error window (seed 001, ch. 9): the brief messages of the station's
/// error log with origin (compiler, runtime, restart), program and block;
/// <Additional text> shows the detail lines of the highlighted message;
/// Enter opens the editor on the message's program and line.
class ErrorsScreen : public mtc::hmi::Screen {
    Q_OBJECT
  public:
    /// `restart` (may be null): the station's restart controller whose
    /// errors are collected into the log.
    ErrorsScreen(const mtc::hmi::ScreenContext& context,
                 std::shared_ptr<mtc::hmi::ProgramWorkspace> workspace,
                 std::shared_ptr<RestartController> restart);
    QString screenName() const override { return "errors"; }
    QString title() const override {
        return QCoreApplication::translate("ScreenTitle", "Error display");
    }
    mtc::hmi::SoftKeys softKeys() override;
    void activated() override;

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    void rebuild();
    void toggleDetails();
    void jumpToSource();
    void collectRestartMessage();
    QString itemText(const mtc::hmi::ErrorEntry& entry, bool expanded) const;

    std::shared_ptr<mtc::hmi::ProgramWorkspace> workspace_;
    std::shared_ptr<RestartController> restart_;
    QListWidget* list_;
    QLabel* hint_;
    QSet<int> expanded_;  ///< entries whose additional text is shown
};

}  // namespace mtc::screens
