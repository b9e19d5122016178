#pragma once

#include <vector>

#include "hmi/Screen.h"

class QLabel;
class QTableView;

namespace mtc::hmi {
class PromptedInput;
}

namespace mtc::screens {

class MachineDataModel;

/// Machine data screen: one page of the station's process as the table
/// Nr. / Title / Value / Unit with the "→" cursor (seed 000 Fig. 4-6).
/// Keys: Up/Down/PageUp/PageDown move the cursor, Left/Right (F1/F2) change
/// the page (30, 60, 61, user pages), F3 the sub of page 61, Enter (F4)
/// edits the element. An edit is checked like every operator write (GUI
/// write protection, range, type); a password-protected element asks for
/// the machine data password once, then the screen stays unlocked until it
/// is left. A bad value leaves the old one and says why. Values follow the
/// running program and the computing process (CellSession::processChanged).
class MachineDataScreen : public mtc::hmi::Screen {
    Q_OBJECT
  public:
    explicit MachineDataScreen(const mtc::hmi::ScreenContext& context);
    QString screenName() const override { return "machine-data"; }
    QString title() const override {
        return QCoreApplication::translate("ScreenTitle", "Machine data");
    }
    mtc::hmi::SoftKeys softKeys() override;
    void activated() override;

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    void hideEvent(QHideEvent* event) override;

  private:
    enum class Input { None, Value, Password };

    int processNumber() const;
    /// Shows the page `step` places before/after the current one.
    void stepPage(int step);
    void stepSub();
    void showPage(int page, int sub);
    void updateHeader();
    bool browseKey(int key);
    void startEdit();
    void openInput(Input input, const QString& prompt, const QString& text);
    void closeInput();
    void cancelInput();
    /// Closes the input and acts on the confirmed `text` (value or password).
    void confirmInput(const QString& text);
    void confirmValue(const QString& text);
    void confirmPassword(const QString& text);
    /// Writes `value` to the element under the cursor and reports the outcome.
    void writeValue(double value);
    void say(const QString& message);
    QString elementName() const;

    MachineDataModel* model_;
    QLabel* header_;
    QTableView* table_;
    mtc::hmi::PromptedInput* inputLine_;
    QLabel* message_;
    QString notice_;  ///< the last take-over of another program's values (CF-021)
    Input input_ = Input::None;
    double pendingValue_ = 0.0;
    QString password_;  ///< accepted password while the screen is shown
};

}  // namespace mtc::screens
