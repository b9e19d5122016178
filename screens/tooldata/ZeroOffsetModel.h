#pragma once

#include <memory>
#include <vector>

#include "cnc_core/machine/MachineConfig.h"
#include "cnc_core/machine/ZeroOffsetTable.h"
#include "screens/tooldata/CursorTableModel.h"

namespace mtc::screens {

/// The zero offsets G54..G59 of one process as a table: one row per code,
/// one column per axis definition of the process (zeroOffsetColumns, as
/// `mtc200-cli offsets get` shows them; seed 003, 3.5: a column applies to
/// whichever axis has that definition). Reads the table the interpreter
/// reads; never writes it.
class ZeroOffsetModel : public CursorTableModel {
    Q_OBJECT
  public:
    ZeroOffsetModel(const mtc::core::ProcessConfig* process,
                    std::shared_ptr<const mtc::core::ZeroOffsetTable> table,
                    QObject* parent = nullptr);

    /// Reads the table again (after a change), the cursor stays.
    void refresh();
    /// G code of the cursor row (54..59); the column letter of the cursor
    /// ('\0' on the code column).
    int currentCode() const { return 54 + cursorRow(); }
    char currentColumn() const;
    /// The value under the cursor as the file writes it.
    QString currentValueText() const;
    /// The cursor to the cell of `code` and `column` (the first one when absent).
    void showCell(int code, char column);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

  protected:
    QString cellText(int row, int column) const override;
    bool rightAligned(int column) const override { return column != 0; }

  private:
    const mtc::core::ProcessConfig* process_;
    std::shared_ptr<const mtc::core::ZeroOffsetTable> table_;
    std::vector<mtc::core::AxisDefinition> columns_;
};

}  // namespace mtc::screens
