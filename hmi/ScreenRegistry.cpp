#include "hmi/ScreenRegistry.h"

namespace mtc::hmi {

void ScreenRegistry::add(const QString& name, const QString& title, Factory factory,
                         bool inMainMenu) {
    for (auto& e : entries_) {
        if (e.name == name) {
            e = {name, title, std::move(factory), inMainMenu};
            return;
        }
    }
    entries_.push_back({name, title, std::move(factory), inMainMenu});
}

const ScreenRegistry::Entry* ScreenRegistry::find(const QString& name) const {
    for (const auto& e : entries_)
        if (e.name == name) return &e;
    return nullptr;
}

QStringList ScreenRegistry::names() const {
    QStringList list;
    for (const auto& e : entries_)
        list << e.name;
    return list;
}

}  // namespace mtc::hmi
