#pragma once

#include <QCoreApplication>
#include <QVector>
#include <QWidget>
#include <functional>

#include "hmi/SoftKey.h"

namespace mtc::hmi {

class CellSession;
class Screen;

/// What every screen gets: the cell it shows and the process (station) it
/// belongs to. Each station has its own screen instances.
struct ScreenContext {
    CellSession* session = nullptr;
    int process = 0;  ///< station slot (index into the cell's processes)
    /// All screens of the same station (for the help screen's key list).
    std::function<QVector<Screen*>()> stationScreens;
    /// Name of the screen shown before the current one on this station ("" =
    /// none): F12 opens the help of the screen the operator was on.
    std::function<QString()> previousScreen;
};

/// Base of every screen: a widget with a stable name, a title and its soft
/// keys. The screen renders its model and forwards input to it; it never
/// touches other screens or the window (navigation goes through signals).
class Screen : public QWidget {
    Q_OBJECT
  public:
    Screen(const ScreenContext& context, QWidget* parent = nullptr);

    /// Stable lower-case name ("restart", "help", ...).
    virtual QString screenName() const = 0;
    virtual QString title() const = 0;
    /// The soft keys F1..F8 as they are now.
    virtual SoftKeys softKeys() = 0;
    /// Called when the screen becomes visible (refresh from the core).
    virtual void activated() {}

    const ScreenContext& context() const { return context_; }

  signals:
    /// The labels or actions of the soft keys changed.
    void softKeysChanged();
    /// Ask the window to show another screen of the same station.
    void navigateTo(const QString& screenName);

  private:
    ScreenContext context_;
};

}  // namespace mtc::hmi
