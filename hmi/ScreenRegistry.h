#pragma once

#include <QString>
#include <QVector>
#include <functional>

#include "hmi/Screen.h"

namespace mtc::hmi {

/// Screens register themselves here (name, title, factory); the window
/// creates one instance per station on first use.
class ScreenRegistry {
  public:
    using Factory = std::function<Screen*(const ScreenContext&)>;
    struct Entry {
        QString name;
        QString title;
        Factory factory;
        bool inMainMenu = true;  ///< offered on the main menu's soft keys
    };

    /// Adds a screen; a second registration of the same name replaces the first.
    void add(const QString& name, const QString& title, Factory factory, bool inMainMenu = true);
    const Entry* find(const QString& name) const;
    const QVector<Entry>& entries() const { return entries_; }
    QStringList names() const;

  private:
    QVector<Entry> entries_;
};

}  // namespace mtc::hmi
