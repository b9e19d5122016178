#pragma once

// Reading and writing the GNE keywords (docs/GNE-SYNTAX.md):
// keyword text <-> GneDocument, with a diagnostic and line for bad input.

#include <string>
#include <string_view>

#include "cnc_core/contour/GneModel.h"

namespace mtc::core::gne {

/// Reads every GNE instruction of `text` (a whole NC program or just the GNE
/// lines). Lines that are not GNE keywords are skipped outside CONT ...
/// END_CONT; N numbers, '/', ':' and ';' comments are allowed on every line.
/// `firstLine` is the line number of the text's first line. Never throws:
/// bad input becomes diagnostics with line; good items are kept.
GneDocument readGne(std::string_view text, std::uint32_t firstLine = 1);

/// The shortest decimal text that reads back as exactly `value`.
std::string formatValue(double value);

/// One contour element as a line ("LINE Z-30 X20 TAN").
std::string writeElement(const ContourElement& element, GnePlane plane);
/// A contour: "CONT (1, FINAL)", its elements, "END_CONT", one per line.
std::string writeContour(const Contour& contour);
/// A call: "FORM_52 (3, 40, 30, 12.5)".
std::string writeCall(const GneCall& call);
/// Every item, one instruction per line, each line ending in '\n'.
std::string writeGne(const GneDocument& document);

/// The plane-axis letters of end points (turning "ZX", milling "XY") and of
/// centres (turning "KI", milling "IJ").
const char* endLetters(GnePlane plane);
const char* centreLetters(GnePlane plane);

}  // namespace mtc::core::gne
