#pragma once

#include <QElapsedTimer>
#include <QPlainTextEdit>
#include <QTimer>

namespace mtc::screens {

class NcHighlighter;

/// The text area of the program editor: a plain text editor with a gutter
/// of line numbers and NC syntax highlighting of the visible lines only
/// (stays fluent on programs of a million blocks). Long texts are loaded in
/// chunks: the first lines show at once, the rest follows in the background
/// (read-only until loaded).
class NcCodeEdit : public QPlainTextEdit {
    Q_OBJECT
  public:
    explicit NcCodeEdit(QWidget* parent = nullptr);

    /// Replaces the text (undo history cleared, not modified): the first
    /// chunk now, the rest from the event loop (loading() until then).
    void load(const QString& text);
    /// True while a text is still being loaded.
    bool loading() const { return loadTimer_.isActive(); }
    /// Milliseconds to the first view / to the whole text of the last load.
    qint64 firstViewMs() const { return firstViewMs_; }
    qint64 loadMs() const { return loadMs_; }
    /// Puts the cursor on the start of 1-based `line` and centres it.
    void goToLine(int line);
    /// 1-based line of the cursor.
    int cursorLine() const;
    /// The block id ("N0053", "N0053:0001") of the NC block the cursor is
    /// in (continuation lines belong to the line above), "" when none.
    QString cursorBlockId() const;
    NcHighlighter* highlighter() const { return highlighter_; }
    /// Width of the line number gutter in pixels.
    int gutterWidth() const;
    /// Paints the gutter (called by the gutter widget).
    void paintGutter(QPaintEvent* event);

  signals:
    /// A load finished: the whole text is in the editor.
    void loaded();

  protected:
    void resizeEvent(QResizeEvent* event) override;

  private:
    void loadChunk();
    void updateGutter(const QRect& rect, int dy);
    void highlightVisible();

    QWidget* gutter_;
    NcHighlighter* highlighter_;
    bool highlighting_ = false;
    QTimer loadTimer_;
    QElapsedTimer loadClock_;
    QString pending_;      ///< text still to be loaded
    int pendingAt_ = 0;    ///< offset in pending_ of the next chunk
    int pendingLine_ = 0;  ///< goToLine() target beyond the loaded lines
    bool readOnlyBefore_ = false;
    Qt::TextInteractionFlags flagsBefore_;
    qint64 firstViewMs_ = 0;
    qint64 loadMs_ = 0;
};

}  // namespace mtc::screens
