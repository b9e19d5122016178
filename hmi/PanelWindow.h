#pragma once

#include <QMainWindow>
#include <QMap>
#include <QVector>

#include "cnc_core/machine/ProcessControl.h"

class QStackedWidget;

namespace mtc::hmi {

class CellSession;
class MachineKeyBar;
class Screen;
class ScreenRegistry;
class SoftKeyBar;
class StatusHeader;

/// The panel shell: status header, screen area, soft-key bar F1..F8 and the
/// machine control key bar. It only navigates and wires: screens render and
/// act, machine keys go to the CellSession. Each station (process) has its
/// own instance of every screen, so switching stations keeps screen state.
class PanelWindow : public QMainWindow {
    Q_OBJECT
  public:
    PanelWindow(CellSession* session, const ScreenRegistry* registry, QWidget* parent = nullptr);

    /// Shows screen `name` on the current station; false if unknown.
    bool showScreen(const QString& name);
    /// Every station shows screen `name` (start-up: the base screen); false if unknown.
    bool showScreenOnEveryStation(const QString& name);
    /// Switches to station `slot` (wraps around); its last screen reappears.
    void showStation(int slot);
    int currentStation() const { return station_; }
    QString currentScreenName() const;
    Screen* currentScreen() const;
    Screen* screen(int slot, const QString& name) const;
    SoftKeyBar* softKeyBar() const { return softKeys_; }

    /// Restores geometry, station and last screens from QSettings; without
    /// a saved geometry, the window is fitted into its screen's free area.
    void restoreSettings();
    /// Writes geometry, station and last screens to QSettings.
    void saveSettings() const;

  protected:
    void closeEvent(QCloseEvent* event) override;

  private:
    void buildStations();
    void installShortcuts();
    void refresh();
    /// Shrinks the window to its screen's available area, not below its
    /// minimum size.
    void fitIntoScreen();
    void onMachineKey(mtc::core::ControlKey key);
    /// An override switch of the shown station one position up or down.
    void stepOverride(bool rapid, int direction);
    /// The question before a user compiler that came with the program folder
    /// runs (docs/DECISIONS.md D-010): true when the operator says Yes.
    bool askToRunUserCompiler(int slot, const QString& command, const QString& folder);

    CellSession* session_;
    const ScreenRegistry* registry_;
    StatusHeader* header_;
    QStackedWidget* stationStack_;
    SoftKeyBar* softKeys_;
    MachineKeyBar* machineKeys_;
    QVector<QStackedWidget*> stationPages_;
    QVector<QMap<QString, Screen*>> screens_;
    QVector<QString> currentScreen_;
    QVector<QString> previousScreen_;  ///< per station: the screen before the current one
    int station_ = 0;
};

}  // namespace mtc::hmi
