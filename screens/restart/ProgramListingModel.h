#pragma once

#include <QAbstractListModel>
#include <cstdint>
#include <memory>

#include "cnc_core/language/Program.h"

namespace mtc::core {
class ProgramScan;
}

namespace mtc::screens {

/// The listing of one program as the restart screen shows it: one row per
/// source line from the first block to the last, comment lines included.
/// Virtual: a row's text is cut out of the source when the view asks for it
/// (O(log n) to find its block), so a 1,000,000-block program needs no copy
/// and no line table. The rows of the cursor block and of the start block
/// carry their own colours.
class ProgramListingModel : public QAbstractListModel {
    Q_OBJECT
  public:
    /// Role with the block index (uint) a row belongs to.
    static constexpr int BlockRole = Qt::UserRole + 1;

    /// An empty listing; setProgram() fills it.
    explicit ProgramListingModel(QObject* parent = nullptr);
    ~ProgramListingModel() override;

    /// Shows `program` (nullptr = nothing); resets the model.
    void setProgram(mtc::core::ProgramPtr program);
    const mtc::core::ProgramPtr& program() const { return program_; }
    /// Highlights the rows of block `cursor` as the cursor and of `start` (or
    /// -1 for none) as the start block. Emits marksChanged(), not dataChanged():
    /// the view repaints what it shows (see the .cpp).
    void setMarks(std::uint32_t cursor, std::int64_t start);

    int rowCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    /// First row of block `block`.
    int rowOfBlock(std::uint32_t block) const;
    /// Number of rows of block `block` (its continuation lines).
    int rowsOfBlock(std::uint32_t block) const;
    /// Block shown on row `row` (a comment row belongs to the block above it).
    std::uint32_t blockOfRow(int row) const;
    /// The text of row `row` without its line break.
    QString lineText(int row) const;

  signals:
    /// The cursor or start block rows changed: repaint the visible rows.
    void marksChanged();

  private:
    mtc::core::ProgramPtr program_;
    std::unique_ptr<mtc::core::ProgramScan> scan_;
    std::uint32_t firstLine_ = 1;
    int rows_ = 0;
    std::uint32_t cursor_ = 0;
    std::int64_t start_ = -1;
};

}  // namespace mtc::screens
