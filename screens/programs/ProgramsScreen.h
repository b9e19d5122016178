#pragma once

#include "hmi/Screen.h"

class QListView;
class QPlainTextEdit;

namespace mtc::screens {

class ProgramDirectoryModel;

/// Program directory of a station: the programs in memory, the listing of
/// the one under the cursor, and selection of the program to run (Enter/F1).
class ProgramsScreen : public mtc::hmi::Screen {
    Q_OBJECT
  public:
    explicit ProgramsScreen(const mtc::hmi::ScreenContext& context);
    QString screenName() const override { return "programs"; }
    QString title() const override { return "Program directory"; }
    mtc::hmi::SoftKeys softKeys() override;
    void activated() override;

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    void selectCurrent();
    void showListing();

    ProgramDirectoryModel* model_;
    QListView* list_;
    QPlainTextEdit* listing_;
};

}  // namespace mtc::screens
