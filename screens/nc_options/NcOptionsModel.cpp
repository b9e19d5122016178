#include "screens/nc_options/NcOptionsModel.h"

#include "cnc_core/compiler/NcOptions.h"
#include "hmi/NcOptionsHolder.h"

namespace mtc::screens {

NcOptionsModel::NcOptionsModel(mtc::hmi::NcOptionsHolder* holder, QObject* parent)
    : QAbstractListModel(parent), holder_(holder) {
    rebuild();
    connect(holder_, &mtc::hmi::NcOptionsHolder::optionsChanged, this, [this] { rebuild(); });
}

void NcOptionsModel::rebuild() {
    beginResetModel();
    rows_ = {{RowKind::CompilerActive}, {RowKind::UserCompiler, 1}, {RowKind::UserCompiler, 2},
             {RowKind::Indramat},       {RowKind::UserCompiler, 3}, {RowKind::UserCompiler, 4},
             {RowKind::SyntaxCheck}};
    const int macros = static_cast<int>(holder_->globalMacros().size());
    for (int i = 0; i < macros; ++i)
        rows_.push_back({RowKind::Macro, i});
    rows_.push_back({RowKind::NewMacro, macros});
    endResetModel();
}

int NcOptionsModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : rows_.size();
}

NcOptionsModel::Row NcOptionsModel::rowAt(int row) const {
    if (row < 0 || row >= rows_.size()) return rows_.back();
    return rows_[row];
}

int NcOptionsModel::rowOfMacro(int index) const {
    for (int row = 0; row < rows_.size(); ++row)
        if ((rows_[row].kind == RowKind::Macro && rows_[row].index == index) ||
            rows_[row].kind == RowKind::NewMacro)
            return row;
    return rows_.size() - 1;
}

QString NcOptionsModel::macroEntry(int index) const {
    const auto& macros = holder_->globalMacros();
    if (index < 0 || index >= static_cast<int>(macros.size())) return "DEFINE ";
    const auto& macro = macros[static_cast<std::size_t>(index)];
    return QString::fromStdString("DEFINE " + macro.name + " AS " + macro.body);
}

QString NcOptionsModel::text(const Row& row) const {
    switch (row.kind) {
        case RowKind::CompilerActive:
            return tr("Compiler active:          %1")
                .arg(holder_->compilerActive() ? tr("Yes") : tr("No"));
        case RowKind::UserCompiler: {
            const std::string& command =
                mtc::core::userCompilerCommand(holder_->userCompilers(), row.index);
            // D-010: a command that came with the folder is marked until approved.
            return "  " +
                   tr("User compiler %1:        %2%3")
                       .arg(row.index)
                       .arg(command.empty() ? QString("\u2014") : QString::fromStdString(command))
                       .arg(holder_->userCompilerApproved(row.index)
                                ? QString()
                                : "   " + tr("[from the folder: asks before it runs]"));
        }
        case RowKind::Indramat:
            return "  " + tr("INDRAMAT compiler:      %1")
                              .arg(holder_->compilerActive() ? tr("active") : tr("not active"));
        case RowKind::SyntaxCheck:
            return "  " + tr("Syntax check:           in the controller at download");
        case RowKind::Macro:
            return tr("Global macro  %1").arg(macroEntry(row.index));
        case RowKind::NewMacro:
            return tr("Global macro  <new>");
    }
    return {};
}

QVariant NcOptionsModel::data(const QModelIndex& index, int role) const {
    if (role != Qt::DisplayRole || !index.isValid() || index.row() >= rows_.size()) return {};
    return text(rows_[index.row()]);
}

}  // namespace mtc::screens
