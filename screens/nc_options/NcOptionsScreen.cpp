#include "screens/nc_options/NcOptionsScreen.h"

#include <QFontDatabase>
#include <QItemSelectionModel>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QListView>
#include <QVBoxLayout>
#include <algorithm>

#include "cnc_core/compiler/GlobalMacroFile.h"
#include "cnc_core/compiler/NcOptions.h"
#include "hmi/CellSession.h"
#include "hmi/NcOptionsHolder.h"
#include "hmi/PromptedInput.h"
#include "screens/nc_options/NcOptionsModel.h"

namespace mtc::screens {

using RowKind = NcOptionsModel::RowKind;

NcOptionsScreen::NcOptionsScreen(const mtc::hmi::ScreenContext& context)
    : Screen(context), holder_(&context.session->ncOptions()) {
    model_ = new NcOptionsModel(holder_, this);
    header_ = new QLabel(this);
    header_->setObjectName("ncoHeader");
    header_->setWordWrap(true);
    list_ = new QListView(this);
    list_->setObjectName("ncoList");
    list_->setModel(model_);
    list_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    list_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    list_->installEventFilter(this);
    inputLine_ = new mtc::hmi::PromptedInput("ncoPrompt", "ncoEditor", this);
    inputLine_->field()->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    inputLine_->setReturnFocus(list_);
    connect(inputLine_, &mtc::hmi::PromptedInput::confirmed, this, &NcOptionsScreen::confirmInput);
    connect(inputLine_, &mtc::hmi::PromptedInput::cancelled, this, &NcOptionsScreen::cancelInput);
    message_ = new QLabel(this);
    message_->setObjectName("ncoMessage");
    message_->setWordWrap(true);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(header_);
    layout->addWidget(list_, 1);
    layout->addWidget(inputLine_);
    layout->addWidget(message_);
    setFocusProxy(list_);
    closeInput();
    moveTo(0);
    // A change of the options (here or on the other station) rebuilds the
    // rows: the cursor stays on its row.
    connect(model_, &QAbstractItemModel::modelAboutToBeReset, this,
            [this] { keptRow_ = std::max(0, currentRow()); });
    connect(model_, &QAbstractItemModel::modelReset, this, [this] { moveTo(keptRow_); });
    connect(list_->selectionModel(), &QItemSelectionModel::currentChanged, this,
            [this] { emit softKeysChanged(); });
}

void NcOptionsScreen::activated() {
    const QString where =
        holder_->persistent()
            ? tr("kept in %1 (%2, %3)")
                  .arg(context().session->programDirectory(), mtc::core::kNcOptionsFileName,
                       mtc::core::kGlobalMacroFileName)
            : tr("built-in programs: kept in memory until the panel ends");
    header_->setText(
        tr("NC options of the cell, valid for every station and program — %1").arg(where));
    if (currentRow() < 0) moveTo(0);
    emit softKeysChanged();
}

void NcOptionsScreen::hideEvent(QHideEvent* event) {
    closeInput();
    Screen::hideEvent(event);
}

int NcOptionsScreen::currentRow() const {
    return list_->currentIndex().row();
}

void NcOptionsScreen::moveTo(int row) {
    row = std::max(0, std::min(row, model_->rowCount() - 1));
    list_->setCurrentIndex(model_->index(row));
}

mtc::hmi::SoftKeys NcOptionsScreen::softKeys() {
    mtc::hmi::SoftKeys keys(8);
    const bool onMacro = model_->rowAt(currentRow()).kind == RowKind::Macro;
    keys[0] = {tr("Change"), [this] { changeCurrent(); }};
    keys[1] = {tr("Add\nmacro"), [this] { startNewMacro(); }};
    keys[2] = {tr("Delete\nmacro"), [this] { deleteCurrentMacro(); }, onMacro};
    keys[3] = {holder_->compilerActive() ? tr("Compiler\nactive: Yes") : tr("Compiler\nactive: No"),
               [this] { toggleCompiler(); }};
    keys[7] = {tr("Back"), [this] { emit navigateTo("programs"); }};
    return keys;
}

void NcOptionsScreen::changeCurrent() {
    if (input_ != Input::None) return;
    const NcOptionsModel::Row row = model_->rowAt(currentRow());
    switch (row.kind) {
        case RowKind::CompilerActive:
            toggleCompiler();
            break;
        case RowKind::UserCompiler:
            openInput(Input::UserCompiler, row.index,
                      tr("Command of user compiler %1 (empty = none; called as COMMAND "
                         "INPUT OUTPUT ERRORS):")
                          .arg(row.index),
                      QString::fromStdString(
                          mtc::core::userCompilerCommand(holder_->userCompilers(), row.index)));
            break;
        case RowKind::Indramat:
            say(tr("The INDRAMAT compiler is switched with \"Compiler active\"."));
            break;
        case RowKind::SyntaxCheck:
            say(tr("The syntax check is done by the controller at download; it has no setting."));
            break;
        case RowKind::Macro:
            openInput(Input::ChangeMacro, row.index, tr("Change the global macro:"),
                      model_->macroEntry(row.index));
            break;
        case RowKind::NewMacro:
            startNewMacro();
            break;
    }
}

void NcOptionsScreen::toggleCompiler() {
    if (input_ != Input::None) return;
    QString error;
    if (!holder_->setCompilerActive(!holder_->compilerActive(), error)) {
        say(error);
        return;
    }
    say(tr("Compiler active = %1: the compile files of both stations are cleared")
            .arg(holder_->compilerActive() ? tr("Yes") : tr("No")));
    emit softKeysChanged();
}

void NcOptionsScreen::startNewMacro() {
    if (input_ != Input::None) return;
    moveTo(model_->rowCount() - 1);
    openInput(Input::NewMacro, 0,
              tr("New global macro (DEFINE name AS instructions; name <= 20 characters, "
                 "instructions <= 156):"),
              "DEFINE ");
    inputLine_->field()->deselect();
    inputLine_->field()->end(false);
}

void NcOptionsScreen::deleteCurrentMacro() {
    const NcOptionsModel::Row row = model_->rowAt(currentRow());
    if (input_ != Input::None || row.kind != RowKind::Macro) return;
    const QString entry = model_->macroEntry(row.index);
    QString error;
    if (!holder_->removeGlobalMacro(row.index, error)) {
        say(error);
        return;
    }
    moveTo(model_->rowOfMacro(row.index));
    say(tr("Deleted: %1\nPrograms that used the global macros are set to N again.").arg(entry));
}

void NcOptionsScreen::openInput(Input input, int index, const QString& prompt,
                                const QString& text) {
    input_ = input;
    inputIndex_ = index;
    inputLine_->open(prompt, text);
}

void NcOptionsScreen::closeInput() {
    input_ = Input::None;
    inputLine_->close();
}

void NcOptionsScreen::cancelInput() {
    closeInput();
    say(tr("Input cancelled: the NC options are unchanged"));
}

void NcOptionsScreen::confirmInput(const QString& text) {
    QString error;
    bool taken = false;
    switch (input_) {
        case Input::UserCompiler:
            taken = holder_->setUserCompiler(inputIndex_, text, error);
            break;
        case Input::NewMacro:
            taken = holder_->addGlobalMacro(text, error);
            break;
        case Input::ChangeMacro:
            taken = holder_->changeGlobalMacro(inputIndex_, text, error);
            break;
        case Input::None:
            return;
    }
    if (!taken) {
        say(error);  // the input stays open with the typed text
        return;
    }
    const Input done = input_;
    const int index = inputIndex_;
    closeInput();
    if (done == Input::UserCompiler) {
        moveTo(index == 1 || index == 2 ? index : index + 1);
        say(tr("User compiler %1 set: the compile files of both stations are cleared").arg(index));
        return;
    }
    const int macro =
        done == Input::NewMacro ? static_cast<int>(holder_->globalMacros().size()) - 1 : index;
    moveTo(model_->rowOfMacro(macro));
    say(tr("Taken: %1\nPrograms that use the global macros are set to N again.")
            .arg(model_->macroEntry(macro)));
}

bool NcOptionsScreen::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() != QEvent::KeyPress) return Screen::eventFilter(watched, event);
    const int key = static_cast<QKeyEvent*>(event)->key();
    if (watched == list_) {
        if (key == Qt::Key_Return || key == Qt::Key_Enter) {
            changeCurrent();
            return true;
        }
        if (key == Qt::Key_Delete) {
            deleteCurrentMacro();
            return true;
        }
        if (key == Qt::Key_Up || key == Qt::Key_Down) {
            moveTo(currentRow() + (key == Qt::Key_Up ? -1 : 1));
            return true;
        }
    }
    return Screen::eventFilter(watched, event);
}

void NcOptionsScreen::say(const QString& message) {
    message_->setText(message);
}

}  // namespace mtc::screens
