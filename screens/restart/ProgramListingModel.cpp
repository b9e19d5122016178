#include "screens/restart/ProgramListingModel.h"

#include <QBrush>
#include <QColor>

#include "cnc_core/restart/ProgramScan.h"

namespace mtc::screens {

ProgramListingModel::ProgramListingModel(QObject* parent) : QAbstractListModel(parent) {}

ProgramListingModel::~ProgramListingModel() = default;

void ProgramListingModel::setProgram(mtc::core::ProgramPtr program) {
    beginResetModel();
    program_ = std::move(program);
    scan_.reset();
    rows_ = 0;
    firstLine_ = 1;
    cursor_ = 0;
    start_ = -1;
    if (program_ && !program_->blocks.empty()) {
        scan_ = std::make_unique<mtc::core::ProgramScan>(program_);
        const auto first = program_->blocks.front();
        const auto last = program_->blocks.back();
        firstLine_ = first.line;
        rows_ = static_cast<int>(last.line + last.lineCount - first.line);
    }
    endResetModel();
}

int ProgramListingModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : rows_;
}

int ProgramListingModel::rowOfBlock(std::uint32_t block) const {
    if (!program_ || block >= program_->blocks.size()) return -1;
    return static_cast<int>(program_->blocks[block].line - firstLine_);
}

int ProgramListingModel::rowsOfBlock(std::uint32_t block) const {
    if (!program_ || block >= program_->blocks.size()) return 0;
    return program_->blocks[block].lineCount;
}

std::uint32_t ProgramListingModel::blockOfRow(int row) const {
    if (!scan_ || row < 0) return 0;
    return scan_->blockAtLine(firstLine_ + static_cast<std::uint32_t>(row));
}

QString ProgramListingModel::lineText(int row) const {
    if (!scan_ || row < 0 || row >= rows_) return {};
    const std::uint32_t line = firstLine_ + static_cast<std::uint32_t>(row);
    const auto block = program_->blocks[scan_->blockAtLine(line)];
    const std::string_view source = program_->source.view();
    // From the start of the block's first line, skip to the wanted line.
    std::size_t at = std::min<std::size_t>(block.sourceText.offset, source.size());
    while (at > 0 && source[at - 1] != '\n')
        --at;
    for (std::uint32_t skip = block.line; skip < line; ++skip) {
        const std::size_t newline = source.find('\n', at);
        if (newline == std::string::npos) return {};
        at = newline + 1;
    }
    std::size_t end = std::min(source.find('\n', at), source.size());
    if (end > at && source[end - 1] == '\r') --end;
    QString text = QString::fromUtf8(source.data() + at, static_cast<int>(end - at));
    text.replace('\t', "    ");
    return text;
}

QVariant ProgramListingModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= rows_) return {};
    switch (role) {
        case Qt::DisplayRole:
            return lineText(index.row());
        case BlockRole:
            return blockOfRow(index.row());
        case Qt::BackgroundRole:
        case Qt::ForegroundRole: {
            const std::uint32_t block = blockOfRow(index.row());
            const int first = rowOfBlock(block);
            const bool inBlock = index.row() < first + rowsOfBlock(block);
            const bool cursor = inBlock && block == cursor_;
            const bool start = inBlock && static_cast<std::int64_t>(block) == start_;
            if (role == Qt::ForegroundRole) return cursor ? QBrush(Qt::white) : QVariant();
            if (cursor) return QBrush(QColor(0x00, 0x30, 0x7a));
            if (start) return QBrush(QColor(0xd8, 0xf0, 0xc8));
            return {};
        }
        default:
            return {};
    }
}

void ProgramListingModel::setMarks(std::uint32_t cursor, std::int64_t start) {
    if (cursor == cursor_ && start == start_) return;
    cursor_ = cursor;
    start_ = start;
    // Not dataChanged(): QListView answers it with a relayout of every row,
    // which costs tens of milliseconds on a 1,000,000-line listing.
    emit marksChanged();
}

}  // namespace mtc::screens
