#pragma once

#include <QString>

namespace mtc::hmi {

/// The panel's look: grey console, blue header line, raised soft keys and
/// machine keys in the style of the 1990s MTC200 operator interface.
QString panelStyleSheet();

}  // namespace mtc::hmi
