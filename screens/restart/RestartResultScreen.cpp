#include "screens/restart/RestartResultScreen.h"

#include <QHeaderView>
#include <QLabel>
#include <QTableView>
#include <QVBoxLayout>

#include "hmi/ColumnFit.h"
#include "screens/restart/RestartController.h"
#include "screens/restart/RestartResultModel.h"
#include "screens/restart/RestartRun.h"

namespace mtc::screens {

RestartResultScreen::RestartResultScreen(const mtc::hmi::ScreenContext& context,
                                         std::shared_ptr<RestartController> controller)
    : Screen(context), controller_(std::move(controller)) {
    model_ = new RestartResultModel(controller_->run(), controller_->verification(),
                                    &controller_->collisions(), this);
    summary_ = new QLabel(this);
    summary_->setObjectName("resultSummary");
    summary_->setWordWrap(true);
    summary_->setStyleSheet("background: #dfe6ef; padding: 3px; font-weight: bold;");
    collisions_ = new QLabel(this);
    collisions_->setObjectName("resultCollisions");
    collisions_->setWordWrap(true);
    collisions_->hide();
    table_ = new QTableView(this);
    table_->setObjectName("resultTable");
    table_->setModel(model_);
    table_->verticalHeader()->hide();
    // Headings across the table (before the columns are fitted: they do
    // not widen the item column), then columns as wide as their texts
    // need, long texts wrapped at blanks: the collision's position was cut
    // at 144 dpi (issue 19).
    connect(model_, &QAbstractItemModel::modelReset, this, &RestartResultScreen::spanHeadings);
    new mtc::hmi::ColumnFit(table_);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    hint_ = new QLabel(this);
    hint_->setObjectName("resultHint");
    hint_->setWordWrap(true);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(summary_);
    layout->addWidget(collisions_);
    layout->addWidget(table_, 1);
    layout->addWidget(hint_);
    setFocusProxy(table_);
    connect(controller_->run(), &RestartRun::phaseChanged, this, [this] {
        if (isVisible()) activated();
    });
}

void RestartResultScreen::spanHeadings() {
    table_->clearSpans();
    for (int row = 0; row < model_->rowCount(); ++row)
        if (model_->index(row, 0).data(RestartResultModel::SectionRole).toBool())
            table_->setSpan(row, 0, 1, model_->columnCount());
}

void RestartResultScreen::activated() {
    model_->reload();
    render();
    emit softKeysChanged();
}

void RestartResultScreen::render() {
    const RestartRun* run = controller_->run();
    renderCollisions();
    if (!run->started()) {
        summary_->setText(tr("No computing process yet: select the target on the restart screen."));
        hint_->clear();
        return;
    }
    const auto& s = controller_->accepted();
    summary_->setText(
        tr("Target %1  ·  %2 blocks interpreted  ·  %3 differences  ·  verification: %4")
            .arg(controller_->acceptedTarget())
            .arg(run->computedBlocks())
            .arg(model_->differenceCount())
            .arg(model_->verificationSummary()) +
        (s.selection.runs > 1 ? tr("  ·  arrival %1").arg(s.selection.runs) : QString()));
    hint_->setText(controller_->phaseText());
}

void RestartResultScreen::renderCollisions() {
    const RestartCollisions& check = controller_->collisions();
    const QString text = check.summary();
    collisions_->setVisible(!text.isEmpty());
    collisions_->setText(text);
    // Red when the way back meets the part, neutral when clear or unchecked.
    collisions_->setStyleSheet(check.colliding()
                                   ? "background: #c00000; color: white; padding: 3px; "
                                     "font-weight: bold;"
                                   : "background: #eef2f6; color: #303030; padding: 3px;");
}

mtc::hmi::SoftKeys RestartResultScreen::softKeys() {
    mtc::hmi::SoftKeys keys(8);
    keys[0] = {tr("Reposition"), [this] { emit navigateTo("repos"); }};
    keys[1] = {tr("Target\nselection"), [this] { emit navigateTo("restart"); }};
    keys[2] = {model_->differencesOnly() ? tr("All\nitems") : tr("Differences\nonly"), [this] {
                   model_->setDifferencesOnly(!model_->differencesOnly());
                   emit softKeysChanged();
               }};
    keys[3] = {tr("Verify\ntarget"),
               [this] {
                   controller_->verifyAcceptedTarget();
                   activated();
               },
               controller_->accepted().ok};
    keys[7] = {tr("Back"), [this] { emit navigateTo("menu"); }};
    return keys;
}

}  // namespace mtc::screens
