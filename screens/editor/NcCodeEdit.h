#pragma once

#include <QElapsedTimer>
#include <QPlainTextEdit>
#include <string>

#include "screens/editor/LineStore.h"

class QMenu;
class QScrollBar;

namespace mtc::screens {

class NcHighlighter;

/// The text area of the program editor: a plain text editor with a gutter
/// of line numbers and NC syntax highlighting of the visible lines only.
/// A text is loaded in one go into a fresh document that no view and no
/// highlighter watches yet (ED-007). With windowing on (the program editor,
/// ED-009) a text of more than kWholeTextLines lines is kept in a LineStore
/// and the document holds only a window of kWindowLines lines around the
/// cursor: the gutter numbers, cursorLine(), goToLine(), lineCount() and
/// the scroll bar refer to the whole text, the window follows the cursor
/// and the view (edits in it are spliced back first), wholeText() and
/// isModified() cover the whole text. Smaller texts are the document as
/// before.
class NcCodeEdit : public QPlainTextEdit {
    Q_OBJECT
  public:
    /// Texts up to this many lines are held whole in the document.
    static constexpr int kWholeTextLines = 20000;
    /// Lines in the document's window over a larger text.
    static constexpr int kWindowLines = 1500;
    /// The window moves when the cursor or the view comes this close to a
    /// window edge that is not the end of the text.
    static constexpr int kWindowMargin = 300;

    explicit NcCodeEdit(QWidget* parent = nullptr);
    ~NcCodeEdit() override;

    /// Allows the window over large texts (takes effect at the next load).
    void setWindowing(bool on) { windowingAllowed_ = on; }
    /// True while the document holds a window of a larger text.
    bool windowed() const { return windowed_; }
    /// Replaces the text (undo history cleared, not modified); the whole
    /// text is there when it returns.
    void load(const QString& text);
    /// The same from UTF-8 (no conversion of the whole text when windowed).
    void load(const std::string& text);
    /// False: load() is synchronous (kept for callers that wait for it).
    bool loading() const { return false; }
    /// Milliseconds to the first view / to the whole text of the last load.
    qint64 firstViewMs() const { return firstViewMs_; }
    qint64 loadMs() const { return loadMs_; }
    /// Puts the cursor on the start of 1-based `line` and centres it.
    void goToLine(int line);
    /// 1-based line of the cursor in the whole text.
    int cursorLine() const;
    /// Lines of the whole text.
    int lineCount() const;
    /// 0-based line of the whole text the document's first block is.
    int windowStart() const { return windowStart_; }
    /// The whole text (with the window's edits).
    QString wholeText();
    /// Whether the whole text differs from the last load / setModified(false).
    bool isModified() const;
    /// Marks the whole text (un)modified, e.g. after it was saved.
    void setModified(bool modified);
    /// The block id ("N0053", "N0053:0001") of the NC block the cursor is
    /// in (continuation lines belong to the line above), "" when none.
    QString cursorBlockId() const;
    NcHighlighter* highlighter() const { return highlighter_; }
    /// The scroll bar over the whole text while windowed (else nullptr).
    QScrollBar* wholeScrollBar() const { return windowed_ ? wholeBar_ : nullptr; }
    /// The context menu at `position` (Qt's standard one; Select all is
    /// disabled while windowed, as its key is). The caller owns it.
    QMenu* contextMenu(const QPoint& position);
    /// Width of the line number gutter in pixels.
    int gutterWidth() const;
    /// Paints the gutter (called by the gutter widget).
    void paintGutter(QPaintEvent* event);

  signals:
    /// A load finished: the whole text is in the editor.
    void loaded();
    /// isModified() changed (the document is replaced by every load() and
    /// window move, this signal stays).
    void modifiedChanged(bool modified);

  protected:
    void resizeEvent(QResizeEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void contextMenuEvent(QContextMenuEvent* event) override;

  private:
    void showDocumentText(const QString& text);
    void updateGutter(const QRect& rect, int dy);
    void updateMargins();
    void highlightVisible();
    void reportModified();
    int pageLines() const;
    bool nearWindowEdge(int local, int extent) const;
    void spliceWindow();
    void moveWindow(int start, int viewTop);
    /// A place in the whole text: 0-based line and column.
    struct TextPoint {
        int line;
        int column;
    };
    TextPoint textPoint(int position) const;
    int documentPosition(const TextPoint& point) const;
    int windowEnd() const { return windowStart_ + document()->blockCount(); }
    void placeCursor(TextPoint position, const TextPoint& anchor, int viewTop);
    void followCursor();
    void followView();
    void syncWholeBar();
    void wholeBarMoved(int top);

    QWidget* gutter_;
    QScrollBar* wholeBar_;
    NcHighlighter* highlighter_;
    bool highlighting_ = false;
    qint64 firstViewMs_ = 0;
    qint64 loadMs_ = 0;
    bool windowingAllowed_ = false;
    bool windowed_ = false;
    bool movingWindow_ = false;
    LineStore store_;            ///< the whole text while windowed
    int windowStart_ = 0;        ///< store line of the document's first block
    int windowLines_ = 1;        ///< store lines the document stood for when shown
    bool windowEdited_ = false;  ///< the document changed since it was shown/spliced
    bool storeModified_ = false;
    bool reportedModified_ = false;
};

}  // namespace mtc::screens
