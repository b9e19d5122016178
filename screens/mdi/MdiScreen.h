#pragma once

#include "hmi/Screen.h"

class QLabel;
class QListWidget;
class QPlainTextEdit;

namespace mtc::screens {

class MdiModel;

/// Manual data input (docs/decisions/mdi.md): the station's position and
/// modal state, an input of a few NC blocks (global macros allowed, seed 001
/// ch. 4/12), the message of the last check or run, and the history of the
/// entries run. Start (machine key) in MDI mode runs the input.
class MdiScreen : public mtc::hmi::Screen {
    Q_OBJECT
  public:
    explicit MdiScreen(const mtc::hmi::ScreenContext& context);
    QString screenName() const override { return "mdi"; }
    QString title() const override {
        return QCoreApplication::translate("ScreenTitle", "MDI (manual data input)");
    }
    mtc::hmi::SoftKeys softKeys() override;
    void activated() override;
    /// The station's MDI model (input, history).
    MdiModel& model() { return *model_; }

  private:
    void refresh();
    void refreshHistory();

    MdiModel* model_;
    QLabel* mode_;
    QLabel* position_;
    QLabel* modal_;
    QLabel* positionCaption_;
    QLabel* modalCaption_;
    QPlainTextEdit* input_;
    QLabel* message_;
    QListWidget* history_;
};

}  // namespace mtc::screens
