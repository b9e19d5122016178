#pragma once

#include "cnc_core/compiler/lookahead/PathElement.h"

namespace mtc::core::lookahead {

/// Derived geometry of one element, computed once.
struct ElementGeometry {
    double length = 0.0;       ///< path length over all axes, mm
    double radiusStart = 0.0;  ///< arcs: plane radius at the start
    double radiusEnd = 0.0;    ///< arcs: plane radius at the end
    double angleStart = 0.0;   ///< arcs: polar angle of the start point around the centre
    double sweep = 0.0;        ///< arcs: signed angle, > 0 counter-clockwise (G3)
    double curvature = 0.0;    ///< 1/mm; 0 for lines
    AxisVector maxAbsTangent;  ///< per axis: largest |unit tangent component| on the element
    AxisVector maxAbsNormal;   ///< per axis: largest |principal normal component| (arcs)
};

/// Length, sweep, curvature and per-axis extremes of `element`.
/// A full circle is an arc whose start equals its end (sweep 2*pi).
ElementGeometry describeElement(const PathElement& element);

/// Point at path distance `s` (0 .. length) from the start of `element`.
AxisVector pointAt(const PathElement& element, const ElementGeometry& geometry, double s);

/// Unit tangent at path distance `s`.
AxisVector tangentAt(const PathElement& element, const ElementGeometry& geometry, double s);

/// Unit principal normal at path distance `s` (zero vector for lines).
AxisVector normalAt(const PathElement& element, const ElementGeometry& geometry, double s);

}  // namespace mtc::core::lookahead
