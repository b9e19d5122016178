#pragma once

#include <memory>
#include <vector>

#include "cnc_core/tooldata/ToolList.h"
#include "screens/tooldata/CursorTableModel.h"

namespace mtc::screens {

/// The tool list of one process as a table, one row per cutting edge:
/// T, name, E, radius and wear, L1..L3 and their wear, edge position,
/// corner and setting angle (seed 001 ch. 3, seed 003 ch. 3.6). Reads the
/// list the interpreter reads; never writes it.
class ToolTableModel : public CursorTableModel {
    Q_OBJECT
  public:
    enum Column {
        Tool,
        Name,
        Edge,
        Radius,
        RadiusWear,
        Length1,
        Length1Wear,
        Length2,
        Length2Wear,
        Length3,
        Length3Wear,
        Orientation,
        CornerAngle,
        SettingAngle,
        ColumnCount
    };

    explicit ToolTableModel(std::shared_ptr<const mtc::core::ToolList> list,
                            QObject* parent = nullptr);

    /// Reads the list again (after a change); the cursor stays on the same
    /// tool and edge when they are still there.
    void refresh();
    /// Puts the cursor on edge `edge` of tool `tool` (0: its first edge).
    void showEdge(int tool, int edge);

    /// Tool and edge under the cursor (0, 0 for an empty list).
    int currentTool() const;
    int currentEdge() const;
    /// The tool file key of a column ("radius", "name"; "" for T and E).
    static const char* columnKey(int column);
    /// What a column is, for prompts ("radius R", "wear of L3").
    static QString columnMeaning(int column);
    /// The value under the cursor as the file writes it (for the input).
    QString currentValueText() const;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

  protected:
    QString cellText(int row, int column) const override;
    bool rightAligned(int column) const override { return column != Name; }

  private:
    /// Numbers only, looked up when drawn: the list may be replaced by an
    /// edit (or another program's save taken over) at any time.
    struct Row {
        int tool;
        int edge;
    };
    void readRows();
    static double value(const mtc::core::ToolEdge& edge, int column);

    std::shared_ptr<const mtc::core::ToolList> list_;
    std::vector<Row> rows_;
};

}  // namespace mtc::screens
