#include "screens/errors/ErrorsScreen.h"

#include <QFontDatabase>
#include <QKeyEvent>
#include <QLabel>
#include <QListWidget>
#include <QVBoxLayout>

#include "hmi/CellSession.h"
#include "hmi/ProgramWorkspace.h"
#include "screens/restart/RestartController.h"

namespace mtc::screens {

using mtc::hmi::ErrorEntry;
using mtc::hmi::ErrorOrigin;

ErrorsScreen::ErrorsScreen(const mtc::hmi::ScreenContext& context,
                           std::shared_ptr<mtc::hmi::ProgramWorkspace> workspace,
                           std::shared_ptr<RestartController> restart)
    : Screen(context), workspace_(std::move(workspace)), restart_(std::move(restart)) {
    list_ = new QListWidget(this);
    list_->setObjectName("errorList");
    list_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    list_->installEventFilter(this);
    hint_ = new QLabel(this);
    hint_->setObjectName("errorHint");
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(list_, 1);
    layout->addWidget(hint_);
    setFocusProxy(list_);
    connect(&workspace_->errors(), &mtc::hmi::ErrorLog::changed, this, [this] {
        expanded_.clear();
        rebuild();
    });
    connect(list_, &QListWidget::itemActivated, this, [this] { jumpToSource(); });
    if (restart_)
        connect(restart_.get(), &RestartController::changed, this,
                [this] { collectRestartMessage(); });
    rebuild();
}

void ErrorsScreen::collectRestartMessage() {
    const RestartMessage& message = restart_->message();
    if (message.level != RestartMessage::Level::Error || message.text.isEmpty()) return;
    QVector<ErrorEntry> entries;
    for (const mtc::core::Diagnostic& d : message.diagnostics)
        if (d.severity == mtc::core::Severity::Error)
            entries.push_back(mtc::hmi::entryFromDiagnostic(d, ErrorOrigin::Restart));
    if (entries.isEmpty()) {  // the screen's own refusal: a plain text, no place
        ErrorEntry entry;
        entry.origin = ErrorOrigin::Restart;
        entry.message = message.text;
        entries.push_back(entry);
    }
    const int selected = context().session->control(context().process).selectedProgram();
    for (ErrorEntry& entry : entries) {
        if (entry.code.isEmpty()) entry.code = "RESTART";
        if (entry.program == 0) entry.program = selected;
    }
    workspace_->errors().addAll(entries);
}

void ErrorsScreen::activated() {
    rebuild();
    // Start on the first message of the program the editor shows.
    const int program = workspace_->editProgram();
    const auto& entries = workspace_->errors().entries();
    for (int i = 0; i < entries.size(); ++i)
        if (entries[i].program == program) {
            list_->setCurrentRow(i);
            return;
        }
    if (list_->count() > 0 && list_->currentRow() < 0) list_->setCurrentRow(0);
}

QString ErrorsScreen::itemText(const ErrorEntry& entry, bool expanded) const {
    QString text = QString("%1 %2  P%3 %4  %5")
                       .arg(entry.warning ? tr("W", "warning") : tr("E", "error"))
                       .arg(mtc::hmi::originName(entry.origin), -8)
                       .arg(entry.program, 3, 10, QChar('0'))
                       .arg(entry.block.isEmpty() ? QString("-") : entry.block, -10)
                       .arg(entry.message);
    if (expanded) {
        if (entry.line > 0)
            text += "\n      " + (entry.origin == ErrorOrigin::Mdi
                                      ? tr("MDI input line %1").arg(entry.line)
                                      : tr("source line %1").arg(entry.line));
        if (!entry.code.isEmpty()) text += "\n      [" + entry.code + "]";
        for (const QString& line : entry.details)
            text += "\n      " + line;
    }
    return text;
}

void ErrorsScreen::rebuild() {
    const int row = list_->currentRow();
    list_->clear();
    const auto& entries = workspace_->errors().entries();
    for (int i = 0; i < entries.size(); ++i)
        list_->addItem(itemText(entries[i], expanded_.contains(i)));
    if (entries.isEmpty()) {
        hint_->setText(tr("No errors."));
    } else {
        hint_->setText(
            tr("%n message(s). Enter: go to the block in the editor; F2: additional "
               "text",
               nullptr, entries.size()));
        list_->setCurrentRow(qBound(0, row, entries.size() - 1));
    }
}

void ErrorsScreen::toggleDetails() {
    const int row = list_->currentRow();
    if (row < 0) return;
    if (expanded_.contains(row))
        expanded_.remove(row);
    else
        expanded_.insert(row);
    list_->item(row)->setText(
        itemText(workspace_->errors().entries().at(row), expanded_.contains(row)));
}

void ErrorsScreen::jumpToSource() {
    const int row = list_->currentRow();
    const auto& entries = workspace_->errors().entries();
    if (row < 0 || row >= entries.size()) return;
    const ErrorEntry& entry = entries[row];
    if (entry.program == 0 || !context().session->program(context().process, entry.program)) {
        hint_->setText(tr("This message belongs to no program of this station."));
        return;
    }
    int line = entry.line;
    if (line <= 0) line = workspace_->sourceLineOf(entry.program, entry.block);
    workspace_->requestEdit(entry.program, qMax(1, line));
    emit navigateTo("editor");
}

bool ErrorsScreen::eventFilter(QObject* watched, QEvent* event) {
    if (watched == list_ && event->type() == QEvent::KeyPress) {
        const int key = static_cast<QKeyEvent*>(event)->key();
        if (key == Qt::Key_Return || key == Qt::Key_Enter) {
            jumpToSource();
            return true;
        }
    }
    return Screen::eventFilter(watched, event);
}

mtc::hmi::SoftKeys ErrorsScreen::softKeys() {
    mtc::hmi::SoftKeys keys(8);
    keys[0] = {tr("Go to\nblock"), [this] { jumpToSource(); }};
    keys[1] = {tr("Additional\ntext"), [this] { toggleDetails(); }};
    keys[5] = {tr("Clear\nruntime"), [this] {
                   workspace_->errors().clear(ErrorOrigin::Runtime);
                   workspace_->errors().clear(ErrorOrigin::Restart);
                   workspace_->errors().clear(ErrorOrigin::Mdi);
               }};
    keys[7] = {tr("Back"),
               [this] { emit navigateTo(workspace_->editProgram() ? "editor" : "programs"); }};
    return keys;
}

}  // namespace mtc::screens
