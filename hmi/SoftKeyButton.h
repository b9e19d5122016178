#pragma once

#include <QPushButton>

namespace mtc::hmi {

/// One soft key button: the key name ("F4") on the first line and the label
/// below it, broken into lines at blanks so that it fits the button's width
/// (issue 20 §3: no label may be clipped, at any size or dpi); a word too
/// wide for the button breaks at its soft hyphens (U+00AD, e.g. the German
/// "Programm\u00ADverzeichnis" as "Programm-" / "verzeichnis"). A label that
/// cannot fit even so (a word wider than the button, more lines than the
/// button has room for) is shortened with "…" and the full text becomes the
/// tooltip.
class SoftKeyButton : public QPushButton {
    Q_OBJECT
  public:
    explicit SoftKeyButton(const QString& keyName, QWidget* parent = nullptr);

    /// The label as the screen gave it ('\n' forces a line break).
    void setLabel(const QString& label);
    const QString& label() const { return label_; }
    /// True when the label had to be shortened to fit (the tooltip has it all).
    bool shortened() const { return shortened_; }

    /// The lines of `label` that fit `width` pixels with `metrics`, at most
    /// `maxLines`; `shortened` tells whether anything was cut.
    static QStringList fitLines(const QString& label, const QFontMetrics& metrics, int width,
                                int maxLines, bool& shortened);

  protected:
    void resizeEvent(QResizeEvent* event) override;
    void changeEvent(QEvent* event) override;

  private:
    void relayout();

    QString keyName_;
    QString label_;
    bool shortened_ = false;
};

}  // namespace mtc::hmi
