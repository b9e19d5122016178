#include "screens/menu/MenuScreen.h"

#include <QKeyEvent>
#include <QLabel>
#include <QListWidget>
#include <QVBoxLayout>

#include "hmi/ScreenRegistry.h"

namespace mtc::screens {

namespace {
constexpr int kKeysPerPage = 7;  // F8 pages through the rest
}

MenuScreen::MenuScreen(const mtc::hmi::ScreenContext& context,
                       const mtc::hmi::ScreenRegistry* registry)
    : Screen(context), registry_(registry) {
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(
        new QLabel(tr("Select a screen (cursor keys + Enter, or its soft key):"), this));
    list_ = new QListWidget(this);
    list_->setObjectName("menuList");
    layout->addWidget(list_);
    setFocusProxy(list_);
    list_->installEventFilter(this);
    connect(list_, &QListWidget::itemActivated, this, [this] { openSelected(); });
}

void MenuScreen::activated() {
    list_->clear();
    targets_.clear();
    for (const auto& entry : registry_->entries()) {
        if (!entry.inMainMenu || entry.name == screenName()) continue;
        targets_ << entry.name;
        list_->addItem(QString("%1  (%2)").arg(entry.title, entry.name));
    }
    if (list_->currentRow() < 0 && list_->count() > 0) list_->setCurrentRow(0);
    if (page_ * kKeysPerPage >= targets_.size()) page_ = 0;
    emit softKeysChanged();
}

mtc::hmi::SoftKeys MenuScreen::softKeys() {
    mtc::hmi::SoftKeys keys(8);
    for (int i = 0; i < kKeysPerPage; ++i) {
        const int index = page_ * kKeysPerPage + i;
        if (index >= targets_.size()) break;
        const QString name = targets_[index];
        const auto* entry = registry_->find(name);
        keys[i] = {entry ? entry->title : name, [this, name] { emit navigateTo(name); }};
    }
    if (targets_.size() > kKeysPerPage) {
        keys[7] = {tr("More…"), [this] {
                       const int pages = (targets_.size() + kKeysPerPage - 1) / kKeysPerPage;
                       page_ = (page_ + 1) % pages;
                       emit softKeysChanged();
                   }};
    }
    return keys;
}

void MenuScreen::openSelected() {
    const int row = list_->currentRow();
    if (row >= 0 && row < targets_.size()) emit navigateTo(targets_[row]);
}

void MenuScreen::keyPressEvent(QKeyEvent* event) {
    if (event->key() == Qt::Key_Return || event->key() == Qt::Key_Enter) {
        openSelected();
        return;
    }
    Screen::keyPressEvent(event);
}

}  // namespace mtc::screens
