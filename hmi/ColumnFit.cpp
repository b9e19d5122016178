#include "hmi/ColumnFit.h"

#include <QEvent>
#include <QFontMetricsF>
#include <QHeaderView>
#include <QRegularExpression>
#include <QScrollBar>
#include <QStyle>
#include <QTableView>
#include <algorithm>
#include <cmath>
#include <numeric>

namespace mtc::hmi {

std::vector<int> fitColumnWidths(const std::vector<ColumnNeed>& needs, int available) {
    std::vector<int> widths;
    int words = 0;
    for (const ColumnNeed& need : needs) {
        widths.push_back(need.word);
        words += need.word;
    }
    if (widths.empty() || words >= available) return widths;
    const auto lacks = [&needs](std::size_t i) {
        return std::max(0, needs[i].line - needs[i].word);
    };
    // Shared out evenly; a column that lacks less than its share gets its
    // lines whole and leaves the rest of its share to the others (the
    // columns that lack least first).
    std::vector<std::size_t> order(needs.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&lacks](std::size_t a, std::size_t b) { return lacks(a) < lacks(b); });
    int spare = available - words;
    std::size_t next = 0;
    for (; next < order.size(); ++next) {
        const int share = spare / static_cast<int>(order.size() - next);
        if (lacks(order[next]) > share) break;
        widths[order[next]] += lacks(order[next]);
        spare -= lacks(order[next]);
    }
    for (std::size_t k = next; k < order.size(); ++k)
        widths[order[k]] += spare / static_cast<int>(order.size() - next);
    // Rounding and what no line needs: to the last column, so the table
    // fills its view.
    widths.back() += available - std::accumulate(widths.begin(), widths.end(), 0);
    return widths;
}

namespace {

/// Pixels of `text` in `metrics`, up to the next whole pixel and one more:
/// the painter lays the text out in fractions of a pixel (QTextLayout) and
/// wraps a line that is a fraction too wide.
int widthOf(const QString& text, const QFontMetricsF& metrics) {
    return static_cast<int>(std::ceil(metrics.horizontalAdvance(text))) + 1;
}

/// The longest word and line of `text` in `metrics`, plus `margin`.
ColumnNeed needOf(const QString& text, const QFontMetricsF& metrics, int margin) {
    static const QRegularExpression blanks("\\s+");
    ColumnNeed need;
    for (const QString& line : text.split('\n')) {
        need.line = std::max(need.line, widthOf(line, metrics) + margin);
        for (const QString& word : line.split(blanks, Qt::SkipEmptyParts))
            need.word = std::max(need.word, widthOf(word, metrics) + margin);
    }
    return need;
}

void widen(ColumnNeed& need, const ColumnNeed& by) {
    need.word = std::max(need.word, by.word);
    need.line = std::max(need.line, by.line);
}

}  // namespace

ColumnFit::ColumnFit(QTableView* table) : QObject(table), table_(table) {
    table->setWordWrap(true);
    table->setTextElideMode(Qt::ElideRight);
    table->horizontalHeader()->setStretchLastSection(false);
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    table->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    // Always there: a scroll bar that came and went with the row heights
    // would change the width the columns share, and so the row heights.
    table->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOn);
    table->installEventFilter(this);
    table->viewport()->installEventFilter(this);
    if (QAbstractItemModel* model = table->model()) {
        connect(model, &QAbstractItemModel::modelReset, this, &ColumnFit::fit);
        connect(model, &QAbstractItemModel::layoutChanged, this, &ColumnFit::fit);
        connect(model, &QAbstractItemModel::rowsInserted, this, &ColumnFit::fit);
    }
}

std::vector<ColumnNeed> ColumnFit::measure() const {
    const QAbstractItemModel* model = table_->model();
    if (model == nullptr) return {};
    // The item delegate's text margin on each side, and the grid line the
    // column's width includes.
    const int cellMargin =
        2 * (table_->style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, table_) + 1) +
        (table_->showGrid() ? 1 : 0);
    const QHeaderView* header = table_->horizontalHeader();
    std::vector<ColumnNeed> needs(static_cast<std::size_t>(model->columnCount()));
    for (int column = 0; column < model->columnCount(); ++column) {
        ColumnNeed& need = needs[static_cast<std::size_t>(column)];
        // A title is not broken: it must fit on its line, as the header
        // measures it (bold, as it is drawn while a row is selected).
        const int title = header->sectionSizeHint(column);
        widen(need, {title, title});
        for (int row = 0; row < model->rowCount(); ++row) {
            // A text across several columns (a heading) has their widths
            // (and the cells it covers show nothing).
            if (table_->columnSpan(row, column) > 1) continue;
            const QModelIndex index = model->index(row, column);
            const QVariant font = index.data(Qt::FontRole);
            const QFontMetricsF metrics(font.isValid() ? font.value<QFont>().resolve(table_->font())
                                                       : table_->font());
            widen(need, needOf(index.data(Qt::DisplayRole).toString(), metrics, cellMargin));
        }
    }
    return needs;
}

void ColumnFit::fit() {
    if (fitting_) return;
    fitting_ = true;  // resizing sections resizes the viewport: no second fit from there
    const std::vector<int> widths = fitColumnWidths(measure(), table_->viewport()->width());
    for (std::size_t i = 0; i < widths.size(); ++i)
        table_->horizontalHeader()->resizeSection(static_cast<int>(i), widths[i]);
    table_->resizeRowsToContents();
    fitting_ = false;
}

bool ColumnFit::eventFilter(QObject* watched, QEvent* event) {
    const bool resized = watched == table_->viewport() && event->type() == QEvent::Resize;
    const bool restyled = watched == table_ &&
                          (event->type() == QEvent::FontChange ||
                           event->type() == QEvent::StyleChange || event->type() == QEvent::Show);
    if (resized || restyled) fit();
    return QObject::eventFilter(watched, event);
}

}  // namespace mtc::hmi
