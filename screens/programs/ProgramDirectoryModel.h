#pragma once

#include <QAbstractListModel>

namespace mtc::hmi {
class CellSession;
class ProgramWorkspace;
}  // namespace mtc::hmi

namespace mtc::screens {

/// The programs of one station, ordered by number, with the compiler's
/// status bit (seed 001 ch. 7: ' ', N, C, E): "→ 001 [C] N1010001.DAT".
class ProgramDirectoryModel : public QAbstractListModel {
    Q_OBJECT
  public:
    /// `workspace` (may be null) gives the status bits.
    ProgramDirectoryModel(mtc::hmi::CellSession* session, int slot,
                          const mtc::hmi::ProgramWorkspace* workspace = nullptr,
                          QObject* parent = nullptr);
    int rowCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    /// Program number in `row`, 0 if out of range.
    int programAt(int row) const;
    /// Row of program `number`, -1 if absent.
    int rowOf(int number) const;
    /// Re-reads the session (programs added or replaced).
    void reload();

  private:
    mtc::hmi::CellSession* session_;
    int slot_;
    const mtc::hmi::ProgramWorkspace* workspace_;
    QVector<int> numbers_;
};

}  // namespace mtc::screens
