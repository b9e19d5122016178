#pragma once

#include <QAbstractTableModel>

namespace mtc::screens {

/// A table with a cell cursor, as the tool and zero offset screens show
/// them: the cursor's row is marked "→" in its first column and the cursor
/// cell is drawn highlighted. Subclasses give the rows, columns and text.
class CursorTableModel : public QAbstractTableModel {
    Q_OBJECT
  public:
    using QAbstractTableModel::QAbstractTableModel;

    int cursorRow() const { return row_; }
    int cursorColumn() const { return column_; }
    /// Moves the cursor by rows and columns, clamped to the table.
    void moveCursor(int rows, int columns);
    /// Puts the cursor on (row, column), clamped to the table.
    void setCursor(int row, int column);

    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;

  protected:
    /// The text of a cell (without the cursor mark).
    virtual QString cellText(int row, int column) const = 0;
    /// Alignment of a column's cells.
    virtual bool rightAligned(int column) const = 0;
    /// Clamps the cursor after the rows changed (call after a reset).
    void keepCursorInside();

  private:
    int row_ = 0;
    int column_ = 0;
};

/// A number as the tables show it: at least `decimals` places, at most 5,
/// without the trailing zeros beyond `decimals` ("3.500", "3.12345").
QString tableNumber(double value, int decimals);

}  // namespace mtc::screens
