#pragma once

// VTK side of the toolpath view: included by the VTK translation units and
// the toolpath benchmark only (VTK headers are heavy; keep them out of the rest).
#include <vtkSmartPointer.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "cnc_core/toolpath/ToolpathGeometry.h"

class vtkPoints;
class vtkPolyData;

namespace mtc::screens {

struct ToolpathPalette;

/// ONE vtkPolyData for a layer of the geometry (`developed` picks the
/// developed plane, else the scene): the vertices (float, copied once), one
/// line cell per segment (32-bit connectivity, cell i = segment i, so a
/// picked cell id is a segment index) and RGB cell colours by motion type
/// (cell scalars "colours").
vtkSmartPointer<vtkPolyData> toolpathPolyData(const mtc::core::ToolpathGeometry& geometry,
                                              bool developed, const ToolpathPalette& palette);

/// A coarser copy for moving the view (level of detail): runs of segments
/// along a chain are joined into one line of at most `maxSegments` in all,
/// coloured by the first move's type. The full copy is returned when it has
/// no more than `maxSegments`. `points` (the full poly-data's points) is
/// shared when given, instead of copying the vertices again.
vtkSmartPointer<vtkPolyData> toolpathLevelOfDetail(const mtc::core::ToolpathGeometry& geometry,
                                                   bool developed, const ToolpathPalette& palette,
                                                   std::size_t maxSegments,
                                                   vtkPoints* points = nullptr);

/// The segments of moves `moves` (highlight), without colours; shares `points`.
vtkSmartPointer<vtkPolyData> toolpathMoves(const mtc::core::ToolpathGeometry& geometry,
                                           bool developed, const std::vector<std::uint32_t>& moves,
                                           vtkPoints* points = nullptr);

}  // namespace mtc::screens
