#pragma once

#include <memory>

#include "hmi/Screen.h"
#include "screens/gne/GneEditModel.h"

class QLabel;
class QLineEdit;
class QListWidget;
class QTableWidget;

namespace mtc::hmi {
class ProgramWorkspace;
}

namespace mtc::screens {

class GneCanvas;

/// The graphical NC editor (seed 001, ch. 3), opened from the program
/// editor's GNE soft key: on a GNE keyword it modifies that section, on any
/// other line it creates a new one. Rows (items and contour elements) on
/// the left, the values of the selected row with checked entry, the live
/// drawing on the right. Exit writes the section back into the program as
/// function calls (keywords) or as expanded NC blocks, as the operator
/// chooses, saves the program and returns to the editor on that line.
///
/// Keys: Up/Down rows, Enter = values, Enter on a value = edit it (Enter
/// takes, Esc cancels), Del = clear a value / delete a row, Esc = back;
/// Ins = insert, +/- zoom, Ctrl+Z/Ctrl+Y undo/redo. Soft keys F1-F8.
class GneScreen : public mtc::hmi::Screen {
    Q_OBJECT
  public:
    GneScreen(const mtc::hmi::ScreenContext& context,
              std::shared_ptr<mtc::hmi::ProgramWorkspace> workspace);
    QString screenName() const override { return "gne"; }
    QString title() const override {
        return QCoreApplication::translate("ScreenTitle", "Graphical NC editor (GNE)");
    }
    mtc::hmi::SoftKeys softKeys() override;
    void activated() override;

    /// The model (tests, the drawing).
    const GneEditModel& model() const { return model_; }
    /// Program the dialog belongs to (0 = none).
    int program() const { return program_; }
    /// Opens the dialog on `programText` at `line` for program `number`
    /// (what activated() does with the editor's request).
    void openOn(int number, const std::string& programText, int line);

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    enum class Chooser { None, Insert, Exit };
    bool rowKey(int key, Qt::KeyboardModifiers modifiers);
    bool fieldKey(int key, const QString& text);
    bool inputKey(int key);
    bool chooserKey(int key);
    void startInput(const QString& initial);
    void applyInput();
    void closeInput();
    void clearField();
    void openChooser(Chooser kind);
    void closeChooser();
    void choose();
    void insertChoice(const std::string& choice);
    void deleteRow();
    void nextAlternative();
    void undo();
    void redo();
    void toggleZoom();
    void finish(GneOutput output);
    void discard();
    void refresh();
    void refreshFields();
    void showMessage(const QString& text, bool error = false);

    std::shared_ptr<mtc::hmi::ProgramWorkspace> workspace_;
    GneEditModel model_;
    int program_ = 0;
    int openedLine_ = -1;
    const void* openedSource_ = nullptr;
    Chooser chooser_ = Chooser::None;
    QLabel* heading_;
    QListWidget* rows_;
    QTableWidget* fields_;
    QLabel* fieldHelp_;
    QLineEdit* input_;
    QListWidget* choices_;
    QLabel* problems_;
    QLabel* message_;
    GneCanvas* canvas_;
};

}  // namespace mtc::screens
