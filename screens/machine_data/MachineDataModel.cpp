#include "screens/machine_data/MachineDataModel.h"

#include <QStringLiteral>

#include "screens/machine_data/MachineDataTexts.h"

namespace mtc::screens {

MachineDataModel::MachineDataModel(const mtc::core::MachineDataStore* store, QObject* parent)
    : QAbstractTableModel(parent), store_(store) {}

bool MachineDataModel::showPage(int process, int page, int sub) {
    const mtc::core::MachineDataPage* definition = store_->page(process, page);
    if (!definition || definition->subSlot(sub) < 0) return false;
    beginResetModel();
    definition_ = definition;
    process_ = process;
    page_ = page;
    sub_ = sub;
    cursor_ = 0;
    revision_ = store_->revision();
    endResetModel();
    return true;
}

void MachineDataModel::moveCursor(int rows) {
    const int count = rowCount();
    if (count == 0) return;
    const int next = std::max(0, std::min(count - 1, cursor_ + rows));
    if (next == cursor_) return;
    const int previous = cursor_;
    cursor_ = next;
    emit dataChanged(index(previous, Number), index(previous, Number));
    emit dataChanged(index(cursor_, Number), index(cursor_, Number));
}

const mtc::core::MachineDataElement* MachineDataModel::currentElement() const {
    if (!definition_ || cursor_ >= rowCount()) return nullptr;
    return &definition_->elements[static_cast<std::size_t>(cursor_)];
}

mtc::core::MachineDataAddress MachineDataModel::currentAddress() const {
    const mtc::core::MachineDataElement* e = currentElement();
    return {page_, process_, sub_, e ? e->number : 0};
}

QString MachineDataModel::currentValueText() const {
    return valueText(cursor_);
}

void MachineDataModel::refresh() {
    const std::uint64_t revision = store_->revision();
    if (revision == revision_ || rowCount() == 0) return;
    revision_ = revision;
    emit dataChanged(index(0, Value), index(rowCount() - 1, Value));
}

int MachineDataModel::rowCount(const QModelIndex& parent) const {
    if (parent.isValid() || !definition_) return 0;
    return static_cast<int>(definition_->elements.size());
}

int MachineDataModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QString MachineDataModel::valueText(int row) const {
    if (!definition_ || row < 0 || row >= rowCount()) return {};
    const mtc::core::MachineDataElement& e = definition_->elements[static_cast<std::size_t>(row)];
    double value = 0.0;
    if (store_->read({page_, process_, sub_, e.number}, value) != mtc::core::MachineDataStatus::Ok)
        return QStringLiteral("?");
    return QString::fromStdString(mtc::core::formatMachineDataValue(e.type, value));
}

QVariant MachineDataModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= rowCount()) return {};
    const mtc::core::MachineDataElement& e =
        definition_->elements[static_cast<std::size_t>(index.row())];
    if (role == Qt::TextAlignmentRole && index.column() == Value)
        return int(Qt::AlignRight | Qt::AlignVCenter);
    if (role != Qt::DisplayRole) return {};
    switch (index.column()) {
        case Number: {
            const QString number = QString("%1").arg(e.number, 3, 10, QChar('0'));
            return index.row() == cursor_ ? QStringLiteral("\u2192") + number : " " + number;
        }
        case Title:
            return machineDataText(e.designation);
        case Value:
            return valueText(index.row());
        case Unit:
            return QString::fromStdString(e.unit);
        default:
            return {};
    }
}

QVariant MachineDataModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    static const char* const names[] = {QT_TR_NOOP("Nr."), QT_TR_NOOP("Title"), QT_TR_NOOP("Value"),
                                        QT_TR_NOOP("Unit")};
    return section >= 0 && section < ColumnCount ? tr(names[section]) : QVariant();
}

}  // namespace mtc::screens
