#pragma once

#include <QLineEdit>
#include <QWidget>

class QLabel;

namespace mtc::hmi {

/// The one-line input of a screen, shown under its list: a prompt label
/// above a QLineEdit. open() shows both, puts the text in the field
/// (selected) and takes the focus; Enter reports confirmed(), Escape
/// reports cancelled() (and does not leave the screen). It only shows and
/// edits text: the screen decides what a confirmed text means and when the
/// input closes. close() hides it and gives the focus back to the widget
/// set with setReturnFocus() while that one is visible.
class PromptedInput : public QWidget {
    Q_OBJECT
  public:
    /// A hidden input; `promptName` and `fieldName` are the objectNames of
    /// the prompt label and the line edit.
    PromptedInput(const QString& promptName, const QString& fieldName, QWidget* parent = nullptr);

    /// The widget that gets the focus back on close() (the screen's list).
    void setReturnFocus(QWidget* widget) { returnFocus_ = widget; }
    /// Shows `prompt` and the field with `text` selected, in `echo` mode;
    /// the field takes the focus.
    void open(const QString& prompt, const QString& text,
              QLineEdit::EchoMode echo = QLineEdit::Normal);
    /// Clears and hides the input; the return-focus widget takes the focus.
    void close();
    /// The text in the field, as typed.
    QString text() const;
    /// The line edit (for its font or cursor placement).
    QLineEdit* field() const { return field_; }

  signals:
    /// Enter in the field; `text` is the field's text as typed.
    void confirmed(const QString& text);
    /// Escape in the field.
    void cancelled();

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    QLabel* prompt_;
    QLineEdit* field_;
    QWidget* returnFocus_ = nullptr;
};

}  // namespace mtc::hmi
