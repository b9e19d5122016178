#pragma once

#include <QString>

#include "cnc_core/cell/StationStatus.h"
#include "cnc_core/machine/ProcessControl.h"

namespace mtc::hmi {

/// The panel's words for the names the core gives (machine keys, operating
/// modes, program states). The core keeps one English name per value; the
/// panel translates that name in the context "CoreTerms" of the catalogues
/// (docs/DECISIONS.md D-018). A test checks every value has a German text.
QString keyLabel(mtc::core::ControlKey key);
QString modeLabel(mtc::core::OperatingMode mode);
QString programStateLabel(mtc::core::ProgramState state);
/// The state in a few words ("feed hold: Start continues").
QString programStateDescription(mtc::core::ProgramState state);
/// The translation of one of the core's English names ("" stays "").
QString coreTerm(const char* english);

}  // namespace mtc::hmi
