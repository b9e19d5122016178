#pragma once

#include "screens/tooldata/SetupTableScreen.h"

namespace mtc::screens {

class ToolTableModel;

/// Tool table of the station's process: one row per cutting edge with T,
/// name, E, radius, lengths L1..L3 with their wear, edge position, corner
/// and setting angle (docs/TOOL-DATA.md). Cursor keys move the cell
/// cursor; Enter (F1) edits the cell, F2 adds a tool, F3 an edge of the
/// tool under the cursor, F4 removes the edge, F5 the whole tool (each
/// removal asks first). Every entry goes through the core's
/// SetupDataEditor: checked by the tool file's rules (a refusal says why
/// and keeps the old value), effective for the next block, saved at once.
class ToolTableScreen : public SetupTableScreen {
    Q_OBJECT
  public:
    explicit ToolTableScreen(const mtc::hmi::ScreenContext& context);
    QString screenName() const override { return "tools"; }
    QString title() const override {
        return QCoreApplication::translate("ScreenTitle", "Tool table");
    }
    mtc::hmi::SoftKeys softKeys() override;
    void activated() override;

  protected:
    void startEdit() override;
    void inputConfirmed(const QString& text) override;
    void inputCancelled() override;
    void dataChangedElsewhere() override { activated(); }

  private:
    enum class Input { None, Value, NewTool, NewEdge, RemoveEdge, RemoveTool };

    void ask(Input input, const QString& prompt, const QString& text);
    void askNewTool();
    void askNewEdge();
    void askRemoval(bool wholeTool);
    void confirmValue(const QString& text);
    void confirmNewTool(const QString& text);
    void confirmNewEdge(const QString& text);
    void confirmRemoval(bool wholeTool);
    /// "T3 E1" of the cursor row.
    QString edgeName() const;
    void updateHeading();

    ToolTableModel* model_;
    Input input_ = Input::None;
};

}  // namespace mtc::screens
