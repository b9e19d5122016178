#pragma once

#include <QObject>
#include <vector>

class QTableView;

namespace mtc::hmi {

/// What a column's texts need, in pixels with the cell's margins: the
/// longest word (texts wrap at blanks, never inside a word) and the longest
/// line (the whole text on one line).
struct ColumnNeed {
    int word = 0;
    int line = 0;
};

/// Widths for columns with `needs` in `available` pixels: every column gets
/// its longest word; what is left is shared out evenly, except that a column
/// needing less than its share for its longest line gets just that and the
/// others share the rest (max-min fair: a short value stays on one line, a
/// long description wraps); what is left after every line fits goes to the
/// last column. When the longest words
/// alone are wider than `available`, the widths are those words (the table
/// scrolls sideways rather than cutting a text).
std::vector<int> fitColumnWidths(const std::vector<ColumnNeed>& needs, int available);

/// Keeps the columns of `table` wide enough for every text of its model
/// (fitColumnWidths over the texts as the table draws them: the row's font,
/// the style's cell margins, the header's titles unbroken; a cell spanning
/// several columns left out: it has their widths together) and the rows as
/// high as their wrapped lines: when the model changes, the table is
/// resized or its font changes (another dpi). No text is cut at any font
/// size as long as the longest words fit side by side; a long text wraps
/// instead of ending in "…". Owned by the table.
class ColumnFit : public QObject {
    Q_OBJECT
  public:
    explicit ColumnFit(QTableView* table);
    /// Measures the model's texts and sets the widths and row heights now.
    void fit();
    /// The needs of every column of the table's model, as fit() measures them.
    std::vector<ColumnNeed> measure() const;

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    QTableView* table_;
    bool fitting_ = false;
};

}  // namespace mtc::hmi
