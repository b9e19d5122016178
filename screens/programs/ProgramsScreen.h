#pragma once

#include <memory>

#include "cnc_core/language/Program.h"
#include "hmi/Screen.h"

class QLabel;
class QListView;
class QPlainTextEdit;

namespace mtc::hmi {
class ProgramWorkspace;
}

namespace mtc::screens {

class NcCodeEdit;
class ProgramDirectoryModel;

/// Program directory of a station: the programs in memory with their
/// compiler status bit (N/C/E, seed 001 ch. 7), the listing of the one under
/// the cursor, selection of the program to run (Enter/F1), opening it in the
/// editor, <Compile> and the NC option "Compiler active".
class ProgramsScreen : public mtc::hmi::Screen {
    Q_OBJECT
  public:
    ProgramsScreen(const mtc::hmi::ScreenContext& context,
                   std::shared_ptr<mtc::hmi::ProgramWorkspace> workspace);
    QString screenName() const override { return "programs"; }
    QString title() const override {
        return QCoreApplication::translate("ScreenTitle", "Program directory");
    }
    mtc::hmi::SoftKeys softKeys() override;
    void activated() override;

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    void selectCurrent();
    void showListing();
    void editCurrent();
    void compileCurrent();
    void toggleCompiler();
    int currentNumber() const;

    std::shared_ptr<mtc::hmi::ProgramWorkspace> workspace_;
    QLabel* message_;

    ProgramDirectoryModel* model_;
    QListView* list_;
    NcCodeEdit* listing_;
    mtc::core::ProgramPtr shownProgram_;  ///< the program the listing shows
};

}  // namespace mtc::screens
