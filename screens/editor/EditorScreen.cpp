#include "screens/editor/EditorScreen.h"

#include <QElapsedTimer>
#include <QKeyEvent>
#include <QLabel>
#include <QVBoxLayout>

#include "hmi/CellSession.h"
#include "hmi/ProgramWorkspace.h"
#include "screens/editor/NcCodeEdit.h"

namespace mtc::screens {

namespace {
const QString kGneScreen = "gne";
}

EditorScreen::EditorScreen(const mtc::hmi::ScreenContext& context,
                           std::shared_ptr<mtc::hmi::ProgramWorkspace> workspace)
    : Screen(context), workspace_(std::move(workspace)) {
    heading_ = new QLabel(this);
    heading_->setObjectName("editorHeading");
    edit_ = new NcCodeEdit(this);
    edit_->setObjectName("programEditor");
    edit_->setWindowing(true);  // ED-009: a window of a large program in the view
    edit_->installEventFilter(this);
    status_ = new QLabel(this);
    status_->setObjectName("editorStatus");
    message_ = new QLabel(this);
    message_->setObjectName("editorMessage");
    message_->setWordWrap(true);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(heading_);
    layout->addWidget(edit_, 1);
    layout->addWidget(status_);
    layout->addWidget(message_);
    setFocusProxy(edit_);
    // The cursor line only: the status letter is read from the workspace when
    // it changes (programChanged), not on every key of a million-block text.
    connect(edit_, &QPlainTextEdit::cursorPositionChanged, this, [this] { updateCursorLine(); });
    connect(edit_, &QPlainTextEdit::cursorPositionChanged, this,
            [this] { emit cursorLineChanged(program_, edit_->cursorLine()); });
    connect(edit_, &NcCodeEdit::modifiedChanged, this, [this] {
        updateStatus();
        emit softKeysChanged();
    });
    connect(workspace_.get(), &mtc::hmi::ProgramWorkspace::programChanged, this, [this] {
        updateStatus();
        emit softKeysChanged();
    });
}

QString EditorScreen::title() const {
    return QCoreApplication::translate("ScreenTitle", "Program editor");
}

void EditorScreen::activated() {
    int wanted = workspace_->editProgram();
    if (wanted == 0) wanted = context().session->control(context().process).selectedProgram();
    const auto program = context().session->program(context().process, wanted);
    const bool other = wanted != program_ || (program && program != loadedSource_);
    if (program && other) {
        if (edit_->isModified() && wanted != program_) {
            showMessage(
                tr("Program %1 has unsaved changes: Save (F1) or Discard (F7) first").arg(program_),
                true);
        } else if (!edit_->isModified()) {
            open(wanted);
        }
    }
    if (program_ == wanted && workspace_->editLine() > 0) {
        edit_->goToLine(workspace_->editLine());
        workspace_->takeEditLine();
    }
    updateStatus();
    emit softKeysChanged();
}

void EditorScreen::open(int number) {
    const auto program = context().session->program(context().process, number);
    if (!program) return;
    QElapsedTimer timer;
    timer.start();
    edit_->load(program->source.str());
    lastOpenMs_ = timer.elapsed();
    program_ = number;
    loadedSource_ = program;
    emit cursorLineChanged(program_, edit_->cursorLine());
    workspace_->requestEdit(number, workspace_->editLine());
    updateStatus();
    // How long the load took is for the benchmark (lastOpenMs), not the operator.
    showMessage(tr("%1 lines opened").arg(edit_->lineCount()));
}

bool EditorScreen::save() {
    if (program_ == 0 || edit_->loading()) return false;
    QString error;
    if (!workspace_->save(program_, edit_->wholeText(), error)) {
        showMessage(error, true);
        return false;
    }
    loadedSource_ = context().session->program(context().process, program_);
    edit_->setModified(false);
    const QString file = workspace_->filePath(program_, "DAT");
    showMessage(file.isEmpty() ? tr("Saved (program memory; built-in program without file)")
                               : tr("Saved to %1").arg(file));
    return true;
}

void EditorScreen::compile() {
    if (program_ == 0 || edit_->loading()) return;
    if (edit_->isModified() && !save()) return;
    QString error;
    if (!workspace_->compile(program_, error)) {
        showMessage(error, true);
        return;
    }
    if (workspace_->compiling(program_)) {  // D-019: the status follows when done
        showMessage(tr("The user compilers run; the status follows in the program directory"));
        return;
    }
    const auto result = workspace_->lastResult(program_);
    if (result && result->status == mtc::core::CompileStatus::Compiled)
        showMessage(tr("Compiled: %1 object blocks, %2 warnings (Ctrl+E)")
                        .arg(result->objectBlocks)
                        .arg(result->errors.size()));
    else if (result)
        showMessage(tr("Compile error: %1 messages (Ctrl+E shows them)").arg(result->errors.size()),
                    true);
}

void EditorScreen::showErrors() {
    workspace_->requestEdit(program_, 0);
    emit navigateTo("errors");
}

bool EditorScreen::gneAvailable() const {
    if (!context().stationScreens) return false;
    for (const Screen* screen : context().stationScreens())
        if (screen->screenName() == kGneScreen) return true;
    return false;
}

void EditorScreen::openGne() {
    if (!gneAvailable()) {
        showMessage(tr("The graphical NC editor (GNE) is not part of this panel yet"), true);
        return;
    }
    // The GNE works on the saved program: unsaved changes are saved first.
    if (program_ != 0 && edit_->isModified() && !save()) return;
    workspace_->requestEdit(program_, edit_->cursorLine());
    emit navigateTo(kGneScreen);
}

void EditorScreen::reload() {
    if (program_ == 0) return;
    edit_->setModified(false);
    open(program_);
    showMessage(tr("Changes discarded, program reloaded"));
}

void EditorScreen::showMessage(const QString& text, bool error) {
    message_->setText(text);
    message_->setStyleSheet(error ? "color: #a00000;" : "");
}

void EditorScreen::updateStatus() {
    const auto program = context().session->program(context().process, program_);
    const QString name = program ? QString::fromStdString(program->name) : tr("(none)");
    const char status = mtc::core::statusLetter(workspace_->status(program_));
    heading_->setText(tr("Program %1  %2  status [%3]%4")
                          .arg(program_, 3, 10, QChar('0'))
                          .arg(name)
                          .arg(QChar(status))
                          .arg(edit_->isModified() ? "  " + tr("*modified*") : QString()));
    updateCursorLine();
}

void EditorScreen::updateCursorLine() {
    const QString block = edit_->cursorBlockId();
    status_->setText(tr("Line %1 of %2   Block %3")
                         .arg(edit_->cursorLine())
                         .arg(edit_->lineCount())
                         .arg(block.isEmpty() ? "-" : block));
}

bool EditorScreen::eventFilter(QObject* watched, QEvent* event) {
    if (watched == edit_ && event->type() == QEvent::KeyPress) {
        const auto* key = static_cast<QKeyEvent*>(event);
        if (key->key() == Qt::Key_E && (key->modifiers() & Qt::ControlModifier)) {
            showErrors();
            return true;
        }
        if (key->key() == Qt::Key_S && (key->modifiers() & Qt::ControlModifier)) {
            save();
            return true;
        }
        if (key->key() == Qt::Key_W && (key->modifiers() & Qt::ControlModifier)) {
            openGne();  // seed 001 ch. 3: <Control W> calls the GNE from the full screen editor
            return true;
        }
    }
    return Screen::eventFilter(watched, event);
}

mtc::hmi::SoftKeys EditorScreen::softKeys() {
    mtc::hmi::SoftKeys keys(8);
    const bool open = program_ != 0 && !edit_->loading();
    keys[0] = {tr("Save"), [this] { save(); }, open};
    keys[1] = {tr("Compile"), [this] { compile(); }, open && workspace_->compilerActive()};
    keys[2] = {tr("Errors\nCtrl+E"), [this] { showErrors(); }};
    keys[3] = {gneAvailable() ? tr("GNE\nCtrl+W") : tr("GNE\n(n/a)"), [this] { openGne(); }};
    keys[4] = {tr("Runtime\nprogram"), [this] {
                   workspace_->requestEdit(program_, 0);
                   emit navigateTo("runtime");
               }};
    keys[6] = {tr("Discard\nchanges"), [this] { reload(); }, open && edit_->isModified()};
    keys[7] = {tr("Back"), [this] { emit navigateTo("programs"); }};
    return keys;
}

}  // namespace mtc::screens
