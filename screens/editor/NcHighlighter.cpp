#include "screens/editor/NcHighlighter.h"

#include "cnc_core/language/Keywords.h"

namespace mtc::screens {

namespace {

QTextCharFormat makeFormat(const QColor& color, bool bold = false, bool italic = false) {
    QTextCharFormat format;
    format.setForeground(color);
    if (bold) format.setFontWeight(QFont::Bold);
    format.setFontItalic(italic);
    return format;
}

bool isHeaderLine(const QString& text) {
    if (text.isEmpty()) return false;
    const QChar c = text[0];
    return c == '%' || c == '$' || c == '#' || c == '!' || c == '*' || text.startsWith("iMTc");
}

bool isWordChar(QChar c) {
    return c.isLetterOrNumber() || c == '_';
}

}  // namespace

NcHighlighter::NcHighlighter(QTextDocument* document) : QSyntaxHighlighter(document) {
    formats_[int(Token::BlockNumber)] = makeFormat(QColor(0, 70, 160), true);
    formats_[int(Token::GWord)] = makeFormat(QColor(150, 30, 30), true);
    formats_[int(Token::MWord)] = makeFormat(QColor(20, 120, 40), true);
    formats_[int(Token::Keyword)] = makeFormat(QColor(0, 120, 130), true);
    formats_[int(Token::CompilerKeyword)] = makeFormat(QColor(150, 0, 150), true);
    formats_[int(Token::Comment)] = makeFormat(QColor(110, 110, 110), false, true);
    formats_[int(Token::Header)] = makeFormat(QColor(120, 90, 0));
}

void NcHighlighter::setWindow(int first, int last) {
    first_ = first;
    last_ = last;
}

QTextCharFormat NcHighlighter::format(Token token) const {
    return formats_[int(token)];
}

void NcHighlighter::highlightBlock(const QString& text) {
    const int number = currentBlock().blockNumber();
    if (number < first_ || number > last_) {
        if (currentBlockState() == kHighlighted) setCurrentBlockState(-1);
        return;
    }
    setCurrentBlockState(kHighlighted);
    if (isHeaderLine(text)) {
        QSyntaxHighlighter::setFormat(0, text.size(), format(Token::Header));
        return;
    }
    int i = 0;
    while (i < text.size()) {
        const QChar c = text[i];
        if (c == ';') {
            QSyntaxHighlighter::setFormat(i, text.size() - i, format(Token::Comment));
            return;
        }
        if (!c.isLetter() && c != '_') {
            ++i;
            continue;
        }
        const int end = wordEnd(text, i);
        highlightWord(text, i, end);
        i = end;
    }
}

int NcHighlighter::wordEnd(const QString& text, int from) const {
    int end = from + 1;
    if (text[from].isLetter() && end < text.size() && (text[end].isDigit() || text[end] == '.')) {
        // An address letter with its number (G01, N0053:0001, X12.5).
        while (end < text.size() && (text[end].isDigit() || text[end] == '.' || text[end] == ':'))
            ++end;
        return end;
    }
    while (end < text.size() && isWordChar(text[end]))
        ++end;
    return end;
}

void NcHighlighter::highlightWord(const QString& text, int start, int end) {
    const QChar letter = text[start].toUpper();
    const int length = end - start;
    const bool numbered = length > 1 && (text[start + 1].isDigit() || text[start + 1] == '.');
    if (numbered) {
        const bool atBlockStart =
            text.left(start).remove(QChar(0x2192)).remove('/').trimmed().isEmpty();
        if (letter == 'N' && atBlockStart)
            QSyntaxHighlighter::setFormat(start, length, format(Token::BlockNumber));
        else if (letter == 'G')
            QSyntaxHighlighter::setFormat(start, length, format(Token::GWord));
        else if (letter == 'M')
            QSyntaxHighlighter::setFormat(start, length, format(Token::MWord));
        return;
    }
    if (length < 2) return;
    const std::string name = text.mid(start, length).toUpper().toStdString();
    const auto info = mtc::core::lookupKeyword(name);
    using mtc::core::KeywordClass;
    if (info.keywordClass == KeywordClass::CompilerCommand ||
        info.keywordClass == KeywordClass::CompilerRestOfBlock ||
        info.keywordClass == KeywordClass::AxisFeed)
        QSyntaxHighlighter::setFormat(start, length, format(Token::CompilerKeyword));
    else if (info.keywordClass != KeywordClass::None)
        QSyntaxHighlighter::setFormat(start, length, format(Token::Keyword));
}

}  // namespace mtc::screens
