#include "screens/tooldata/CursorTableModel.h"

#include <QBrush>
#include <QPalette>
#include <algorithm>

namespace mtc::screens {

QString tableNumber(double value, int decimals) {
    QString text = QString::number(value == 0.0 ? 0.0 : value, 'f', 5);
    const int point = text.indexOf('.');
    int keep = text.size();
    while (keep > point + 1 + decimals && text[keep - 1] == '0')
        --keep;
    if (decimals == 0 && keep == point + 1) --keep;
    return text.left(keep);
}

void CursorTableModel::setCursor(int row, int column) {
    const int oldRow = row_;
    row_ = std::clamp(row, 0, std::max(0, rowCount() - 1));
    column_ = std::clamp(column, 0, std::max(0, columnCount() - 1));
    if (rowCount() == 0) return;
    // The mark of the old and the new row, and the two cursor cells.
    emit dataChanged(index(oldRow, 0), index(oldRow, columnCount() - 1));
    emit dataChanged(index(row_, 0), index(row_, columnCount() - 1));
}

void CursorTableModel::moveCursor(int rows, int columns) {
    setCursor(row_ + rows, column_ + columns);
}

void CursorTableModel::keepCursorInside() {
    row_ = std::clamp(row_, 0, std::max(0, rowCount() - 1));
    column_ = std::clamp(column_, 0, std::max(0, columnCount() - 1));
}

QVariant CursorTableModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid()) return {};
    const bool atCursor = index.row() == row_ && index.column() == column_;
    switch (role) {
        case Qt::DisplayRole: {
            const QString text = cellText(index.row(), index.column());
            if (index.column() != 0) return text;
            return (index.row() == row_ ? QString("\u2192") : QString(" ")) + text;
        }
        case Qt::TextAlignmentRole:
            return static_cast<int>(
                Qt::AlignVCenter | (rightAligned(index.column()) ? Qt::AlignRight : Qt::AlignLeft));
        case Qt::BackgroundRole:
            if (atCursor) return QBrush(QPalette().color(QPalette::Highlight));
            return {};
        case Qt::ForegroundRole:
            if (atCursor) return QBrush(QPalette().color(QPalette::HighlightedText));
            return {};
        default:
            return {};
    }
}

}  // namespace mtc::screens
