#pragma once

// The GNE editing model's texts in the panel's language (issue 20 §1,
// docs/DECISIONS.md D-018): the model writes English forms marked for Qt
// Linguist (context "GneModel"), these functions translate them.

#include <QString>
#include <vector>

#include "screens/gne/GneFields.h"
#include "screens/gne/GneModelText.h"

namespace mtc::screens {

/// `text` with its form translated and the values filled in. In German a
/// core GNE diagnostic's message is preceded by its code's German brief
/// message (D-023).
QString gneText(const gnefields::ModelText& text);
/// Each text on its own line.
QString gneLines(const std::vector<gnefields::ModelText>& texts);
/// The one-line meaning of a value, with what an empty optional value
/// stands for.
QString gneMeaning(const gnefields::Field& field);

}  // namespace mtc::screens
