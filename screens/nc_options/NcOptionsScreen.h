#pragma once

#include "hmi/Screen.h"

class QLabel;
class QListView;

namespace mtc::hmi {
class NcOptionsHolder;
class PromptedInput;
}  // namespace mtc::hmi

namespace mtc::screens {

class NcOptionsModel;

/// The "NC options" screen (seed 001 ch. 4, 7, 8; decisions NO-001..):
/// the cell's compiler settings and global macros, the same for both
/// stations. Keys: Up/Down move the cursor; Enter (F1) changes the row:
/// toggles "Compiler active", edits a user compiler command or a global
/// macro (`DEFINE name AS instructions`), on the last row adds one; F2 adds
/// a macro, F3 / Delete deletes the macro under the cursor, F4 toggles
/// "Compiler active", F8 back to the program directory. In the input line
/// Enter takes the entry, Escape cancels. A refused entry leaves the options
/// as they were, keeps the typed text and says why.
class NcOptionsScreen : public mtc::hmi::Screen {
    Q_OBJECT
  public:
    explicit NcOptionsScreen(const mtc::hmi::ScreenContext& context);
    QString screenName() const override { return "nc-options"; }
    QString title() const override {
        return QCoreApplication::translate("ScreenTitle", "NC options");
    }
    mtc::hmi::SoftKeys softKeys() override;
    void activated() override;

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    void hideEvent(QHideEvent* event) override;

  private:
    enum class Input { None, UserCompiler, NewMacro, ChangeMacro };

    int currentRow() const;
    void changeCurrent();
    void toggleCompiler();
    void startNewMacro();
    void deleteCurrentMacro();
    void openInput(Input input, int index, const QString& prompt, const QString& text);
    void closeInput();
    void cancelInput();
    /// Takes the confirmed `text` for the open input, or says why not.
    void confirmInput(const QString& text);
    /// Puts the cursor on `row` (clamped).
    void moveTo(int row);
    void say(const QString& message);

    mtc::hmi::NcOptionsHolder* holder_;
    NcOptionsModel* model_;
    QLabel* header_;
    QListView* list_;
    mtc::hmi::PromptedInput* inputLine_;
    QLabel* message_;
    Input input_ = Input::None;
    int inputIndex_ = 0;  ///< user compiler slot or macro index of the input
    int keptRow_ = 0;     ///< cursor row while the model is rebuilt
};

}  // namespace mtc::screens
