#pragma once

#include <QKeySequence>
#include <QString>
#include <QVector>

#include "cnc_core/machine/ProcessControl.h"

namespace mtc::hmi {

/// One key assignment of the panel, as the help screen lists it.
struct KeyAssignment {
    QString keys;
    QString meaning;
};

/// A key with a modifier (Qt::SHIFT, Qt::CTRL, Qt::ALT).
QKeySequence chord(Qt::Modifier modifier, Qt::Key key);

/// The keys that show the next (`direction` > 0: Ctrl+PgDn) or previous
/// station (Ctrl+PgUp).
QKeySequence stationShortcut(int direction);

/// Keyboard shortcut of each machine control key (M key).
QKeySequence machineKeyShortcut(mtc::core::ControlKey key);

/// The key that changes the simulation speed (x1, x10, as fast as possible).
QKeySequence speedKeyShortcut();

/// The keys of the override switches: one position up (`direction` > 0) or
/// down (feed: Alt+Up / Alt+Down, rapid: Alt+PgUp / Alt+PgDn).
QKeySequence feedOverrideShortcut(int direction);
QKeySequence rapidOverrideShortcut(int direction);

/// The key that shows the station's base screen (position display).
QKeySequence baseScreenShortcut();

/// All machine control keys in bar order.
QVector<mtc::core::ControlKey> machineKeys();

/// Every global key assignment of the panel (soft keys, M keys, navigation).
/// The single source for the help screen and the README's key map.
QVector<KeyAssignment> globalKeyAssignments();

}  // namespace mtc::hmi
