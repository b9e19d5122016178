#include "screens/programs/ProgramDirectoryModel.h"

#include "hmi/CellSession.h"
#include "hmi/ProgramWorkspace.h"

namespace mtc::screens {

ProgramDirectoryModel::ProgramDirectoryModel(mtc::hmi::CellSession* session, int slot,
                                             const mtc::hmi::ProgramWorkspace* workspace,
                                             QObject* parent)
    : QAbstractListModel(parent), session_(session), slot_(slot), workspace_(workspace) {
    reload();
}

void ProgramDirectoryModel::reload() {
    beginResetModel();
    numbers_.clear();
    for (const auto& program : session_->programs(slot_))
        numbers_.push_back(program->number);
    endResetModel();
}

int ProgramDirectoryModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : numbers_.size();
}

QVariant ProgramDirectoryModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= numbers_.size()) return {};
    const auto program = session_->program(slot_, numbers_[index.row()]);
    if (!program) return {};
    if (role == Qt::DisplayRole) {
        const bool selected = session_->control(slot_).selectedProgram() == program->number;
        const char status =
            workspace_ ? mtc::core::statusLetter(workspace_->status(program->number)) : ' ';
        return QString("%1 %2 [%3] %4")
            .arg(selected ? "→" : " ")
            .arg(program->number, 3, 10, QChar('0'))
            .arg(QChar(status))
            .arg(QString::fromStdString(program->name));
    }
    if (role == Qt::UserRole) return program->number;
    return {};
}

int ProgramDirectoryModel::programAt(int row) const {
    return numbers_.value(row, 0);
}

int ProgramDirectoryModel::rowOf(int number) const {
    return numbers_.indexOf(number);
}

}  // namespace mtc::screens
