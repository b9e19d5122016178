#include "screens/mdi/MdiScreen.h"

#include <QFontDatabase>
#include <QLabel>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QStringList>
#include <QVBoxLayout>

#include "hmi/CellSession.h"
#include "screens/mdi/MdiModel.h"

namespace mtc::screens {

namespace {

QLabel* makeLabel(QWidget* parent, const char* name, const QFont& font) {
    auto* label = new QLabel(parent);
    label->setObjectName(name);
    label->setFont(font);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    label->setWordWrap(true);  // long texts must not widen the panel's minimum size
    return label;
}

QLabel* caption(QWidget* parent, const QString& text) {
    auto* label = new QLabel(text, parent);
    QFont bold = label->font();
    bold.setBold(true);
    label->setFont(bold);
    return label;
}

}  // namespace

MdiScreen::MdiScreen(const mtc::hmi::ScreenContext& context) : Screen(context) {
    model_ = new MdiModel(context.session, context.process, this);
    const QFont fixed = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    mode_ = makeLabel(this, "mdiMode", font());
    position_ = makeLabel(this, "mdiPosition", fixed);
    modal_ = makeLabel(this, "mdiModal", fixed);
    input_ = new QPlainTextEdit(this);
    input_->setObjectName("mdiInput");
    input_->setFont(fixed);
    input_->setTabChangesFocus(true);
    input_->setPlaceholderText(
        tr("NC blocks, one a line (global macros allowed); Start runs them"));
    input_->setMaximumHeight(input_->fontMetrics().lineSpacing() * 6);
    message_ = makeLabel(this, "mdiMessage", font());
    history_ = new QListWidget(this);
    history_->setObjectName("mdiHistory");
    history_->setFont(fixed);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(mode_);
    positionCaption_ = caption(this, {});
    positionCaption_->setObjectName("mdiPositionCaption");
    modalCaption_ = caption(this, {});
    layout->addWidget(positionCaption_);
    layout->addWidget(position_);
    layout->addWidget(modalCaption_);
    layout->addWidget(modal_);
    layout->addWidget(caption(this, tr("MDI input")));
    layout->addWidget(input_);
    layout->addWidget(message_);
    layout->addWidget(caption(this, tr("Entries run")));
    layout->addWidget(history_, 1);
    setFocusProxy(input_);

    connect(input_, &QPlainTextEdit::textChanged, this,
            [this] { model_->setInput(input_->toPlainText()); });
    connect(model_, &MdiModel::changed, this, [this] {
        if (isVisible()) refresh();
    });
    connect(history_, &QListWidget::itemActivated, this, [this] {
        if (model_->recall(history_->currentRow())) input_->setFocus();
    });
    refresh();
}

void MdiScreen::activated() {
    refresh();
    input_->setFocus();
}

void MdiScreen::refresh() {
    mode_->setText(model_->modeSummary());
    // While the axes work off blocks the interpreter has left behind, the
    // lines show the running block's state and where the axes are.
    const bool running = model_->showsRunningBlock();
    positionCaption_->setText(running ? tr("Position (actual, running program)")
                                      : tr("Position (programmed)"));
    modalCaption_->setText(running ? tr("Modal state of the running block") : tr("Modal state"));
    position_->setText(model_->positionSummary());
    modal_->setText(model_->modalSummary());
    if (input_->toPlainText() != model_->input()) {  // cleared or recalled by the model
        input_->setPlainText(model_->input());
        input_->moveCursor(QTextCursor::End);
    }
    message_->setText(model_->message());
    message_->setStyleSheet(model_->messageIsError() ? "color: #c00000;" : QString());
    refreshHistory();
}

void MdiScreen::refreshHistory() {
    QStringList rows;
    const auto& items = model_->history();
    for (std::size_t i = 0; i < items.size(); ++i) {
        QString text = QString::fromStdString(items[i].text);
        text.replace('\n', " | ");
        rows << QString("%1  %2   [%3]")
                    .arg(static_cast<int>(i) + 1, 2)
                    .arg(text, QString::fromStdString(items[i].outcome));
    }
    bool same = rows.size() == history_->count();
    for (int i = 0; same && i < rows.size(); ++i)
        same = history_->item(i)->text() == rows[i];
    if (same) return;  // refreshed every tick while an entry runs
    const bool grew = rows.size() > history_->count();
    const int row = history_->currentRow();
    history_->clear();
    history_->addItems(rows);
    if (!rows.isEmpty()) history_->setCurrentRow(grew || row < 0 ? rows.size() - 1 : row);
}

mtc::hmi::SoftKeys MdiScreen::softKeys() {
    mtc::hmi::SoftKeys keys(8);
    keys[0] = {tr("Check\ninput"), [this] {
                   model_->check();
                   refresh();
               }};
    keys[1] = {tr("Recall\nentry"), [this] {
                   model_->recall(history_->currentRow());
                   refresh();
                   input_->setFocus();
               }};
    keys[2] = {tr("Clear\ninput"), [this] {
                   input_->clear();
                   input_->setFocus();
               }};
    keys[3] = {tr("Error\ndisplay"), [this] { emit navigateTo("errors"); }};
    keys[7] = {tr("Back"), [this] { emit navigateTo("menu"); }};
    return keys;
}

}  // namespace mtc::screens
