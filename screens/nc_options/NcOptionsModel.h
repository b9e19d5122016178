#pragma once

#include <QAbstractListModel>
#include <QVector>

namespace mtc::hmi {
class NcOptionsHolder;
}

namespace mtc::screens {

/// The rows of the NC options screen (seed 001 ch. 7, 8, 4): "Compiler
/// active", the compiler chain in its calling order (user compilers 1, 2,
/// INDRAMAT compiler, user compilers 3, 4, syntax check), then the global
/// macros and a last row to add one. Follows the holder.
class NcOptionsModel : public QAbstractListModel {
    Q_OBJECT
  public:
    enum class RowKind { CompilerActive, UserCompiler, Indramat, SyntaxCheck, Macro, NewMacro };
    struct Row {
        RowKind kind = RowKind::CompilerActive;
        int index = 0;  ///< user compiler slot 1..4 or macro index
    };

    explicit NcOptionsModel(mtc::hmi::NcOptionsHolder* holder, QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;

    /// What row `row` is (a NewMacro row for rows outside).
    Row rowAt(int row) const;
    /// Row of global macro `index`, of the "new macro" row for an index past
    /// the end.
    int rowOfMacro(int index) const;
    /// The global macro `index` as the operator types it.
    QString macroEntry(int index) const;

  private:
    void rebuild();
    QString text(const Row& row) const;

    mtc::hmi::NcOptionsHolder* holder_;
    QVector<Row> rows_;
};

}  // namespace mtc::screens
