#include "screens/restart/ReposScreen.h"

#include <QHeaderView>
#include <QKeyEvent>
#include <QLabel>
#include <QTableView>
#include <QVBoxLayout>

#include "hmi/CellSession.h"
#include "screens/restart/ReposModel.h"
#include "screens/restart/RestartController.h"
#include "screens/restart/RestartRun.h"

namespace mtc::screens {

ReposScreen::ReposScreen(const mtc::hmi::ScreenContext& context,
                         std::shared_ptr<RestartController> controller)
    : Screen(context), controller_(std::move(controller)) {
    model_ = new ReposModel(context.session, context.process, controller_->run(), this);
    phase_ = new QLabel(this);
    phase_->setObjectName("reposPhase");
    phase_->setWordWrap(true);
    phase_->setStyleSheet("background: #dfe6ef; padding: 3px; font-weight: bold;");
    table_ = new QTableView(this);
    table_->setObjectName("reposTable");
    table_->setModel(model_);
    table_->verticalHeader()->hide();
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    table_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setSelectionMode(QAbstractItemView::SingleSelection);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->installEventFilter(this);
    message_ = new QLabel(this);
    message_->setObjectName("reposMessage");
    message_->setWordWrap(true);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(phase_);
    layout->addWidget(table_, 1);
    layout->addWidget(message_);
    setFocusProxy(table_);
    auto update = [this] {
        if (isVisible()) render();
    };
    connect(controller_->run(), &RestartRun::progressed, this, update);
    connect(controller_->run(), &RestartRun::phaseChanged, this, update);
    connect(context.session, &mtc::hmi::CellSession::processChanged, this,
            [this, update](int slot) {
                if (slot == this->context().process) update();
            });
}

void ReposScreen::activated() {
    if (!table_->currentIndex().isValid() && model_->rowCount() > 0)
        table_->setCurrentIndex(model_->index(0, 0));
    message_->clear();
    render();
}

void ReposScreen::render() {
    const QString phase = controller_->phaseText();
    phase_->setText(phase.isEmpty() ? tr("No NC program restart: the re-entry point is not known.")
                                    : phase);
    model_->refresh();
}

void ReposScreen::jog(double direction) {
    const int axis = table_->currentIndex().row();
    if (axis < 0) return;
    if (controller_->run()->jog(axis, direction * step_))
        message_->setText(tr("Jogged %1 by %2")
                              .arg(model_->index(axis, 0).data().toString())
                              .arg(direction * step_));
    else
        message_->setText(
            tr("Jogging is possible in manual mode between ADJUST and REPOS only "
               "(and within the travel range)."));
    render();
}

bool ReposScreen::eventFilter(QObject* watched, QEvent* event) {
    if (watched == table_ && event->type() == QEvent::KeyPress) {
        const int key = static_cast<QKeyEvent*>(event)->key();
        if (key == Qt::Key_Plus) {
            jog(+1.0);
            return true;
        }
        if (key == Qt::Key_Minus) {
            jog(-1.0);
            return true;
        }
    }
    return Screen::eventFilter(watched, event);
}

mtc::hmi::SoftKeys ReposScreen::softKeys() {
    mtc::hmi::SoftKeys keys(8);
    keys[0] = {tr("Jog −"), [this] { jog(-1.0); }};
    keys[1] = {tr("Jog +"), [this] { jog(+1.0); }};
    keys[2] = {tr("Step\n%1").arg(step_), [this] {
                   step_ = step_ >= 10.0 ? 0.1 : step_ * 10.0;
                   emit softKeysChanged();
               }};
    keys[4] = {tr("Restart\nresult"), [this] { emit navigateTo("restart-result"); }};
    keys[7] = {tr("Back"), [this] { emit navigateTo("menu"); }};
    return keys;
}

}  // namespace mtc::screens
