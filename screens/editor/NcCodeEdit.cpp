#include "screens/editor/NcCodeEdit.h"

#include <QFontDatabase>
#include <QPaintEvent>
#include <QPainter>
#include <QPlainTextDocumentLayout>
#include <QPointer>
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

}  // namespace

NcCodeEdit::NcCodeEdit(QWidget* parent) : QPlainTextEdit(parent) {
    setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    setLineWrapMode(QPlainTextEdit::NoWrap);
    gutter_ = new Gutter(this);
    highlighter_ = new NcHighlighter(document());
    highlighter_->setParent(this);  // outlives the documents load() replaces
    connect(this, &QPlainTextEdit::blockCountChanged, this, [this] {
        if (viewportMargins().left() != gutterWidth()) setViewportMargins(gutterWidth(), 0, 0, 0);
    });
    connect(this, &QPlainTextEdit::updateRequest, this, &NcCodeEdit::updateGutter);
    connect(this, &QPlainTextEdit::cursorPositionChanged, gutter_, [this] { gutter_->update(); });
    setViewportMargins(gutterWidth(), 0, 0, 0);
    connect(document(), &QTextDocument::modificationChanged, this, &NcCodeEdit::modifiedChanged);
}

void NcCodeEdit::load(const QString& text) {
    QElapsedTimer clock;
    clock.start();
    // ED-007: the text goes into a fresh document while no view lays it out
    // and no highlighter formats it (neither looks at a million blocks).
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
    connect(fresh, &QTextDocument::modificationChanged, this, &NcCodeEdit::modifiedChanged);
    highlighter_->setWindow(0, kHighlightMargin * 2);
    highlighter_->setDocument(fresh);
    highlighting_ = false;
    // setDocument() schedules a rehighlight of every block; a contents
    // change cancels it (QSyntaxHighlighter formats the changed block and
    // the next ones while their state changes: the window only).
    emit fresh->contentsChange(0, 0, 0);
    setViewportMargins(gutterWidth(), 0, 0, 0);
    highlightVisible();
    firstViewMs_ = loadMs_ = clock.elapsed();
    emit modifiedChanged(false);
    emit loaded();
}

void NcCodeEdit::goToLine(int line) {
    const QTextBlock block = document()->findBlockByNumber(qMax(0, line - 1));
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
        if (block.userState() != kHighlighted) highlighter_->rehighlightBlock(block);
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
