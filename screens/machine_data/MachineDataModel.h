#pragma once

#include <QAbstractTableModel>
#include <cstdint>

#include "cnc_core/machine_data/MachineDataStore.h"

namespace mtc::screens {

/// One machine data page of one process (and sub) as the table of seed 000
/// Fig. 4-6: Nr. / Title / Value / Unit, the row under the cursor marked
/// with "→" before its number. Reads the store; never writes it.
class MachineDataModel : public QAbstractTableModel {
    Q_OBJECT
  public:
    enum Column { Number, Title, Value, Unit, ColumnCount };

    MachineDataModel(const mtc::core::MachineDataStore* store, QObject* parent = nullptr);

    /// Shows page `page` of process `process`, sub `sub`; the cursor goes to
    /// the first row. False (nothing changes) when the page does not exist.
    bool showPage(int process, int page, int sub);
    int process() const { return process_; }
    int page() const { return page_; }
    int sub() const { return sub_; }
    /// The page definition shown (nullptr before the first showPage()).
    const mtc::core::MachineDataPage* definition() const { return definition_; }

    int cursor() const { return cursor_; }
    /// Moves the cursor by `rows`, clamped to the table.
    void moveCursor(int rows);
    /// The element under the cursor, or nullptr for an empty page.
    const mtc::core::MachineDataElement* currentElement() const;
    /// The address of the element under the cursor.
    mtc::core::MachineDataAddress currentAddress() const;
    /// The value of the element under the cursor as the table shows it.
    QString currentValueText() const;
    /// Re-reads the values when the store changed since the last look.
    void refresh();

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

  private:
    QString valueText(int row) const;

    const mtc::core::MachineDataStore* store_;
    const mtc::core::MachineDataPage* definition_ = nullptr;
    int process_ = 0;
    int page_ = 0;
    int sub_ = 0;
    int cursor_ = 0;
    std::uint64_t revision_ = 0;
};

}  // namespace mtc::screens
