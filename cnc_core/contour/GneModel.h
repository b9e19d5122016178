#pragma once

// The graphical NC editor's instructions as data (seed 001, ch. 3 and 12):
// drawing windows, contours with partly specified elements, forms and
// machining cycles. Syntax: docs/GNE-SYNTAX.md. Plain C++17, no Qt.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace mtc::core::gne {

/// The plane a GNE item is drawn in: turning = G18 (1st axis Z, 2nd axis X,
/// centre letters K and I), milling = G17 (X, Y; I, J).
enum class GnePlane : std::uint8_t { Turning, Milling };

/// Kinds of contour elements (seed 001, ch. 12: START, LINE, CW, CCW, RD, CF, RELIEF).
enum class ElementKind : std::uint8_t { Start, Line, ArcCW, ArcCCW, Round, Chamfer, Relief };

/// One element of a contour as the operator entered it. Every geometric
/// value is optional: the solver computes what is missing. Coordinates are
/// in plane order (index 0 = 1st plane axis, 1 = 2nd plane axis).
struct ContourElement {
    ElementKind kind = ElementKind::Line;
    std::optional<double> end[2];     ///< end point (START: the point)
    std::optional<double> centre[2];  ///< CW/CCW: absolute centre
    std::optional<double> angle;      ///< LINE: direction in degrees from the 1st axis, ccw
    std::optional<double> length;     ///< LINE: length
    std::optional<double> radius;     ///< CW/CCW radius; RD rounding radius; RELIEF radius
    std::optional<double> width;      ///< CF chamfer width; RELIEF width (else DIN 509 table)
    std::optional<double> depth;      ///< RELIEF depth into the cylinder (t1)
    std::optional<double> faceDepth;  ///< RELIEF form F: depth into the face (t2)
    char reliefForm = 'E';            ///< RELIEF: DIN 509 form E or F
    bool tangent = false;             ///< TAN: tangential to the previous element
    int alternative = 0;              ///< ALT: chosen solution where several exist (0-based)
    std::uint32_t line = 0;           ///< source line (0 = built in memory)
};

/// CONT (nr, FINAL|RAW) ... END_CONT.
struct Contour {
    int number = 0;
    bool raw = false;  ///< RAW = initial (blank) contour, else final part contour
    GnePlane plane = GnePlane::Turning;
    std::vector<ContourElement> elements;
    std::uint32_t line = 0;
    std::uint32_t endLine = 0;
};

/// A keyword with positional parameters: WINDOW_0x, FORM_xx, CYCLE_xx.
/// Empty positions keep their default (`values[i]` empty).
struct GneCall {
    std::string keyword;                        ///< "FORM_52", "CYCLE_11", ...
    std::vector<std::optional<double>> values;  ///< numeric parameters in order
    std::string text;                           ///< FORM_54/55: the quoted text
    std::uint32_t line = 0;
};

/// One item of a GNE instruction sequence in program order.
struct GneItem {
    bool isContour = false;
    Contour contour;  ///< when isContour
    GneCall call;     ///< otherwise
};

/// Diagnostic of the GNE reader, solver or expansion.
struct GneDiagnostic {
    std::uint32_t line = 0;  ///< source line, 0 = unknown
    std::string code;        ///< e.g. "GNE_UNDERDETERMINED"
    std::string message;
};

/// Every GNE item of a program text in order, with what was wrong.
struct GneDocument {
    std::vector<GneItem> items;
    std::vector<GneDiagnostic> diagnostics;
    bool ok() const { return diagnostics.empty(); }
};

/// Keyword of an element ("LINE", "CW", ...).
const char* elementKeyword(ElementKind kind);

}  // namespace mtc::core::gne
