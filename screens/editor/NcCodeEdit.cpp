#include "screens/editor/NcCodeEdit.h"

#include <QFontDatabase>
#include <QPaintEvent>
#include <QPainter>
#include <QRegularExpression>
#include <QTextBlock>

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
constexpr int kChunkLines = 10000;    // lines per load step (~50 ms)

}  // namespace

NcCodeEdit::NcCodeEdit(QWidget* parent) : QPlainTextEdit(parent) {
    setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    setLineWrapMode(QPlainTextEdit::NoWrap);
    gutter_ = new Gutter(this);
    highlighter_ = new NcHighlighter(document());
    connect(this, &QPlainTextEdit::blockCountChanged, this, [this] {
        if (viewportMargins().left() != gutterWidth()) setViewportMargins(gutterWidth(), 0, 0, 0);
    });
    connect(this, &QPlainTextEdit::updateRequest, this, &NcCodeEdit::updateGutter);
    connect(this, &QPlainTextEdit::cursorPositionChanged, gutter_, [this] { gutter_->update(); });
    setViewportMargins(gutterWidth(), 0, 0, 0);
    loadTimer_.setInterval(0);
    connect(&loadTimer_, &QTimer::timeout, this, &NcCodeEdit::loadChunk);
}

void NcCodeEdit::load(const QString& text) {
    if (loadTimer_.isActive()) {
        loadTimer_.stop();
        setReadOnly(readOnlyBefore_);
        setTextInteractionFlags(flagsBefore_);
    }
    loadClock_.start();
    pendingLine_ = 0;
    highlighter_->setWindow(0, kHighlightMargin * 2);
    setUndoRedoEnabled(false);
    clear();
    pending_ = text;
    pendingAt_ = 0;
    readOnlyBefore_ = isReadOnly();
    flagsBefore_ = textInteractionFlags();
    loadChunk();
    firstViewMs_ = loadClock_.elapsed();
    if (pendingAt_ < pending_.size()) {
        // Moving around works while the rest loads; editing waits.
        setReadOnly(true);
        setTextInteractionFlags(Qt::TextSelectableByKeyboard | Qt::TextSelectableByMouse);
        loadTimer_.start();
    }
}

void NcCodeEdit::loadChunk() {
    int end = pendingAt_;
    for (int lines = 0; lines < kChunkLines && end >= 0; ++lines) {
        end = pending_.indexOf('\n', end);
        if (end >= 0) ++end;
    }
    if (end < 0) end = pending_.size();
    // Text is appended at the end; the user's cursor stays where it is.
    const int keep = textCursor().position();
    QTextCursor cursor(document());
    cursor.movePosition(QTextCursor::End);
    cursor.insertText(pending_.mid(pendingAt_, end - pendingAt_));
    if (textCursor().position() != keep) {
        QTextCursor back = textCursor();
        back.setPosition(keep);
        setTextCursor(back);
    }
    pendingAt_ = end;
    document()->setModified(false);
    if (pendingLine_ > 0 && pendingLine_ <= blockCount()) {
        goToLine(pendingLine_);
        pendingLine_ = 0;
    }
    if (pendingAt_ < pending_.size()) return;
    loadTimer_.stop();
    pending_.clear();
    pendingAt_ = 0;
    setUndoRedoEnabled(true);
    setReadOnly(readOnlyBefore_);
    setTextInteractionFlags(flagsBefore_);
    document()->setModified(false);
    highlightVisible();
    loadMs_ = loadClock_.elapsed();
    emit loaded();
}

void NcCodeEdit::goToLine(int line) {
    const QTextBlock block = document()->findBlockByNumber(qMax(0, line - 1));
    if (loading() && line > blockCount()) {
        pendingLine_ = line;  // taken when the loading reaches it
        return;
    }
    if (!block.isValid()) return;
    setTextCursor(QTextCursor(block));
    centerCursor();
    highlightVisible();
}

int NcCodeEdit::cursorLine() const {
    return textCursor().blockNumber() + 1;
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
    for (int count = qMax(1, blockCount()); count >= 10; count /= 10)
        ++digits;
    return 10 + fontMetrics().horizontalAdvance(QLatin1Char('9')) * qMax(4, digits);
}

void NcCodeEdit::resizeEvent(QResizeEvent* event) {
    QPlainTextEdit::resizeEvent(event);
    const QRect area = contentsRect();
    gutter_->setGeometry(QRect(area.left(), area.top(), gutterWidth(), area.height()));
}

void NcCodeEdit::updateGutter(const QRect& rect, int dy) {
    if (dy != 0)
        gutter_->scroll(0, dy);
    else
        gutter_->update(0, rect.y(), gutter_->width(), rect.height());
    highlightVisible();
}

void NcCodeEdit::highlightVisible() {
    if (highlighting_) return;
    highlighting_ = true;
    QTextBlock block = firstVisibleBlock();
    const int first = block.blockNumber();
    const int visible = viewport()->height() / qMax(1, fontMetrics().height()) + 1;
    highlighter_->setWindow(qMax(0, first - kHighlightMargin), first + visible + kHighlightMargin);
    for (int i = 0; i <= visible && block.isValid(); ++i, block = block.next())
        if (block.userState() != 1) highlighter_->rehighlightBlock(block);
    highlighting_ = false;
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
                             QString::number(block.blockNumber() + 1));
        }
        top += height;
        block = block.next();
    }
}

}  // namespace mtc::screens
