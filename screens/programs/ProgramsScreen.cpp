#include "screens/programs/ProgramsScreen.h"

#include <QFontDatabase>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QListView>
#include <QPlainTextEdit>
#include <QVBoxLayout>

#include "hmi/CellSession.h"
#include "hmi/ProgramWorkspace.h"
#include "screens/editor/NcCodeEdit.h"
#include "screens/programs/ProgramDirectoryModel.h"

namespace mtc::screens {

ProgramsScreen::ProgramsScreen(const mtc::hmi::ScreenContext& context,
                               std::shared_ptr<mtc::hmi::ProgramWorkspace> workspace)
    : Screen(context), workspace_(std::move(workspace)) {
    model_ = new ProgramDirectoryModel(context.session, context.process, workspace_.get(), this);
    list_ = new QListView(this);
    list_->setObjectName("programList");
    list_->setModel(model_);
    list_->installEventFilter(this);
    // The listing loads long programs in chunks (1,000,000 blocks stay fluent).
    listing_ = new NcCodeEdit(this);
    listing_->setObjectName("programListing");
    listing_->setReadOnly(true);
    listing_->setFocusPolicy(Qt::NoFocus);
    listing_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    listing_->setLineWrapMode(QPlainTextEdit::NoWrap);
    listing_->setWindowing(true);  // ED-009: a large program shows at once
    message_ = new QLabel(this);
    message_->setObjectName("programsMessage");
    auto* columns = new QHBoxLayout;
    columns->addWidget(list_, 2);
    columns->addWidget(listing_, 3);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(columns, 1);
    layout->addWidget(message_);
    setFocusProxy(list_);
    connect(list_->selectionModel(), &QItemSelectionModel::currentChanged, this,
            [this] { showListing(); });
    connect(context.session, &mtc::hmi::CellSession::processChanged, this, [this](int slot) {
        if (slot == this->context().process) list_->viewport()->update();
    });
    connect(workspace_.get(), &mtc::hmi::ProgramWorkspace::programChanged, this,
            [this] { list_->viewport()->update(); });
}

void ProgramsScreen::activated() {
    const int keep = model_->programAt(list_->currentIndex().row());
    model_->reload();
    int row = model_->rowOf(keep);
    if (row < 0)
        row = model_->rowOf(context().session->control(context().process).selectedProgram());
    if (row < 0 && model_->rowCount() > 0) row = 0;
    if (row >= 0) list_->setCurrentIndex(model_->index(row));
    showListing();
}

void ProgramsScreen::showListing() {
    const int number = model_->programAt(list_->currentIndex().row());
    const auto program = context().session->program(context().process, number);
    if (program == shownProgram_ && program) return;
    shownProgram_ = program;
    listing_->load(program ? program->source.str() : std::string());
}

int ProgramsScreen::currentNumber() const {
    return model_->programAt(list_->currentIndex().row());
}

void ProgramsScreen::selectCurrent() {
    const int number = currentNumber();
    if (number != 0) context().session->selectProgram(context().process, number);
}

void ProgramsScreen::editCurrent() {
    const int number = currentNumber();
    if (number == 0) return;
    workspace_->requestEdit(number, 0);
    emit navigateTo("editor");
}

void ProgramsScreen::compileCurrent() {
    const int number = currentNumber();
    if (number == 0) return;
    QString error;
    if (!workspace_->compile(number, error)) {
        message_->setText(error);
        return;
    }
    if (workspace_->compiling(number)) {  // D-019: the status follows when done
        message_->setText(tr("Program %1: the user compilers run; the status follows").arg(number));
        return;
    }
    const auto result = workspace_->lastResult(number);
    message_->setText(tr("Program %1 compiled: status %2, %3 messages")
                          .arg(number)
                          .arg(QChar(mtc::core::statusLetter(workspace_->status(number))))
                          .arg(result ? int(result->errors.size()) : 0));
}

void ProgramsScreen::toggleCompiler() {
    QString error;
    if (!workspace_->setCompilerActive(!workspace_->compilerActive(), error))
        message_->setText(error);
    else
        message_->setText(tr("NC options: Compiler active = %1")
                              .arg(workspace_->compilerActive() ? tr("Yes") : tr("No")));
    emit softKeysChanged();
}

bool ProgramsScreen::eventFilter(QObject* watched, QEvent* event) {
    if (watched == list_ && event->type() == QEvent::KeyPress) {
        const int key = static_cast<QKeyEvent*>(event)->key();
        if (key == Qt::Key_Return || key == Qt::Key_Enter) {
            selectCurrent();
            return true;
        }
    }
    return Screen::eventFilter(watched, event);
}

mtc::hmi::SoftKeys ProgramsScreen::softKeys() {
    mtc::hmi::SoftKeys keys(8);
    keys[0] = {tr("Select\nprogram"), [this] { selectCurrent(); }};
    keys[1] = {tr("Edit"), [this] { editCurrent(); }};
    // Seed 001 ch. 7: <Compile> only while "Compiler active" is Yes.
    keys[2] = {tr("Compile"), [this] { compileCurrent(); }, workspace_->compilerActive()};
    keys[3] = {tr("Runtime\nprogram"), [this] {
                   workspace_->requestEdit(currentNumber(), 0);
                   emit navigateTo("runtime");
               }};
    keys[4] = {tr("NC\noptions"), [this] { emit navigateTo("nc-options"); }};
    keys[5] = {
        workspace_->compilerActive() ? tr("Compiler\nactive: Yes") : tr("Compiler\nactive: No"),
        [this] { toggleCompiler(); }};
    keys[6] = {tr("Error\ndisplay"), [this] { emit navigateTo("errors"); }};
    keys[7] = {tr("Back"), [this] { emit navigateTo("menu"); }};
    return keys;
}

}  // namespace mtc::screens
