#pragma once

#include <QSyntaxHighlighter>
#include <QTextCharFormat>

namespace mtc::screens {

/// Syntax highlighting of NC source text: block numbers (N0053, N0053:0001),
/// G and M words, NC keywords, the compiler's keywords, comments (';') and
/// the .DAT identification and header lines. Only blocks inside the window
/// set with setWindow() are highlighted, so a program of a million blocks
/// loads without formatting every line; the editor highlights what becomes
/// visible (block state kHighlighted = highlighted; a block outside the
/// window keeps its state, so QSyntaxHighlighter's "state changed, format
/// the next block too" never runs through the whole document).
/// Block state of a highlighted block.
constexpr int kHighlighted = 1;

class NcHighlighter : public QSyntaxHighlighter {
    Q_OBJECT
  public:
    explicit NcHighlighter(QTextDocument* document);

    /// Blocks first..last (block numbers) are highlighted from now on.
    void setWindow(int first, int last);

    /// Kinds of tokens (for tests and the legend).
    enum class Token { BlockNumber, GWord, MWord, Keyword, CompilerKeyword, Comment, Header };
    /// The format of a token kind.
    QTextCharFormat format(Token token) const;

  protected:
    void highlightBlock(const QString& text) override;

  private:
    int wordEnd(const QString& text, int from) const;
    void highlightWord(const QString& text, int start, int end);

    QTextCharFormat formats_[7];
    int first_ = 0;
    int last_ = 200;
};

}  // namespace mtc::screens
