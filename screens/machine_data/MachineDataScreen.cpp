#include "screens/machine_data/MachineDataScreen.h"

#include <QHeaderView>
#include <QKeyEvent>
#include <QLabel>
#include <QLocale>
#include <QTableView>
#include <QVBoxLayout>
#include <algorithm>

#include "cnc_core/machine_data/MachineDataStore.h"
#include "cnc_core/machine_data/StandardPages.h"
#include "hmi/CellSession.h"
#include "hmi/PromptedInput.h"
#include "screens/machine_data/MachineDataModel.h"
#include "screens/machine_data/MachineDataTexts.h"

namespace mtc::screens {

namespace {

using mtc::core::MachineDataStatus;

QString rangeText(const mtc::core::MachineDataElement& e) {
    return QString::fromStdString(mtc::core::formatMachineDataValue(e.type, e.minimum) + " .. " +
                                  mtc::core::formatMachineDataValue(e.type, e.maximum) +
                                  (e.unit.empty() ? "" : " " + e.unit));
}

}  // namespace

MachineDataScreen::MachineDataScreen(const mtc::hmi::ScreenContext& context) : Screen(context) {
    model_ = new MachineDataModel(&context.session->machineData(), this);
    header_ = new QLabel(this);
    header_->setObjectName("mdPage");
    table_ = new QTableView(this);
    table_->setObjectName("mdTable");
    table_->setModel(model_);
    table_->verticalHeader()->hide();
    table_->horizontalHeader()->setSectionResizeMode(MachineDataModel::Title, QHeaderView::Stretch);
    table_->setSelectionMode(QAbstractItemView::NoSelection);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->installEventFilter(this);
    inputLine_ = new mtc::hmi::PromptedInput("mdPrompt", "mdEditor", this);
    inputLine_->setReturnFocus(table_);
    connect(inputLine_, &mtc::hmi::PromptedInput::confirmed, this,
            &MachineDataScreen::confirmInput);
    connect(inputLine_, &mtc::hmi::PromptedInput::cancelled, this, &MachineDataScreen::cancelInput);
    message_ = new QLabel(this);
    message_->setObjectName("mdMessage");
    message_->setWordWrap(true);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(header_);
    layout->addWidget(table_, 1);
    layout->addWidget(inputLine_);
    layout->addWidget(message_);
    setFocusProxy(table_);
    closeInput();
    showPage(mtc::core::kAdaptiveFeedPage, 0);
    const QStringList told = context.session->machineDataMessages();
    if (!told.isEmpty()) say(told.join('\n'));
    connect(context.session, &mtc::hmi::CellSession::processChanged, this, [this](int slot) {
        if (slot == this->context().process) model_->refresh();
    });
    // Another program changed the data file: the values shown are its now.
    connect(context.session, &mtc::hmi::CellSession::machineDataNotice, this,
            [this](const QString& notice) {
                notice_ = notice;
                model_->refresh();
                say(notice);
            });
}

int MachineDataScreen::processNumber() const {
    return context().session->processConfig(context().process).index;
}

void MachineDataScreen::activated() {
    model_->refresh();
    updateHeader();
}

void MachineDataScreen::hideEvent(QHideEvent* event) {
    password_.clear();  // leaving the screen locks the protected elements again
    closeInput();
    Screen::hideEvent(event);
}

void MachineDataScreen::showPage(int page, int sub) {
    const mtc::core::MachineDataPage* definition =
        context().session->machineData().page(processNumber(), page);
    if (!definition) return;
    if (definition->subSlot(sub) < 0) sub = definition->subs().front();
    model_->showPage(processNumber(), page, sub);
    updateHeader();
    emit softKeysChanged();
}

void MachineDataScreen::stepPage(int step) {
    if (input_ != Input::None) return;
    const std::vector<int> pages = context().session->machineData().pageNumbers(processNumber());
    auto at = std::find(pages.begin(), pages.end(), model_->page());
    if (pages.empty() || at == pages.end()) return;
    const int count = static_cast<int>(pages.size());
    const int index = static_cast<int>(at - pages.begin());
    showPage(pages[static_cast<std::size_t>((index + step + count) % count)], -1);
}

void MachineDataScreen::stepSub() {
    const std::vector<int> subs = model_->definition()->subs();
    if (subs.size() < 2 || input_ != Input::None) return;
    auto at = std::find(subs.begin(), subs.end(), model_->sub());
    const std::size_t next = (static_cast<std::size_t>(at - subs.begin()) + 1) % subs.size();
    const int cursor = model_->cursor();
    model_->showPage(model_->process(), model_->page(), subs[next]);
    model_->moveCursor(cursor);
    updateHeader();
}

void MachineDataScreen::updateHeader() {
    const mtc::core::MachineDataPage* page = model_->definition();
    if (!page) return;
    QString text =
        tr("Page %1  %2    process %3 (%4)")
            .arg(page->number)
            .arg(machineDataText(page->title))
            .arg(processNumber())
            .arg(QString::fromStdString(context().session->processConfig(context().process).name));
    if (model_->sub() > 0)
        text +=
            "    " +
            tr("sub %1: %2")
                .arg(model_->sub())
                .arg(machineDataText(page->subTitles[static_cast<std::size_t>(model_->sub() - 1)]));
    header_->setText(text);
    table_->scrollTo(model_->index(model_->cursor(), 0));
}

mtc::hmi::SoftKeys MachineDataScreen::softKeys() {
    mtc::hmi::SoftKeys keys(8);
    keys[0] = {tr("Page\n-"), [this] { stepPage(-1); }};
    keys[1] = {tr("Page\n+"), [this] { stepPage(1); }};
    const bool hasSubs = model_->definition() && model_->definition()->subs().size() > 1;
    keys[2] = {hasSubs ? QString("M(16)\n/ Q") : QString(), [this] { stepSub(); }, hasSubs};
    keys[3] = {tr("Edit"), [this] { startEdit(); }};
    keys[7] = {tr("Back"), [this] { emit navigateTo("menu"); }};
    return keys;
}

bool MachineDataScreen::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() != QEvent::KeyPress) return Screen::eventFilter(watched, event);
    const int key = static_cast<QKeyEvent*>(event)->key();
    if (watched == table_) return browseKey(key);
    return Screen::eventFilter(watched, event);
}

bool MachineDataScreen::browseKey(int key) {
    const int pageRows = std::max(1, table_->viewport()->height() / 24);
    switch (key) {
        case Qt::Key_Up:
            model_->moveCursor(-1);
            break;
        case Qt::Key_Down:
            model_->moveCursor(1);
            break;
        case Qt::Key_PageUp:
            model_->moveCursor(-pageRows);
            break;
        case Qt::Key_PageDown:
            model_->moveCursor(pageRows);
            break;
        case Qt::Key_Left:
            stepPage(-1);
            return true;
        case Qt::Key_Right:
            stepPage(1);
            return true;
        case Qt::Key_Return:
        case Qt::Key_Enter:
            startEdit();
            return true;
        default:
            return false;
    }
    table_->scrollTo(model_->index(model_->cursor(), 0));
    return true;
}

QString MachineDataScreen::elementName() const {
    const mtc::core::MachineDataElement* e = model_->currentElement();
    if (!e) return {};
    return QString("%1 %2").arg(e->number, 3, 10, QChar('0')).arg(machineDataText(e->designation));
}

void MachineDataScreen::startEdit() {
    const mtc::core::MachineDataElement* e = model_->currentElement();
    if (!e || input_ != Input::None) return;
    if (e->protectedGui) {
        say(tr("Element %1 is write-protected: only the NC changes it").arg(elementName()));
        return;
    }
    openInput(Input::Value, tr("New value of %1 (%2):").arg(elementName(), rangeText(*e)),
              model_->currentValueText());
}

void MachineDataScreen::openInput(Input input, const QString& prompt, const QString& text) {
    input_ = input;
    inputLine_->open(prompt, text,
                     input == Input::Password ? QLineEdit::Password : QLineEdit::Normal);
}

void MachineDataScreen::closeInput() {
    input_ = Input::None;
    inputLine_->close();
}

void MachineDataScreen::cancelInput() {
    closeInput();
    say(tr("Input cancelled: the value stays %1").arg(model_->currentValueText()));
}

void MachineDataScreen::confirmInput(const QString& text) {
    const Input input = input_;
    closeInput();
    if (input == Input::Value) confirmValue(text.trimmed());
    if (input == Input::Password) confirmPassword(text.trimmed());
}

void MachineDataScreen::confirmValue(const QString& text) {
    bool ok = false;
    const double value = QLocale::c().toDouble(text, &ok);
    if (!ok) {
        say(tr("'%1' is not a number: %2 stays %3")
                .arg(text, elementName(), model_->currentValueText()));
        return;
    }
    writeValue(value);
}

void MachineDataScreen::confirmPassword(const QString& text) {
    if (!context().session->machineData().passwordMatches(text.toStdString())) {
        say(tr("Wrong password: %1 stays %2").arg(elementName(), model_->currentValueText()));
        return;
    }
    password_ = text;
    writeValue(pendingValue_);
}

void MachineDataScreen::writeValue(double value) {
    mtc::core::MachineDataStore& store = context().session->machineData();
    const MachineDataStatus status =
        store.write(model_->currentAddress(), value, mtc::core::MachineDataWriter::Gui,
                    password_.toStdString());
    if (status == MachineDataStatus::PasswordRequired) {
        pendingValue_ = value;
        openInput(Input::Password, tr("Password for %1:").arg(elementName()), {});
        return;
    }
    model_->refresh();
    if (status != MachineDataStatus::Ok) {
        QString reason = mtc::core::machineDataStatusText(status);
        if (status == MachineDataStatus::OutOfRange && model_->currentElement())
            reason += " " + rangeText(*model_->currentElement());
        say(tr("%1: %2 stays %3").arg(reason, elementName(), model_->currentValueText()));
        return;
    }
    QString error;
    notice_.clear();
    const bool saved = context().session->saveMachineData(error);
    say(elementName() + " = " + model_->currentValueText() +
        (saved ? QString() : "\n" + tr("NOT saved: %1").arg(error)) +
        (notice_.isEmpty() ? QString() : "\n" + notice_));
}

void MachineDataScreen::say(const QString& message) {
    message_->setText(message);
}

}  // namespace mtc::screens
