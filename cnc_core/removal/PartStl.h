#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cnc_core/removal/PartModel.h"

namespace mtc::core::removal {

/// Triangles of the closed surface partStl() writes for `part`.
std::uint64_t stlTriangleCount(const PartModel& part);

/// The finished part as a binary STL (little-endian, mm): a closed surface.
/// Height field: the top through the cell centres (its border on the
/// block's faces), four side walls down to the bottom and the bottom face.
/// Turned part: the profile revolved with angularSegments() facets, closed
/// by the two end faces; after G32 cuts one facet per jacket column, each
/// vertex at the material's radius of its cell (D-027). Through-cuts leave
/// top and bottom touching.
std::string partStl(const PartModel& part);

/// The same surface as partStl(), for a view: 9 floats per triangle (its
/// three corners x, y, z in scene mm, counter-clockwise seen from outside).
/// Runs of facets in one plane are merged into one quad (TP-029): along a
/// row of the height field the flat quads of one height, along the axis of
/// a turned part the facets of one radius. A milled plate's floors and top
/// then take a few thousand triangles instead of two per cell, which is
/// what a view pays for in building, uploading and drawing the mesh each
/// time the live part changes. Each run is triangulated through the
/// vertices its neighbours have on its edges: closed edge to edge, no
/// T-junction for a rasteriser to crack open.
std::vector<float> partTriangles(const PartModel& part);

/// Writes partStl() to `path` atomically (writeFileAtomically: only over a
/// regular file, the old file stays when anything fails). False with `error`.
bool writePartStl(const PartModel& part, const std::string& path, std::string& error);

}  // namespace mtc::core::removal
