#include "hmi/KeyMap.h"

#include <QCoreApplication>

#include "hmi/CoreTerms.h"

namespace mtc::hmi {

namespace {
/// The key list's texts, context "KeyMap" of the catalogues.
struct Text {
    Q_DECLARE_TR_FUNCTIONS(KeyMap)
};
}  // namespace

using mtc::core::ControlKey;

QVector<ControlKey> machineKeys() {
    return {ControlKey::ProgramRestart, ControlKey::Repos,       ControlKey::Manual,
            ControlKey::Automatic,      ControlKey::Start,       ControlKey::Stop,
            ControlKey::ControlReset,   ControlKey::SingleBlock, ControlKey::Mdi};
}

QKeySequence chord(Qt::Modifier modifier, Qt::Key key) {
    // Qt 5 spells a chord as the sum of two enums of different types; one
    // place does the arithmetic on int.
    return QKeySequence(static_cast<int>(modifier) | static_cast<int>(key));
}

QKeySequence stationShortcut(int direction) {
    return chord(Qt::CTRL, direction > 0 ? Qt::Key_PageDown : Qt::Key_PageUp);
}

QKeySequence machineKeyShortcut(ControlKey key) {
    switch (key) {
        case ControlKey::ProgramRestart:
            return chord(Qt::SHIFT, Qt::Key_F1);
        case ControlKey::Repos:
            return chord(Qt::SHIFT, Qt::Key_F2);
        case ControlKey::Manual:
            return chord(Qt::SHIFT, Qt::Key_F3);
        case ControlKey::Automatic:
            return chord(Qt::SHIFT, Qt::Key_F4);
        case ControlKey::Start:
            return chord(Qt::SHIFT, Qt::Key_F5);
        case ControlKey::Stop:
            return chord(Qt::SHIFT, Qt::Key_F6);
        case ControlKey::ControlReset:
            return chord(Qt::SHIFT, Qt::Key_F7);
        case ControlKey::SingleBlock:
            return chord(Qt::SHIFT, Qt::Key_F8);
        case ControlKey::Mdi:
            return chord(Qt::SHIFT, Qt::Key_F9);
    }
    return {};
}

QKeySequence speedKeyShortcut() {
    return chord(Qt::SHIFT, Qt::Key_F10);
}

QKeySequence feedOverrideShortcut(int direction) {
    return chord(Qt::ALT, direction > 0 ? Qt::Key_Up : Qt::Key_Down);
}

QKeySequence rapidOverrideShortcut(int direction) {
    return chord(Qt::ALT, direction > 0 ? Qt::Key_PageUp : Qt::Key_PageDown);
}

QKeySequence baseScreenShortcut() {
    return QKeySequence(Qt::Key_F11);
}

QVector<KeyAssignment> globalKeyAssignments() {
    QVector<KeyAssignment> list = {
        {"F1 … F8", Text::tr("Soft keys of the current screen (labels in the bar at the bottom)")},
        {"Esc", Text::tr("Back to the main menu of the station")},
        {Text::tr("Ctrl+PgUp / Ctrl+PgDn"),
         Text::tr("Previous / next station (process); each keeps its screen")},
        {"F11", Text::tr("Base screen of the station: positions, feed, spindles, running block")},
        {"F12", Text::tr("Help for the screen shown, and every key")},
        {Text::tr("Tab / Shift+Tab"), Text::tr("Move the focus between fields of a screen")},
    };
    for (ControlKey key : machineKeys())
        list.push_back({machineKeyShortcut(key).toString(QKeySequence::NativeText),
                        Text::tr("Machine control key '%1'").arg(keyLabel(key))});
    const auto pair = [](const QKeySequence& up, const QKeySequence& down) {
        return up.toString(QKeySequence::NativeText) + " / " +
               down.toString(QKeySequence::NativeText);
    };
    list.push_back({pair(feedOverrideShortcut(1), feedOverrideShortcut(-1)),
                    Text::tr("Feed override one step up / down (0 … the machine's maximum, "
                             "shown under the M keys)")});
    list.push_back({pair(rapidOverrideShortcut(1), rapidOverrideShortcut(-1)),
                    Text::tr("Rapid traverse override one step up / down (0, 1, 10, 25, 50, "
                             "100 %)")});
    list.push_back({speedKeyShortcut().toString(QKeySequence::NativeText),
                    Text::tr("Simulation speed: ×1 → ×10 → as fast as possible (shown in "
                             "the header)")});
    return list;
}

}  // namespace mtc::hmi
