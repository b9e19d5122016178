#include "screens/restart/RestartScreen.h"

#include <QFontDatabase>
#include <QFontInfo>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QListView>
#include <QVBoxLayout>

#include "cnc_core/language/Keywords.h"
#include "screens/restart/ProgramListingModel.h"
#include "screens/restart/RestartController.h"
#include "screens/restart/RestartPrompt.h"
#include "screens/restart/RestartRun.h"

namespace mtc::screens {

namespace {

QString eventText(bool set) {
    return set ? RestartScreen::tr("1  (set)") : RestartScreen::tr("0  (not set)");
}

/// A fixed-pitch font for the listing (the platform's, else fontconfig's "Monospace").
QFont listingFont() {
    QFont font = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    if (!QFontInfo(font).fixedPitch()) {
        font.setFamily("Monospace");
        font.setStyleHint(QFont::TypeWriter);
        font.setFixedPitch(true);
    }
    return font;
}

QString messageStyle(RestartMessage::Level level) {
    switch (level) {
        case RestartMessage::Level::Error:
            return "color: #b00000; font-weight: bold;";
        case RestartMessage::Level::Warning:
            return "color: #8a5a00;";
        default:
            return "color: #202020;";
    }
}

}  // namespace

RestartScreen::RestartScreen(const mtc::hmi::ScreenContext& context,
                             std::shared_ptr<RestartController> controller)
    : Screen(context), controller_(std::move(controller)) {
    breadcrumb_ = new QLabel(this);
    breadcrumb_->setObjectName("restartBreadcrumb");
    breadcrumb_->setStyleSheet("background: #dfe6ef; padding: 3px; font-weight: bold;");
    list_ = new QListView(this);
    list_->setObjectName("restartListing");
    list_->setUniformItemSizes(true);
    list_->setSelectionMode(QAbstractItemView::NoSelection);
    list_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    list_->setFont(listingFont());
    list_->setModel(controller_->listing());
    list_->installEventFilter(this);
    prompt_ = new RestartPrompt(this);
    prompt_->field()->installEventFilter(this);
    status_ = new QLabel(this);
    status_->setObjectName("restartStatus");
    status_->setStyleSheet("background: #f4f4f4; border: 1px solid #a0a0a0; padding: 3px;");
    message_ = new QLabel(this);
    message_->setObjectName("restartMessage");
    message_->setWordWrap(true);
    progress_ = new QLabel(this);
    progress_->setObjectName("restartProgress");
    progress_->setWordWrap(true);
    progress_->setStyleSheet("background: #00307a; color: white; padding: 4px;");
    progress_->hide();
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(breadcrumb_);
    layout->addWidget(list_, 1);
    layout->addWidget(prompt_);
    layout->addWidget(status_);
    layout->addWidget(message_);
    layout->addWidget(progress_);
    setFocusProxy(list_);
    connect(list_, &QListView::clicked, this,
            [this](const QModelIndex& index) { controller_->clickRow(index.row()); });
    connect(controller_->listing(), &ProgramListingModel::marksChanged, list_->viewport(),
            [this] { list_->viewport()->update(); });
    connect(controller_->run(), &RestartRun::phaseChanged, this,
            [this](mtc::core::RestartPhase phase) {
                emit softKeysChanged();
                // The computing process is done: the operator checks its result.
                if (phase == mtc::core::RestartPhase::TargetReached && isVisible())
                    emit navigateTo("restart-result");
            });
    connect(controller_.get(), &RestartController::changed, this, [this] {
        if (isVisible()) render();
    });
}

void RestartScreen::activated() {
    if (!entered_) {
        entered_ = true;
        closePrompt();
        controller_->enter();
    }
    render();
    emit softKeysChanged();
}

void RestartScreen::hideEvent(QHideEvent* event) {
    // Hidden by its own station page (another screen was chosen), not just
    // because the whole station was switched away.
    if (!isVisibleTo(parentWidget())) entered_ = false;
    Screen::hideEvent(event);
}

mtc::hmi::SoftKeys RestartScreen::softKeys() {
    mtc::hmi::SoftKeys keys(8);
    const bool primary = controller_->pointer().fromLastPrimary();
    keys[0] = {tr("Plane +"), [this] {
                   closePrompt();
                   controller_->planePlus();
                   openWindow();
               }};
    keys[1] = {tr("Plane −"), [this] {
                   closePrompt();
                   controller_->planeMinus();
               }};
    keys[2] = {tr("Search\nstring"), [this] { openSearch(); }};
    keys[3] = {primary ? tr("From last\nprimary ✓") : tr("From last\nprimary block"), [this] {
                   closePrompt();
                   controller_->toggleFromLastPrimary();
                   emit softKeysChanged();
               }};
    keys[4] = {tr("Number\nof runs"), [this] { openRuns(); }};
    keys[5] = {tr("Accept\ntarget"), [this] {
                   closePrompt();
                   controller_->accept();
               }};
    // F7: Abort while a restart runs; otherwise the restart verifier.
    if (controller_->run()->active())
        keys[6] = {tr("Abort"), [this] { controller_->abort(); }};
    else
        keys[6] = {tr("Verify\nprogram"),
                   [this] {
                       closePrompt();
                       controller_->verifyProgram();
                   },
                   controller_->active()};
    keys[7] = {tr("Back"), [this] { emit navigateTo("menu"); }};
    return keys;
}

// ------------------------------------------------------------------ keys

bool RestartScreen::eventFilter(QObject* watched, QEvent* event) {
    const bool onList = watched == list_;
    const bool onPrompt = watched == prompt_->field();
    const bool keyEvent =
        event->type() == QEvent::KeyPress || event->type() == QEvent::ShortcutOverride;
    if ((!onList && !onPrompt) || !keyEvent) return Screen::eventFilter(watched, event);
    auto* key = static_cast<QKeyEvent*>(event);
    if (onPrompt && event->type() == QEvent::ShortcutOverride && key->key() == Qt::Key_Escape) {
        event->accept();  // Esc closes the window instead of leaving the screen
        return true;
    }
    if (event->type() != QEvent::KeyPress) return Screen::eventFilter(watched, event);
    if (key->modifiers() & (Qt::ControlModifier | Qt::AltModifier)) return false;
    return onList ? listKey(key->key()) : promptKey(key->key());
}

bool RestartScreen::listKey(int key) {
    switch (key) {
        case Qt::Key_Up:
            controller_->up();
            return true;
        case Qt::Key_Down:
            controller_->down();
            return true;
        case Qt::Key_PageUp:
            controller_->pageUp(pageRows());
            return true;
        case Qt::Key_PageDown:
            controller_->pageDown(pageRows());
            return true;
        case Qt::Key_Home:
            controller_->home();
            return true;
        case Qt::Key_End:
            controller_->end();
            return true;
        case Qt::Key_Return:
        case Qt::Key_Enter:
            controller_->accept();
            return true;
        default:
            return false;
    }
}

bool RestartScreen::promptKey(int key) {
    const RestartPrompt::Kind kind = prompt_->kind();
    if (key == Qt::Key_Escape) {
        if (kind == RestartPrompt::Kind::Variable || kind == RestartPrompt::Kind::Event)
            controller_->cancelWindow();
        closePrompt();
        return true;
    }
    if (kind == RestartPrompt::Kind::Event && key == Qt::Key_Space) {
        eventSet_ = !eventSet_;
        prompt_->setText(eventText(eventSet_));
        return true;
    }
    if (key != Qt::Key_Return && key != Qt::Key_Enter) return false;
    bool done = true;
    switch (kind) {
        case RestartPrompt::Kind::Search:
            done = controller_->search(prompt_->text());
            break;
        case RestartPrompt::Kind::Runs:
            done = controller_->setRuns(prompt_->text());
            break;
        case RestartPrompt::Kind::Variable:
            done = controller_->confirmVariable(prompt_->text());
            break;
        case RestartPrompt::Kind::Event:
            controller_->confirmEvent(eventSet_);
            break;
        case RestartPrompt::Kind::None:
            break;
    }
    if (done) closePrompt();
    if (done) openWindow();  // JEV @n: the variable window follows the event window
    return true;
}

// ------------------------------------------------------------------ prompts

void RestartScreen::openSearch() {
    if (!controller_->active()) return;
    controller_->cancelWindow();
    prompt_->open(RestartPrompt::Kind::Search, tr("Search string:"), controller_->lastSearch(),
                  tr("Enter: next occurrence towards the end · Esc: close"));
}

void RestartScreen::openRuns() {
    if (!controller_->active()) return;
    controller_->cancelWindow();
    prompt_->open(RestartPrompt::Kind::Runs, tr("Number of runs (1 … 65536):"),
                  QString::number(controller_->pointer().runs()),
                  tr("Enter: set · Esc: keep the old value"));
}

void RestartScreen::openWindow() {
    const auto& window = controller_->pointer().window();
    const QString command = QString::fromStdString(std::string(mtc::core::jumpName(window.jump)));
    if (window.kind == mtc::core::PlaneWindow::Kind::Event) {
        eventSet_ = window.eventSet;
        prompt_->open(
            RestartPrompt::Kind::Event,
            tr("%1: event %2:%3").arg(command).arg(window.event.process).arg(window.event.event),
            eventText(eventSet_), tr("Space: change · Enter: follow the jump · Esc: abort"), true);
    } else if (window.kind == mtc::core::PlaneWindow::Kind::Variable) {
        const QString name =
            window.writable ? QString("@%1").arg(window.variable)
                            : QString("@%1:%2").arg(window.variableProcess).arg(window.variable);
        prompt_->open(RestartPrompt::Kind::Variable,
                      tr("%1 %2 = program number:").arg(command, name),
                      window.valueKnown ? QString::number(window.value, 'g', 10) : QString(),
                      window.writable ? tr("Enter: jump with this value · Esc: abort")
                                      : tr("read only (other process) · Enter: jump · Esc: abort"),
                      !window.writable);
    }
}

void RestartScreen::closePrompt() {
    const bool hadFocus = prompt_->isVisible();
    prompt_->close();
    if (hadFocus) list_->setFocus();
}

// ------------------------------------------------------------------ rendering

int RestartScreen::pageRows() const {
    const int rowHeight = std::max(1, list_->sizeHintForRow(0));
    return std::max(1, list_->viewport()->height() / rowHeight - 1);
}

void RestartScreen::scrollToCursor() {
    if (!controller_->active()) return;
    const auto* listing = controller_->listing();
    const int row = listing->rowOfBlock(controller_->pointer().current().cursor);
    if (row < 0) return;
    const QModelIndex index = listing->index(row);
    list_->selectionModel()->setCurrentIndex(index, QItemSelectionModel::NoUpdate);
    list_->scrollTo(index, QAbstractItemView::EnsureVisible);
}

void RestartScreen::render() {
    breadcrumb_->setText(controller_->breadcrumb());
    status_->setText(controller_->status());
    const RestartMessage& message = controller_->message();
    message_->setText(message.text);
    message_->setStyleSheet(messageStyle(message.level));
    // The restart of this visit (or one still running), not the one before.
    const QString phase = controller_->phaseText();
    const bool current = controller_->run()->active() || controller_->accepted().ok;
    progress_->setText(phase);
    progress_->setVisible(current && !phase.isEmpty());
    scrollToCursor();
}

}  // namespace mtc::screens
