#include "screens/editor/NcCodeEdit.h"

#include <QFontDatabase>
#include <QKeyEvent>
#include <QPaintEvent>
#include <QPainter>
#include <QPlainTextDocumentLayout>
#include <QPointer>
#include <QRegularExpression>
#include <QScrollBar>
#include <QSignalBlocker>
#include <QTextBlock>
#include <algorithm>
#include <climits>

#include "screens/editor/NcHighlighter.h"

namespace mtc::screens {

namespace {

/// The gutter left of the text: it only forwards painting to the editor.
class Gutter : public QWidget {
  public:
    explicit Gutter(NcCodeEdit* editor) : QWidget(editor), editor_(editor) {
        setObjectName("editorGutter");
    }
    QSize sizeHint() const override { return {editor_->gutterWidth(), 0}; }

  protected:
    void paintEvent(QPaintEvent* event) override { editor_->paintGutter(event); }

  private:
    NcCodeEdit* editor_;
};

constexpr int kHighlightMargin = 40;  // lines highlighted above/below the view

}  // namespace

NcCodeEdit::NcCodeEdit(QWidget* parent) : QPlainTextEdit(parent) {
    setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    setLineWrapMode(QPlainTextEdit::NoWrap);
    gutter_ = new Gutter(this);
    wholeBar_ = new QScrollBar(Qt::Vertical, this);
    wholeBar_->setObjectName("editorWholeScrollBar");
    wholeBar_->setFocusPolicy(Qt::NoFocus);  // keys stay with the text
    wholeBar_->hide();
    connect(wholeBar_, &QScrollBar::valueChanged, this, &NcCodeEdit::wholeBarMoved);
    highlighter_ = new NcHighlighter(document());
    highlighter_->setParent(this);  // outlives the documents load() replaces
    connect(this, &QPlainTextEdit::blockCountChanged, this, &NcCodeEdit::updateMargins);
    connect(this, &QPlainTextEdit::updateRequest, this, &NcCodeEdit::updateGutter);
    connect(this, &QPlainTextEdit::cursorPositionChanged, gutter_, [this] { gutter_->update(); });
    // Cursor moves by mouse or by a caller: the window follows once the
    // event is done (keys follow at once, keyPressEvent()).
    connect(this, &QPlainTextEdit::cursorPositionChanged, this, [this] {
        if (windowed_ && !movingWindow_)
            QMetaObject::invokeMethod(this, &NcCodeEdit::followCursor, Qt::QueuedConnection);
    });
    connect(verticalScrollBar(), &QScrollBar::valueChanged, this, [this] {
        syncWholeBar();
        if (windowed_ && !movingWindow_)
            QMetaObject::invokeMethod(this, &NcCodeEdit::followView, Qt::QueuedConnection);
    });
    connect(verticalScrollBar(), &QScrollBar::rangeChanged, this, &NcCodeEdit::syncWholeBar);
    updateMargins();
    connect(document(), &QTextDocument::modificationChanged, this, &NcCodeEdit::reportModified);
}

NcCodeEdit::~NcCodeEdit() {
    // QPlainTextEdit's teardown still changes the document and the scroll
    // bar after this part of the object is gone; their signals must not reach
    // the lambdas above (UBSan: member access in a destroyed NcCodeEdit).
    if (document()) document()->disconnect(this);
    verticalScrollBar()->disconnect(this);
    disconnect(this, nullptr, this, nullptr);
}

void NcCodeEdit::load(const QString& text) {
    if (windowingAllowed_ && text.count(QLatin1Char('\n')) >= kWholeTextLines) {
        load(text.toStdString());
        return;
    }
    QElapsedTimer clock;
    clock.start();
    windowed_ = false;
    store_ = LineStore();
    windowStart_ = 0;
    storeModified_ = false;
    setVerticalScrollBarPolicy(Qt::ScrollBarAsNeeded);
    showDocumentText(text);
    updateMargins();
    firstViewMs_ = loadMs_ = clock.elapsed();
    reportedModified_ = false;
    emit modifiedChanged(false);
    emit loaded();
}

void NcCodeEdit::load(const std::string& text) {
    QElapsedTimer clock;
    clock.start();
    LineStore store(windowingAllowed_ ? text : std::string());
    if (store.count() <= kWholeTextLines) {
        load(QString::fromStdString(text));
        return;
    }
    // ED-009: the whole text in the line store, a window of it in the view.
    store_ = std::move(store);
    windowed_ = true;
    storeModified_ = false;
    windowStart_ = 0;
    windowLines_ = std::min(kWindowLines, store_.count());
    setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    showDocumentText(store_.text(0, windowLines_));
    updateMargins();
    syncWholeBar();
    firstViewMs_ = loadMs_ = clock.elapsed();
    reportedModified_ = false;
    emit modifiedChanged(false);
    emit loaded();
}

void NcCodeEdit::showDocumentText(const QString& text) {
    // ED-007: the text goes into a fresh document while no view lays it out
    // and no highlighter formats it.
    auto* fresh = new QTextDocument(this);
    fresh->setDocumentLayout(new QPlainTextDocumentLayout(fresh));
    fresh->setDefaultFont(font());
    fresh->setUndoRedoEnabled(false);
    fresh->setPlainText(text);
    fresh->setUndoRedoEnabled(true);
    fresh->setModified(false);
    const QPointer<QTextDocument> old = document();  // the view may delete its own
    highlighting_ = true;  // no highlighting while the highlighter is on the old text
    setDocument(fresh);
    // Deleted before the highlighter moves: it would clear the formats of
    // every block of the old text (a layout per block) otherwise.
    if (old && old->parent() == this) delete old;
    connect(fresh, &QTextDocument::modificationChanged, this, &NcCodeEdit::reportModified);
    highlighter_->setWindow(0, kHighlightMargin * 2);
    highlighter_->setDocument(fresh);
    highlighting_ = false;
    // setDocument() schedules a rehighlight of every block; a contents
    // change cancels it (QSyntaxHighlighter formats the changed block and
    // the next ones while their state changes: the window only).
    emit fresh->contentsChange(0, 0, 0);
    windowEdited_ = false;
    // An edit of the window (the highlighter's own format changes come
    // while highlighting_ is set and change no text).
    connect(fresh, &QTextDocument::contentsChange, this, [this](int, int removed, int added) {
        if (!highlighting_ && (removed != 0 || added != 0)) windowEdited_ = true;
    });
    highlightVisible();
}

void NcCodeEdit::goToLine(int line) {
    const int target = std::clamp(line - 1, 0, lineCount() - 1);
    if (windowed_ && nearWindowEdge(target - windowStart_, 1))
        moveWindow(target - kWindowLines / 2, -1);
    const QTextBlock block = document()->findBlockByNumber(target - windowStart_);
    if (!block.isValid()) return;
    setTextCursor(QTextCursor(block));
    centerCursor();
    highlightVisible();
}

int NcCodeEdit::cursorLine() const {
    return windowStart_ + textCursor().blockNumber() + 1;
}

int NcCodeEdit::lineCount() const {
    if (!windowed_) return blockCount();
    return store_.count() - windowLines_ + document()->blockCount();
}

QString NcCodeEdit::wholeText() {
    if (!windowed_) return toPlainText();
    spliceWindow();
    return QString::fromStdString(store_.whole());
}

bool NcCodeEdit::isModified() const {
    return storeModified_ || document()->isModified();
}

void NcCodeEdit::setModified(bool modified) {
    if (!modified) storeModified_ = false;
    document()->setModified(modified);
    reportModified();
}

void NcCodeEdit::reportModified() {
    const bool now = isModified();
    if (now == reportedModified_) return;
    reportedModified_ = now;
    emit modifiedChanged(now);
}

QString NcCodeEdit::cursorBlockId() const {
    static const QRegularExpression id(R"(^\s*[/:]?\s*(N\d+(:\d+)?))");
    QTextBlock block = textCursor().block();
    for (int up = 0; up < 4 && block.isValid(); ++up, block = block.previous()) {
        const QString text = block.text();
        const auto match = id.match(text);
        if (match.hasMatch()) return match.captured(1);
        if (!text.startsWith("      ")) return {};  // not a continuation line
    }
    return {};
}

int NcCodeEdit::gutterWidth() const {
    int digits = 1;
    for (int count = qMax(1, lineCount()); count >= 10; count /= 10)
        ++digits;
    return 10 + fontMetrics().horizontalAdvance(QLatin1Char('9')) * qMax(4, digits);
}

void NcCodeEdit::updateMargins() {
    const int right = windowed_ ? wholeBar_->sizeHint().width() : 0;
    const QMargins wanted(gutterWidth(), 0, right, 0);
    if (viewportMargins() != wanted) setViewportMargins(wanted);
    wholeBar_->setVisible(windowed_);
    const QRect area = contentsRect();
    gutter_->setGeometry(QRect(area.left(), area.top(), gutterWidth(), area.height()));
    const QRect view = viewport()->geometry();
    wholeBar_->setGeometry(QRect(view.right() + 1, view.top(), right, view.height()));
}

void NcCodeEdit::resizeEvent(QResizeEvent* event) {
    QPlainTextEdit::resizeEvent(event);
    updateMargins();
}

void NcCodeEdit::updateGutter(const QRect& rect, int dy) {
    if (dy != 0) {
        gutter_->scroll(0, dy);
        // QPlainTextEdit moves its scroll bar with the bar's signals blocked.
        syncWholeBar();
        if (windowed_ && !movingWindow_)
            QMetaObject::invokeMethod(this, &NcCodeEdit::followView, Qt::QueuedConnection);
    } else
        gutter_->update(0, rect.y(), gutter_->width(), rect.height());
    highlightVisible();
}

void NcCodeEdit::highlightVisible() {
    if (highlighting_) return;
    highlighting_ = true;
    QTextBlock block = firstVisibleBlock();
    const int first = block.blockNumber();
    const int visible = pageLines() + 1;
    highlighter_->setWindow(qMax(0, first - kHighlightMargin), first + visible + kHighlightMargin);
    for (int i = 0; i <= visible && block.isValid(); ++i, block = block.next())
        if (block.userState() != kHighlighted) highlighter_->rehighlightBlock(block);
    highlighting_ = false;
}

int NcCodeEdit::pageLines() const {
    return viewport()->height() / qMax(1, fontMetrics().height());
}

void NcCodeEdit::paintGutter(QPaintEvent* event) {
    QPainter painter(gutter_);
    painter.fillRect(event->rect(), QColor(232, 232, 226));
    painter.setPen(QColor(120, 120, 120));
    QTextBlock block = firstVisibleBlock();
    int top = qRound(blockBoundingGeometry(block).translated(contentOffset()).top());
    const int current = textCursor().blockNumber();
    while (block.isValid() && top <= event->rect().bottom()) {
        const int height = qRound(blockBoundingRect(block).height());
        if (block.isVisible() && top + height >= event->rect().top()) {
            QFont font = painter.font();
            font.setBold(block.blockNumber() == current);
            painter.setFont(font);
            painter.drawText(0, top, gutter_->width() - 5, fontMetrics().height(), Qt::AlignRight,
                             QString::number(windowStart_ + block.blockNumber() + 1));
        }
        top += height;
        block = block.next();
    }
}

}  // namespace mtc::screens
