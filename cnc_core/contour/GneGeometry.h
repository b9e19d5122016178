#pragma once

// The geometry behind a geometry number: a solved CONT or a FORM_xx, as
// paths of lines and arcs (what the cycles machine and the screen draws).

#include <string>
#include <vector>

#include "cnc_core/contour/Geometry2D.h"
#include "cnc_core/contour/GneModel.h"

namespace mtc::core::gne {

/// One or more paths in one plane. Text forms are several open strokes.
struct Geometry {
    int number = 0;
    GnePlane plane = GnePlane::Turning;
    std::vector<std::vector<Segment>> paths;
    bool closed = false;   ///< every path ends where it starts
    bool strokes = false;  ///< engraving strokes (text): machined on the path only
    std::uint32_t line = 0;
};

/// The geometry of a FORM_xx call (parameters already checked by the
/// reader). False with `problem` when the values do not make a shape
/// (e.g. a slot narrower than its radius, a corner radius too large).
bool formGeometry(const GneCall& call, Geometry& geometry, std::string& problem);

/// Rounded rectangle, counter-clockwise, centre `c`, half sizes, angle in degrees.
std::vector<Segment> roundedRectangle(const Point& c, double halfLength, double halfWidth,
                                      double degrees, double cornerRadius);

}  // namespace mtc::core::gne
