#include "hmi/PromptedInput.h"

#include <QKeyEvent>
#include <QLabel>
#include <QVBoxLayout>

namespace mtc::hmi {

PromptedInput::PromptedInput(const QString& promptName, const QString& fieldName, QWidget* parent)
    : QWidget(parent) {
    prompt_ = new QLabel(this);
    prompt_->setObjectName(promptName);
    field_ = new QLineEdit(this);
    field_->setObjectName(fieldName);
    field_->installEventFilter(this);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(prompt_);
    layout->addWidget(field_);
    close();
}

void PromptedInput::open(const QString& prompt, const QString& text, QLineEdit::EchoMode echo) {
    prompt_->setText(prompt);
    field_->setEchoMode(echo);
    field_->setText(text);
    field_->selectAll();
    prompt_->show();
    field_->show();
    show();
    field_->setFocus();
}

void PromptedInput::close() {
    field_->clear();
    field_->hide();
    prompt_->hide();
    hide();
    if (returnFocus_ && returnFocus_->isVisible()) returnFocus_->setFocus();
}

QString PromptedInput::text() const {
    return field_->text();
}

bool PromptedInput::eventFilter(QObject* watched, QEvent* event) {
    if (watched != field_) return QWidget::eventFilter(watched, event);
    const bool shortcut = event->type() == QEvent::ShortcutOverride;
    if (!shortcut && event->type() != QEvent::KeyPress) return false;
    const int key = static_cast<QKeyEvent*>(event)->key();
    if (shortcut) {
        if (key != Qt::Key_Escape) return false;
        event->accept();  // Escape cancels the input instead of leaving the screen
        return true;
    }
    if (key == Qt::Key_Escape) {
        emit cancelled();
        return true;
    }
    if (key == Qt::Key_Return || key == Qt::Key_Enter) {
        emit confirmed(field_->text());
        return true;
    }
    return false;
}

}  // namespace mtc::hmi
