#include "screens/tooldata/SetupTableScreen.h"

#include <QHeaderView>
#include <QKeyEvent>
#include <QLabel>
#include <QTableView>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>

#include "cnc_core/tooldata/SetupDataEditor.h"
#include "hmi/CellSession.h"
#include "hmi/PanelLanguage.h"
#include "hmi/PromptedInput.h"
#include "screens/tooldata/CursorTableModel.h"

namespace mtc::screens {

SetupTableScreen::SetupTableScreen(const mtc::hmi::ScreenContext& context, const char* prefix)
    : Screen(context) {
    const QString p(prefix);
    heading_ = new QLabel(this);
    heading_->setObjectName(p + "Heading");
    heading_->setWordWrap(true);
    table_ = new QTableView(this);
    table_->setObjectName(p + "Table");
    table_->verticalHeader()->hide();
    table_->setSelectionMode(QAbstractItemView::NoSelection);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setFocusPolicy(Qt::StrongFocus);
    table_->installEventFilter(this);
    input_ = new mtc::hmi::PromptedInput(p + "Prompt", p + "Editor", this);
    input_->setReturnFocus(table_);
    connect(input_, &mtc::hmi::PromptedInput::confirmed, this, [this](const QString& text) {
        input_->close();
        inputConfirmed(text.trimmed());
    });
    connect(input_, &mtc::hmi::PromptedInput::cancelled, this, [this] {
        input_->close();
        inputCancelled();
    });
    message_ = new QLabel(this);
    message_->setObjectName(p + "Message");
    message_->setWordWrap(true);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(heading_);
    layout->addWidget(table_, 1);
    layout->addWidget(input_);
    layout->addWidget(message_);
    setFocusProxy(table_);
    input_->close();
    // Another program saved the files: the table shows their values now.
    connect(context.session, &mtc::hmi::CellSession::setupDataNotice, this,
            [this](const QString& notice) {
                dataChangedElsewhere();
                say(notice);
            });
}

void SetupTableScreen::setModel(CursorTableModel* model, bool stretch) {
    model_ = model;
    table_->setModel(model);
    QHeaderView* header = table_->horizontalHeader();
    header->setSectionResizeMode(stretch ? QHeaderView::Stretch : QHeaderView::ResizeToContents);
    if (stretch) header->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    header->setStretchLastSection(false);
}

int SetupTableScreen::processNumber() const {
    return context().session->processConfig(context().process).index;
}

void SetupTableScreen::hideEvent(QHideEvent* event) {
    input_->close();
    Screen::hideEvent(event);
}

bool SetupTableScreen::eventFilter(QObject* watched, QEvent* event) {
    if (watched == table_ && event->type() == QEvent::KeyPress)
        return browseKey(static_cast<QKeyEvent*>(event)->key());
    return Screen::eventFilter(watched, event);
}

bool SetupTableScreen::browseKey(int key) {
    if (!model_) return false;
    const int pageRows = std::max(1, table_->viewport()->height() / 24);
    switch (key) {
        case Qt::Key_Up:
            model_->moveCursor(-1, 0);
            break;
        case Qt::Key_Down:
            model_->moveCursor(1, 0);
            break;
        case Qt::Key_Left:
            model_->moveCursor(0, -1);
            break;
        case Qt::Key_Right:
            model_->moveCursor(0, 1);
            break;
        case Qt::Key_PageUp:
            model_->moveCursor(-pageRows, 0);
            break;
        case Qt::Key_PageDown:
            model_->moveCursor(pageRows, 0);
            break;
        case Qt::Key_Home:
            model_->setCursor(model_->cursorRow(), 0);
            break;
        case Qt::Key_End:
            model_->setCursor(model_->cursorRow(), model_->columnCount() - 1);
            break;
        case Qt::Key_Return:
        case Qt::Key_Enter:
            startEdit();
            return true;
        default:
            return false;
    }
    showCursor();
    return true;
}

void SetupTableScreen::showCursor() {
    if (!model_ || model_->rowCount() == 0) return;
    // Before the first layout the viewport is a few pixels wide and would
    // scroll the table to its last columns: scroll once it has its size.
    QTimer::singleShot(0, this, [this] {
        if (model_->rowCount() > 0)
            table_->scrollTo(model_->index(model_->cursorRow(), model_->cursorColumn()));
    });
}

void SetupTableScreen::openInput(const QString& prompt, const QString& text) {
    input_->open(prompt, text);
}

void SetupTableScreen::closeInput() {
    input_->close();
}

bool SetupTableScreen::inputOpen() const {
    return !input_->isHidden();
}

void SetupTableScreen::say(const QString& message) {
    message_->setText(message);
}

void SetupTableScreen::setHeading(const QString& heading) {
    heading_->setText(heading);
}

QString SetupTableScreen::outcomeText(const mtc::core::SetupDataEdit& edit, const QString& done,
                                      const QString& refusedWhat) const {
    if (!edit.changed)
        return tr("Refused: %1")
                   .arg(QString::fromStdString(edit.reason(hmi::installedCoreLanguage()))) +
               "\n" + refusedWhat;
    QString text = done + " " + tr("(effective from the next block)");
    for (const mtc::core::Diagnostic& d : edit.diagnostics.items())
        text += "\n" + hmi::coreMessageLine(d);
    if (!edit.saved && !edit.diagnostics.hasErrors())
        text += "\n" + tr("Not kept in a file: the panel runs without a machine data file");
    return text;
}

}  // namespace mtc::screens
