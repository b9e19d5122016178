#pragma once

// Equidistant of a chain of lines and arcs (tool radius compensation of the
// GNE cycles): convex corners get an arc around the corner, concave corners
// are trimmed to the intersection of the offset elements.

#include <string>
#include <vector>

#include "cnc_core/contour/Geometry2D.h"

namespace mtc::core::gne {

/// Offsets `path` by `distance` to the left (side = +1) or right (-1) of its
/// travel direction. `closed`: the last element joins the first. Returns
/// false with `problem` set when an arc would vanish or a concave corner has
/// no intersection. Self-intersections between distant elements are not
/// removed (documented limitation).
bool offsetPath(const std::vector<Segment>& path, int side, double distance, bool closed,
                std::vector<Segment>& result, std::string& problem);

/// +1 when the closed polygon through `points` runs counter-clockwise.
int orientation(const std::vector<Point>& points);

}  // namespace mtc::core::gne
