#include "screens/programs/ProgramsScreen.h"

#include <QFontDatabase>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QListView>
#include <QPlainTextEdit>

#include "hmi/CellSession.h"
#include "screens/programs/ProgramDirectoryModel.h"

namespace mtc::screens {

ProgramsScreen::ProgramsScreen(const mtc::hmi::ScreenContext& context) : Screen(context) {
    model_ = new ProgramDirectoryModel(context.session, context.process, this);
    list_ = new QListView(this);
    list_->setObjectName("programList");
    list_->setModel(model_);
    list_->installEventFilter(this);
    listing_ = new QPlainTextEdit(this);
    listing_->setObjectName("programListing");
    listing_->setReadOnly(true);
    listing_->setFocusPolicy(Qt::NoFocus);
    listing_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    listing_->setLineWrapMode(QPlainTextEdit::NoWrap);
    auto* layout = new QHBoxLayout(this);
    layout->addWidget(list_, 1);
    layout->addWidget(listing_, 3);
    setFocusProxy(list_);
    connect(list_->selectionModel(), &QItemSelectionModel::currentChanged, this,
            [this] { showListing(); });
    connect(context.session, &mtc::hmi::CellSession::processChanged, this, [this](int slot) {
        if (slot == this->context().process) list_->viewport()->update();
    });
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
    listing_->setPlainText(program ? QString::fromStdString(program->source) : QString());
}

void ProgramsScreen::selectCurrent() {
    const int number = model_->programAt(list_->currentIndex().row());
    if (number != 0) context().session->selectProgram(context().process, number);
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
    keys[0] = {"Select\nprogram", [this] { selectCurrent(); }};
    keys[7] = {"Back", [this] { emit navigateTo("menu"); }};
    return keys;
}

}  // namespace mtc::screens
