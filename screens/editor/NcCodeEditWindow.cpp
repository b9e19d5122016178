// The window of NcCodeEdit over a large text (ED-009): the document holds
// kWindowLines lines of the LineStore; the window moves with the cursor and
// the view, edits are spliced back into the store before it moves.
#include <QContextMenuEvent>
#include <QKeyEvent>
#include <QMenu>
#include <QScrollBar>
#include <QSignalBlocker>
#include <QTextBlock>
#include <algorithm>
#include <climits>
#include <memory>

#include "screens/editor/NcCodeEdit.h"

namespace mtc::screens {

bool NcCodeEdit::nearWindowEdge(int local, int extent) const {
    const int blocks = document()->blockCount();
    if (local < 0 || local + extent > blocks) return true;
    const bool moreAbove = windowStart_ > 0;
    const bool moreBelow = windowStart_ + windowLines_ < store_.count();
    return (moreAbove && local < kWindowMargin) ||
           (moreBelow && local + extent > blocks - kWindowMargin);
}

void NcCodeEdit::spliceWindow() {
    if (!windowed_ || !windowEdited_) return;
    store_.replace(windowStart_, windowLines_, document()->toPlainText());
    windowLines_ = document()->blockCount();
    windowEdited_ = false;
    if (document()->isModified()) storeModified_ = true;
}

void NcCodeEdit::moveWindow(int start, int viewTop) {
    spliceWindow();
    const int total = store_.count();
    start = std::clamp(start, 0, std::max(0, total - kWindowLines));
    // The same place: nothing to do unless edits changed the window's size
    // (a large delete could leave too few lines to move on).
    if (start == windowStart_ && windowLines_ == std::min(kWindowLines, total - start)) return;
    const TextPoint position = textPoint(textCursor().position());
    const TextPoint anchor = textPoint(textCursor().anchor());
    const int top = viewTop >= 0 ? viewTop : windowStart_ + firstVisibleBlock().blockNumber();
    movingWindow_ = true;
    {
        // The view's own signals would report lines of a half-moved window.
        const QSignalBlocker quiet(this);
        setExtraSelections({});  // marks belong to the old document
        windowStart_ = start;
        windowLines_ = std::min(kWindowLines, total - start);
        showDocumentText(store_.text(start, windowLines_));
        placeCursor(position, anchor, top);
        verticalScrollBar()->setValue(top - windowStart_);
    }
    movingWindow_ = false;
    updateMargins();
    syncWholeBar();
    highlightVisible();
    gutter_->update();
    viewport()->update();
    emit cursorPositionChanged();
}

NcCodeEdit::TextPoint NcCodeEdit::textPoint(int position) const {
    const QTextBlock block = document()->findBlock(position);
    return {windowStart_ + block.blockNumber(), position - block.position()};
}

int NcCodeEdit::documentPosition(const TextPoint& point) const {
    const QTextBlock block = document()->findBlockByNumber(point.line - windowStart_);
    return block.position() + std::min(point.column, block.length() - 1);
}

void NcCodeEdit::placeCursor(TextPoint position, const TextPoint& anchor, int viewTop) {
    // The cursor keeps its place unless the window left it (or nearly): it
    // goes to the top line of the view then. A selection stays while its
    // anchor is in the window.
    if (nearWindowEdge(position.line - windowStart_, 1)) {
        position = {std::clamp(viewTop, windowStart_, windowEnd() - 1), 0};
        setTextCursor(QTextCursor(document()->findBlockByNumber(position.line - windowStart_)));
        return;
    }
    QTextCursor cursor(document());
    const int local = anchor.line - windowStart_;
    const bool anchorInside = local >= 0 && local < document()->blockCount();
    cursor.setPosition(documentPosition(anchorInside ? anchor : position));
    cursor.setPosition(documentPosition(position), QTextCursor::KeepAnchor);
    setTextCursor(cursor);
}

void NcCodeEdit::keyPressEvent(QKeyEvent* event) {
    if (windowed_ && event->matches(QKeySequence::SelectAll)) {
        event->accept();  // would select the window only (ED-009)
        return;
    }
    if (windowed_ && (event->modifiers() & Qt::ControlModifier)) {
        if (event->key() == Qt::Key_End) moveWindow(INT_MAX, -1);
        if (event->key() == Qt::Key_Home) moveWindow(0, -1);
    }
    QPlainTextEdit::keyPressEvent(event);
    followCursor();
}

QMenu* NcCodeEdit::contextMenu(const QPoint& position) {
    QMenu* menu = createStandardContextMenu(position);
    for (QAction* action : menu->actions())
        if (windowed_ && action->objectName() == QLatin1String("select-all"))
            action->setEnabled(false);
    return menu;
}

void NcCodeEdit::contextMenuEvent(QContextMenuEvent* event) {
    std::unique_ptr<QMenu> menu(contextMenu(event->pos()));
    menu->exec(event->globalPos());
}

void NcCodeEdit::followCursor() {
    if (!windowed_ || movingWindow_) return;
    const int local = textCursor().blockNumber();
    if (nearWindowEdge(local, 1)) moveWindow(windowStart_ + local - kWindowLines / 2, -1);
}

void NcCodeEdit::followView() {
    if (!windowed_ || movingWindow_) return;
    const int top = verticalScrollBar()->value();
    const int page = std::min(pageLines(), document()->blockCount() - top);
    if (nearWindowEdge(top, std::max(1, page)))
        moveWindow(windowStart_ + top + page / 2 - kWindowLines / 2, windowStart_ + top);
}

void NcCodeEdit::syncWholeBar() {
    if (!windowed_) return;
    const QScrollBar* own = verticalScrollBar();
    const int after = lineCount() - (windowStart_ + document()->blockCount());
    const QSignalBlocker quiet(wholeBar_);
    wholeBar_->setRange(0, windowStart_ + own->maximum() + after);
    wholeBar_->setPageStep(own->pageStep());
    wholeBar_->setSingleStep(1);
    wholeBar_->setValue(windowStart_ + own->value());
}

void NcCodeEdit::wholeBarMoved(int top) {
    if (!windowed_ || movingWindow_) return;
    const int local = top - windowStart_;
    if (local >= 0 && local <= verticalScrollBar()->maximum())
        verticalScrollBar()->setValue(local);  // followView() moves the window when needed
    else
        moveWindow(top + pageLines() / 2 - kWindowLines / 2, top);
}

}  // namespace mtc::screens
