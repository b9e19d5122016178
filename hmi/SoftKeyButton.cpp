#include "hmi/SoftKeyButton.h"

#include <algorithm>
#include <functional>

#include <QEvent>
#include <QFontMetrics>

namespace mtc::hmi {

namespace {
/// Lines the label may take below the key name.
constexpr int kLabelLines = 3;
/// Room the button's frame and padding take from its width, in pixels.
constexpr int kFrameWidth = 10;

/// Where a long (German) word may break: a soft hyphen in the label.
constexpr QChar kSoftHyphen(0x00AD);

/// `text` as shown when it is not broken: without its soft hyphens.
QString withoutSoftHyphens(QString text) {
    return text.remove(kSoftHyphen);
}

/// `word` shortened with "…" to `width` pixels.
QString elided(const QString& word, const QFontMetrics& metrics, int width) {
    return metrics.elidedText(withoutSoftHyphens(word), Qt::ElideRight, width);
}

/// `word` broken at its soft hyphens into pieces that fit (each broken
/// piece ends in '-'); a piece too wide even alone stays as it is.
QStringList breakAtSoftHyphens(const QString& word,
                               const std::function<bool(const QString&)>& fits) {
    const QStringList parts = word.split(kSoftHyphen);
    QStringList pieces;
    QString current;
    for (int i = 0; i < parts.size(); ++i) {
        const QString candidate = current + parts[i];
        const bool last = i + 1 == parts.size();
        // A piece ending in a hyphen of its own ("NC-") needs no second one.
        const auto broken = [](const QString& piece) {
            return piece.endsWith('-') ? piece : piece + '-';
        };
        if (current.isEmpty() || fits(last ? candidate : broken(candidate))) {
            current = candidate;
            continue;
        }
        pieces << broken(current);
        current = parts[i];
    }
    pieces << current;
    return pieces;
}
}  // namespace

SoftKeyButton::SoftKeyButton(const QString& keyName, QWidget* parent)
    : QPushButton(parent), keyName_(keyName) {
    relayout();
}

void SoftKeyButton::setLabel(const QString& label) {
    label_ = label;
    relayout();
}

QStringList SoftKeyButton::fitLines(const QString& label, const QFontMetrics& metrics, int width,
                                    int maxLines, bool& shortened) {
    shortened = false;
    QStringList lines;
    const auto fits = [&](const QString& text) { return metrics.horizontalAdvance(text) <= width; };
    // Greedy filling of each explicit line with its words.
    for (const QString& paragraph : label.split('\n')) {
        QString line;
        for (const QString& word : paragraph.split(' ', Qt::SkipEmptyParts)) {
            const QString plain = withoutSoftHyphens(word);
            const QString joined = line.isEmpty() ? plain : line + ' ' + plain;
            if (fits(joined)) {
                line = joined;
                continue;
            }
            if (!line.isEmpty()) lines << line;
            QStringList pieces = breakAtSoftHyphens(word, fits);
            for (QString& piece : pieces)
                if (!fits(piece)) {
                    piece = elided(piece, metrics, width);
                    shortened = true;
                }
            line = pieces.takeLast();
            lines << pieces;
        }
        lines << line;
    }
    if (lines.size() > maxLines) {
        shortened = true;
        QString last = lines.mid(maxLines - 1).join(' ');
        lines = lines.mid(0, maxLines - 1);
        lines << elided(last, metrics, width);
    }
    return lines;
}

void SoftKeyButton::relayout() {
    const QFontMetrics metrics(font());
    const int width = std::max(1, this->width() - kFrameWidth);
    bool shortened = false;
    const QStringList lines =
        label_.isEmpty() ? QStringList() : fitLines(label_, metrics, width, kLabelLines, shortened);
    shortened_ = shortened;
    setText(lines.isEmpty() ? keyName_ : keyName_ + '\n' + lines.join('\n'));
    setToolTip(shortened ? withoutSoftHyphens(label_).replace('\n', ' ') : QString());
    // Room for the key name and the label lines at any font size (dpi).
    setMinimumHeight(metrics.lineSpacing() * (1 + kLabelLines) + 8);
}

void SoftKeyButton::resizeEvent(QResizeEvent* event) {
    QPushButton::resizeEvent(event);
    relayout();
}

void SoftKeyButton::changeEvent(QEvent* event) {
    QPushButton::changeEvent(event);
    if (event->type() == QEvent::FontChange) relayout();
}

}  // namespace mtc::hmi
