#pragma once

// The GNE solver: computes the missing data of partly specified contour
// elements along the chain, says which element is under- or
// over-determined, and lists the alternatives where several solutions exist.

#include <string>
#include <vector>

#include "cnc_core/contour/Geometry2D.h"
#include "cnc_core/contour/GneModel.h"

namespace mtc::core::gne {

/// What the solver could make of one element.
enum class ElementState : std::uint8_t {
    Solved,          ///< fully known (drawn solid)
    Undetermined,    ///< too few data, even with the next element (drawn dashed)
    Overdetermined,  ///< the data contradict each other
    Impossible,      ///< no solution (no intersection, rounding does not fit, ...)
    NotReached,      ///< follows an element that could not be solved
};

/// Solver result of one element (same index as Contour::elements).
struct ElementSolution {
    ElementState state = ElementState::NotReached;
    std::string message;              ///< why not solved ("" when solved)
    std::vector<Segment> candidates;  ///< LINE/CW/CCW: every solution; >1 = alternatives
    int chosen = 0;                   ///< index into candidates (the element's ALT)
    std::vector<Segment> segments;    ///< final geometry of this element (transitions applied)
    bool solved() const { return state == ElementState::Solved; }
};

/// Solver result of a contour.
struct ContourSolution {
    std::vector<ElementSolution> elements;
    std::vector<Segment> path;  ///< the whole contour in order; complete only when solved
    std::vector<GneDiagnostic> diagnostics;
    bool complete() const { return diagnostics.empty() && !path.empty(); }
};

/// Solves `contour`. Never throws.
ContourSolution solveContour(const Contour& contour);

/// Name of a state for messages and tests ("solved", "undetermined", ...).
const char* stateName(ElementState state);

/// Diagnostic code of a state that is not solved ("GNE_UNDERDETERMINED", ...).
const char* stateCode(ElementState state);

/// Applies the transitions (RD, CF, RELIEF) to the solved primary segments;
/// `primary[i]` belongs to element `owner[i]`. Fills the transitions'
/// states and every element's final segments. Internal to the solver.
void applyTransitions(const Contour& contour, std::vector<Segment> primary,
                      ContourSolution& solution);

}  // namespace mtc::core::gne
