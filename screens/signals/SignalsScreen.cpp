#include "screens/signals/SignalsScreen.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QTableView>

#include "hmi/CellSession.h"
#include "screens/signals/SignalModel.h"

namespace mtc::screens {

namespace {
QTableView* makeView(QWidget* parent, const char* name, QAbstractItemModel* model) {
    auto* view = new QTableView(parent);
    view->setObjectName(name);
    view->setModel(model);
    view->verticalHeader()->hide();
    view->horizontalHeader()->setStretchLastSection(true);
    view->setSelectionBehavior(QAbstractItemView::SelectRows);
    return view;
}
}  // namespace

SignalsScreen::SignalsScreen(const mtc::hmi::ScreenContext& context) : Screen(context) {
    auto& control = context.session->control(context.process);
    values_ = new SignalModel(&control.signalTable(), SignalModel::View::Values, this);
    log_ = new SignalModel(&control.signalTable(), SignalModel::View::Log, this);
    valueView_ = makeView(this, "signalValues", values_);
    logView_ = makeView(this, "signalLog", log_);
    auto* layout = new QHBoxLayout(this);
    layout->addWidget(valueView_, 1);
    layout->addWidget(logView_, 1);
    setFocusProxy(logView_);
    connect(context.session, &mtc::hmi::CellSession::processChanged, this, [this](int slot) {
        if (slot == this->context().process && isVisible()) activated();
    });
}

void SignalsScreen::activated() {
    values_->reload();
    log_->reload();
}

mtc::hmi::SoftKeys SignalsScreen::softKeys() {
    mtc::hmi::SoftKeys keys(8);
    keys[0] = {tr("Clear\nlog"), [this] {
                   context().session->control(context().process).signalTable().clearLog();
                   activated();
               }};
    keys[7] = {tr("Back"), [this] { emit navigateTo("menu"); }};
    return keys;
}

}  // namespace mtc::screens
