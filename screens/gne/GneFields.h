#pragma once

// The parameter entry of the GNE screen: which values a contour element, a
// CONT header or a keyword call (WINDOW_0x, FORM_xx, CYCLE_xx) has, their
// text as shown, and checked assignment from operator text (bad text ->
// message, old value kept). Plain C++; the call parameters come from
// cnc_core/contour/GneSchema.h, the element values are defined here.

#include <string>
#include <vector>

#include "cnc_core/contour/GneModel.h"
#include "screens/gne/GneModelText.h"

namespace mtc::screens::gnefields {

/// One value of the parameter entry.
struct Field {
    std::string name;     ///< short name ("Z", "R", "DEPTH")
    std::string meaning;  ///< one line for the operator (English, context "GneModel")
    std::string value;    ///< as shown; "" = not given (solver computes / default)
    bool required = false;
    std::string emptyValue;  ///< what an empty optional value stands for ("" = none)
};

/// The values of contour element `e` in `plane`.
std::vector<Field> elementFields(const mtc::core::gne::ContourElement& e,
                                 mtc::core::gne::GnePlane plane);

/// Sets value `index` of `e` from `text` ("" clears an optional value).
/// False with an operator message when the text is not acceptable; `e` is
/// then unchanged.
bool setElementField(mtc::core::gne::ContourElement& e, mtc::core::gne::GnePlane plane, int index,
                     const std::string& text, ModelText& message);

/// The values of a CONT header: number and kind (0 = FINAL, 1 = RAW).
std::vector<Field> contourFields(const mtc::core::gne::Contour& c);
/// Sets value `index` of a CONT header (see setElementField).
bool setContourField(mtc::core::gne::Contour& c, int index, const std::string& text,
                     ModelText& message);

/// The positional parameters of a call (plus TEXT for the text forms).
std::vector<Field> callFields(const mtc::core::gne::GneCall& call);
/// Sets parameter `index` of `call` (see setElementField).
bool setCallField(mtc::core::gne::GneCall& call, int index, const std::string& text,
                  ModelText& message);

/// A new call of `keyword` with every required parameter filled with a
/// usable value (geometry number `number`); the operator edits from there.
mtc::core::gne::GneCall newCall(const std::string& keyword, int number);

/// Reads operator text as a number; false when it is not one.
bool parseNumber(const std::string& text, double& value);

}  // namespace mtc::screens::gnefields
