#include "screens/signals/SignalModel.h"

#include "cnc_core/machine/SignalTable.h"

namespace mtc::screens {

SignalModel::SignalModel(const mtc::core::SignalTable* table, View view, QObject* parent)
    : QAbstractTableModel(parent), table_(table), view_(view) {
    reload();
}

void SignalModel::reload() {
    beginResetModel();
    values_.clear();
    for (const auto& [name, value] : table_->values())
        values_.push_back({QString::fromStdString(name), value});
    endResetModel();
}

int SignalModel::rowCount(const QModelIndex& parent) const {
    if (parent.isValid()) return 0;
    return view_ == View::Values ? values_.size() : static_cast<int>(table_->log().size());
}

int SignalModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : (view_ == View::Values ? 2 : 3);
}

QVariant SignalModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || role != Qt::DisplayRole) return {};
    if (view_ == View::Values) {
        const auto& entry = values_.value(index.row());
        return index.column() == 0 ? QVariant(entry.first) : QVariant(entry.second);
    }
    const auto& log = table_->log();
    if (index.row() >= static_cast<int>(log.size())) return {};
    // newest first: the operator watches what just happened
    const auto& change = log[log.size() - 1 - static_cast<size_t>(index.row())];
    switch (index.column()) {
        case 0:
            return QVariant::fromValue<qulonglong>(change.step);
        case 1:
            return QString::fromStdString(change.name);
        default:
            return change.value;
    }
}

QVariant SignalModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    if (view_ == View::Values) return section == 0 ? tr("Signal") : tr("Value");
    static const char* names[] = {QT_TR_NOOP("Step"), QT_TR_NOOP("Signal"), QT_TR_NOOP("Value")};
    return tr(names[section]);
}

}  // namespace mtc::screens
