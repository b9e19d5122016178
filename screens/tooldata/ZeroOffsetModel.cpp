#include "screens/tooldata/ZeroOffsetModel.h"

#include "cnc_core/tooldata/DataFileText.h"
#include "cnc_core/tooldata/ZeroOffsetFile.h"

namespace mtc::screens {

namespace {
constexpr int kCodes = 6;  // G54..G59
}

ZeroOffsetModel::ZeroOffsetModel(const mtc::core::ProcessConfig* process,
                                 std::shared_ptr<const mtc::core::ZeroOffsetTable> table,
                                 QObject* parent)
    : CursorTableModel(parent), process_(process), table_(std::move(table)) {
    if (process_ && table_) columns_ = mtc::core::zeroOffsetColumns(*process_, *table_);
    setCursor(0, 1);
}

void ZeroOffsetModel::refresh() {
    const int code = currentCode();
    const char column = currentColumn();
    beginResetModel();
    if (process_ && table_) columns_ = mtc::core::zeroOffsetColumns(*process_, *table_);
    keepCursorInside();
    endResetModel();
    showCell(code, column);
}

char ZeroOffsetModel::currentColumn() const {
    const int c = cursorColumn() - 1;
    if (c < 0 || c >= static_cast<int>(columns_.size())) return '\0';
    return mtc::core::definitionLetter(columns_[static_cast<std::size_t>(c)]);
}

void ZeroOffsetModel::showCell(int code, char column) {
    int at = 1;
    for (std::size_t c = 0; c < columns_.size(); ++c)
        if (mtc::core::definitionLetter(columns_[c]) == column) at = static_cast<int>(c) + 1;
    setCursor(code - 54, at);
}

QString ZeroOffsetModel::currentValueText() const {
    const int c = cursorColumn() - 1;
    if (!table_ || c < 0 || c >= static_cast<int>(columns_.size())) return {};
    return QString::fromStdString(mtc::core::formatDataNumber(
        table_->value(currentCode(), columns_[static_cast<std::size_t>(c)])));
}

QString ZeroOffsetModel::cellText(int row, int column) const {
    if (column == 0) return QString("G%1").arg(54 + row);
    const int c = column - 1;
    if (!table_ || c < 0 || c >= static_cast<int>(columns_.size())) return {};
    return tableNumber(table_->value(54 + row, columns_[static_cast<std::size_t>(c)]), 3);
}

int ZeroOffsetModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : kCodes;
}

int ZeroOffsetModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : 1 + static_cast<int>(columns_.size());
}

QVariant ZeroOffsetModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (role != Qt::DisplayRole || orientation != Qt::Horizontal) return {};
    if (section == 0) return tr("Offset");
    const int c = section - 1;
    if (c < 0 || c >= static_cast<int>(columns_.size())) return {};
    return QString(QChar(mtc::core::definitionLetter(columns_[static_cast<std::size_t>(c)])));
}

}  // namespace mtc::screens
