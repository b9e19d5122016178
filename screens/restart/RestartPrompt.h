#pragma once

#include <QFrame>

class QLabel;
class QLineEdit;

namespace mtc::screens {

/// The small input window of the restart screen, shown inline under the
/// listing and operated by keyboard: search string, number of runs, the
/// variable window and the event window of <Plane+> (seed 000, 2.5/2.6).
/// It only shows and edits text; the screen decides what Enter and Esc do.
class RestartPrompt : public QFrame {
    Q_OBJECT
  public:
    enum class Kind { None, Search, Runs, Variable, Event };

    /// A hidden prompt; open() shows it.
    explicit RestartPrompt(QWidget* parent = nullptr);

    /// Opens the window: `title` above the field, `text` in it (selected),
    /// `hint` below; read-only for the event window. Takes the focus.
    void open(Kind kind, const QString& title, const QString& text, const QString& hint,
              bool readOnly = false);
    /// Hides the window.
    void close();
    Kind kind() const { return kind_; }
    /// The text in the field.
    QString text() const;
    /// Replaces the text in the field (the event window's state).
    void setText(const QString& text);
    /// The input field (the screen filters its keys).
    QLineEdit* field() const { return field_; }

  private:
    Kind kind_ = Kind::None;
    QLabel* title_;
    QLineEdit* field_;
    QLabel* hint_;
};

}  // namespace mtc::screens
