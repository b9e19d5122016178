#pragma once

#include <QElapsedTimer>
#include <QPlainTextEdit>

namespace mtc::screens {

class NcHighlighter;

/// The text area of the program editor: a plain text editor with a gutter
/// of line numbers and NC syntax highlighting of the visible lines only
/// (stays fluent on programs of a million blocks). A text is loaded in one
/// go into a fresh document that no view and no highlighter watches yet
/// (ED-007): a million blocks are usable after about a second.
class NcCodeEdit : public QPlainTextEdit {
    Q_OBJECT
  public:
    explicit NcCodeEdit(QWidget* parent = nullptr);

    /// Replaces the text (undo history cleared, not modified); the whole
    /// text is there when it returns.
    void load(const QString& text);
    /// False: load() is synchronous (kept for callers that wait for it).
    bool loading() const { return false; }
    /// Milliseconds to the first view / to the whole text of the last load
    /// (the same since ED-007's one-go load).
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
    /// The document's modified flag changed (the document is replaced by
    /// every load(), this signal stays).
    void modifiedChanged(bool modified);

  protected:
    void resizeEvent(QResizeEvent* event) override;

  private:
    void updateGutter(const QRect& rect, int dy);
    void highlightVisible();

    QWidget* gutter_;
    NcHighlighter* highlighter_;
    bool highlighting_ = false;
    qint64 firstViewMs_ = 0;
    qint64 loadMs_ = 0;
};

}  // namespace mtc::screens
