#pragma once

// A single-stroke font for engraving text (FORM_54 / FORM_55): every
// character is a few polylines on a 4 x 6 grid (cap height 6, advance 6).

#include <string>
#include <vector>

#include "cnc_core/contour/Geometry2D.h"

namespace mtc::core::gne {

using Stroke = std::vector<Point>;

/// Strokes of one character in grid units (origin at the lower left of the
/// cell); lower-case letters use the capitals. Empty for a blank.
/// `known` is false for a character the font does not have.
std::vector<Stroke> glyphStrokes(char c, bool* known = nullptr);

/// Grid units from one character's origin to the next.
constexpr double kGlyphAdvance = 6.0;
/// Grid units of the cap height.
constexpr double kGlyphHeight = 6.0;

/// The characters the font has, for validation messages.
std::string fontCharacters();

}  // namespace mtc::core::gne
