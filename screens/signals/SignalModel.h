#pragma once

#include <QAbstractTableModel>

namespace mtc::core {
class SignalTable;
}

namespace mtc::screens {

/// Two views of one SignalTable: current values (Name/Value) or the change
/// log (Step/Name/Value), chosen at construction.
class SignalModel : public QAbstractTableModel {
    Q_OBJECT
  public:
    enum class View { Values, Log };
    SignalModel(const mtc::core::SignalTable* table, View view, QObject* parent = nullptr);
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;
    /// Re-reads the table (call after the process changed).
    void reload();

  private:
    const mtc::core::SignalTable* table_;
    View view_;
    QVector<QPair<QString, int>> values_;
};

}  // namespace mtc::screens
