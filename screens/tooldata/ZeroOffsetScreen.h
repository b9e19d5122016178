#pragma once

#include "screens/tooldata/SetupTableScreen.h"

namespace mtc::screens {

class ZeroOffsetModel;

/// Zero offset table of the station's process: G54..G59 by the axis
/// definitions of its axes (seed 003, 3.5; docs/TOOL-DATA.md). Cursor keys
/// move the cell cursor, Enter (F1) edits the cell. Every entry goes
/// through the core's SetupDataEditor: checked by the offset file's rules
/// (a refusal says why and keeps the old value), effective for the next
/// block, saved at once.
class ZeroOffsetScreen : public SetupTableScreen {
    Q_OBJECT
  public:
    explicit ZeroOffsetScreen(const mtc::hmi::ScreenContext& context);
    QString screenName() const override { return "offsets"; }
    QString title() const override {
        return QCoreApplication::translate("ScreenTitle", "Zero offsets");
    }
    mtc::hmi::SoftKeys softKeys() override;
    void activated() override;

  protected:
    void startEdit() override;
    void inputConfirmed(const QString& text) override;
    void inputCancelled() override;
    void dataChangedElsewhere() override { activated(); }

  private:
    /// "G54 X" of the cursor cell.
    QString cellName() const;
    void updateHeading();

    ZeroOffsetModel* model_;
    bool editing_ = false;
};

}  // namespace mtc::screens
