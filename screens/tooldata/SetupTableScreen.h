#pragma once

#include "hmi/Screen.h"

class QLabel;
class QTableView;

namespace mtc::core {
struct SetupDataEdit;
}
namespace mtc::hmi {
class PromptedInput;
}

namespace mtc::screens {

class CursorTableModel;

/// What the tool table and the zero offset screen share: a heading, the
/// table with its cell cursor (cursor keys, Page Up/Down, Home/End), the
/// one-line input and the message line. Enter edits the cell; the
/// subclass says what a confirmed input means.
class SetupTableScreen : public mtc::hmi::Screen {
    Q_OBJECT
  public:
    SetupTableScreen(const mtc::hmi::ScreenContext& context, const char* prefix);

  protected:
    /// Call once the model exists: shows it in the table, the columns as
    /// wide as their contents or (`stretch`) sharing the width.
    void setModel(CursorTableModel* model, bool stretch);
    bool eventFilter(QObject* watched, QEvent* event) override;
    void hideEvent(QHideEvent* event) override;

    /// Enter (or the Edit soft key) on the cursor cell.
    virtual void startEdit() = 0;
    /// The input was confirmed with `text` / cancelled with Escape.
    virtual void inputConfirmed(const QString& text) = 0;
    virtual void inputCancelled() = 0;
    /// Another program's save was taken over: show the values again.
    virtual void dataChangedElsewhere() = 0;

    void openInput(const QString& prompt, const QString& text);
    void closeInput();
    bool inputOpen() const;
    void say(const QString& message);
    void setHeading(const QString& heading);
    /// The outcome of an edit for the message line: `done` when it was
    /// taken, the reason when refused, and whether it is in the file.
    QString outcomeText(const mtc::core::SetupDataEdit& edit, const QString& done,
                        const QString& refusedWhat) const;
    /// Keeps the cursor cell in view.
    void showCursor();
    int processNumber() const;

    QTableView* table_;

  private:
    bool browseKey(int key);

    CursorTableModel* model_ = nullptr;
    QLabel* heading_;
    mtc::hmi::PromptedInput* input_;
    QLabel* message_;
};

}  // namespace mtc::screens
