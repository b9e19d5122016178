#include "screens/restart/ReposModel.h"

#include <QBrush>
#include <QColor>
#include <cmath>

#include "cnc_core/interp/Interpreter.h"
#include "hmi/CellSession.h"
#include "screens/restart/RestartRun.h"

namespace mtc::screens {

namespace {
constexpr double kInPosition = 0.001;
}

ReposModel::ReposModel(mtc::hmi::CellSession* session, int slot, const RestartRun* run,
                       QObject* parent)
    : QAbstractTableModel(parent), session_(session), slot_(slot), run_(run) {}

bool ReposModel::hasReentry() const {
    return run_->started() && run_->sequence().reentry().valid;
}

double ReposModel::distance(int row) const {
    if (!hasReentry() || row < 0 || row >= rowCount()) return 0.0;
    return run_->sequence().reentry().machine[static_cast<std::size_t>(row)] -
           run_->actualPosition(row);
}

void ReposModel::refresh() {
    if (rowCount() > 0) emit dataChanged(index(0, 0), index(rowCount() - 1, columnCount() - 1));
}

int ReposModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : session_->interpreter(slot_).axes().count();
}

int ReposModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : 4;
}

QVariant ReposModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= rowCount()) return {};
    const int axis = index.row();
    const bool far = std::fabs(distance(axis)) > kInPosition;
    switch (role) {
        case Qt::DisplayRole:
            switch (index.column()) {
                case 0:
                    return QString::fromStdString(session_->interpreter(slot_).axisName(axis));
                case 1:
                    return QString::number(run_->actualPosition(axis), 'f', 3);
                case 2:
                    return hasReentry()
                               ? QString::number(run_->sequence()
                                                     .reentry()
                                                     .machine[static_cast<std::size_t>(axis)],
                                                 'f', 3)
                               : QString("—");
                default:
                    return hasReentry() ? QString::number(distance(axis), 'f', 3) : QString("—");
            }
        case Qt::TextAlignmentRole:
            return index.column() == 0 ? int(Qt::AlignLeft | Qt::AlignVCenter)
                                       : int(Qt::AlignRight | Qt::AlignVCenter);
        case Qt::BackgroundRole:
            return index.column() == 3 && far ? QBrush(QColor(0xff, 0xe8, 0x90)) : QVariant();
        case DistanceRole:
            return distance(axis);
        default:
            return {};
    }
}

QVariant ReposModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    const QString titles[] = {tr("Axis"), tr("Actual position"), tr("Re-entry point"),
                              tr("Distance")};
    return section >= 0 && section < 4 ? titles[section] : QVariant();
}

}  // namespace mtc::screens
