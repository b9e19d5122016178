#pragma once

#include <QAbstractTableModel>

namespace mtc::hmi {
class CellSession;
}

namespace mtc::screens {

class RestartRun;

/// The axes of a station on the repositioning screen (seed 000, Fig. 2-4):
/// actual machine position, the re-entry point at the target block and the
/// distance still to go (re-entry − actual). Distances above 0.001 are
/// highlighted. Re-read with refresh() while ADJUST/REPOS or the jog move.
class ReposModel : public QAbstractTableModel {
    Q_OBJECT
  public:
    /// Role: the distance (double) of the row's axis.
    static constexpr int DistanceRole = Qt::UserRole + 1;

    ReposModel(mtc::hmi::CellSession* session, int slot, const RestartRun* run,
               QObject* parent = nullptr);

    /// Axis count may change with the configuration only: rows stay; values repaint.
    void refresh();
    /// Distance of axis `row` to the re-entry point (0 without a re-entry point).
    double distance(int row) const;
    /// True once the computing process has reached the target (re-entry point known).
    bool hasReentry() const;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

  private:
    mtc::hmi::CellSession* session_;
    int slot_;
    const RestartRun* run_;
};

}  // namespace mtc::screens
