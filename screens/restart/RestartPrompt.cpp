#include "screens/restart/RestartPrompt.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>

namespace mtc::screens {

RestartPrompt::RestartPrompt(QWidget* parent) : QFrame(parent) {
    setObjectName("restartPrompt");
    setFrameShape(QFrame::StyledPanel);
    setStyleSheet("QFrame#restartPrompt { background: #fff6c8; border: 1px solid #9a8a40; }");
    title_ = new QLabel(this);
    title_->setObjectName("restartPromptTitle");
    field_ = new QLineEdit(this);
    field_->setObjectName("restartPromptField");
    field_->setMinimumWidth(200);
    hint_ = new QLabel(this);
    hint_->setObjectName("restartPromptHint");
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(8, 4, 8, 4);
    layout->addWidget(title_);
    layout->addWidget(field_, 1);
    layout->addWidget(hint_);
    hide();
}

void RestartPrompt::open(Kind kind, const QString& title, const QString& text, const QString& hint,
                         bool readOnly) {
    kind_ = kind;
    title_->setText(title);
    field_->setReadOnly(readOnly);
    field_->setText(text);
    field_->selectAll();
    hint_->setText(hint);
    show();
    field_->setFocus();
}

void RestartPrompt::close() {
    kind_ = Kind::None;
    hide();
}

QString RestartPrompt::text() const {
    return field_->text();
}

void RestartPrompt::setText(const QString& text) {
    field_->setText(text);
}

}  // namespace mtc::screens
