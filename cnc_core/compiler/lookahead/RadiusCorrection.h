#pragma once

#include <vector>

#include "cnc_core/compiler/lookahead/PathElement.h"
#include "cnc_core/compiler/lookahead/VelocityPlanner.h"

namespace mtc::core::lookahead {

/// TRC of the enhanced look-ahead function (seed 001 ch. 6): tool radius
/// correction of the polygon in the active plane.
struct RadiusCorrectionSettings {
    double radius = 0.0;    ///< tool radius (TL_RADIUS), mm, > 0
    int side = 1;           ///< TRC: 1 = left of the contour, 2 = right
    double approach = 0.0;  ///< ADTRC: approach / retract line length, mm (0 = none)
    int blockBuffer = 3;    ///< BBTRC: elements checked ahead for a bottleneck (1..10)
    int planeFirst = 0;     ///< axis index of the plane's first axis
    int planeSecond = 1;    ///< axis index of the plane's second axis
};

/// The corrected polygon (elements with `generated` > 0 were inserted:
/// 1 = corner arc, 2 = lead-in from the programmed start, 3 = approach line,
/// 4 = retract line, 5 = lead-out back to the programmed end point) or the
/// problems that prevent it.
struct CorrectedPolygon {
    std::vector<PathElement> elements;
    std::vector<PlanProblem> problems;  ///< element = index in the input contour
    bool ok() const { return problems.empty(); }
};

/// Kinds of generated elements (PathElement::generated).
enum GeneratedElement : int {
    kCornerArc = 1,
    kLeadIn = 2,
    kApproachLine = 3,
    kRetractLine = 4,
    kLeadOut = 5,
};

/// Offsets `contour` by the tool radius to the side TRC names: lines move
/// parallel, arcs change their radius; an outside corner gets an arc around
/// the programmed corner point, an inside corner trims both elements to
/// their intersection. The tool enters from the programmed start point
/// (lead-in to the approach line's start) and, after the retract line,
/// returns to the programmed end point, so the position after LA_OFF is the
/// programmed one. Off-plane axes keep their programmed motion.
CorrectedPolygon correctToolRadius(const std::vector<PathElement>& contour,
                                   const RadiusCorrectionSettings& settings);

}  // namespace mtc::core::lookahead
