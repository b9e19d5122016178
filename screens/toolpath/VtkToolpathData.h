#pragma once

// VTK side of the toolpath view: included by the VTK translation units and
// the toolpath benchmark only (VTK headers are heavy; keep them out of the rest).
#include <vtkSmartPointer.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "cnc_core/toolpath/ToolpathDecimation.h"
#include "cnc_core/toolpath/ToolpathGeometry.h"

// VTK objects are reference-counted and end with Delete(), hence their
// protected virtual destructors.
class vtkPolyData;  // NOLINT(cppcoreguidelines-virtual-class-destructor)

namespace mtc::screens {

struct ToolpathPalette;

/// ONE vtkPolyData for a layer of the geometry (`developed` picks the
/// developed plane, else the scene): one line cell per segment (32-bit
/// connectivity) and RGB *point* colours by motion type ("colours"). A
/// vertex is stored twice where the colour changes along a chain, so no
/// cell blends two colours; cell colours would make VTK 9.1 look each
/// fragment's colour up in a texture buffer by gl_PrimitiveID, which is
/// slow on Mesa llvmpipe (docs/decisions/toolpath.md, TP-010). With
/// `dropRepeats`, a segment equal to one drawn before (same end points in
/// either direction, same kind) gets no cell (TP-022): then cells are not
/// segments by index (picking measures the geometry, not cells).
vtkSmartPointer<vtkPolyData> toolpathPolyData(const mtc::core::ToolpathGeometry& geometry,
                                              bool developed, const ToolpathPalette& palette,
                                              bool dropRepeats = true);

/// The coarse copy drawn while the view moves: one line cell per cell of
/// `coarse` (cell i = coarse cell i, see DecimatedLayer::segmentsOf), point
/// colours by the cell's kind.
vtkSmartPointer<vtkPolyData> toolpathLevelOfDetail(const mtc::core::ToolpathGeometry& geometry,
                                                   bool developed, const ToolpathPalette& palette,
                                                   const mtc::core::DecimatedLayer& coarse);

/// The segments of moves `moves` (highlight), without colours, with their
/// own points (only the vertices these segments use).
vtkSmartPointer<vtkPolyData> toolpathMoves(const mtc::core::ToolpathGeometry& geometry,
                                           bool developed, const std::vector<std::uint32_t>& moves);

/// Segments [from, to) of `layer`, without colours, and when `partial` is
/// given, one more line from partial[0] to partial[1] (the backplot's piece
/// of the segment the axes are on, TP-016).
vtkSmartPointer<vtkPolyData> toolpathStretch(const mtc::core::ToolpathLayer& layer,
                                             std::uint32_t from, std::uint32_t to,
                                             const std::array<std::array<double, 3>, 2>* partial);

/// The programmed contour of the compensated moves (the `contour` or
/// `developedContour` layer, compensation.md TC-012), without colours: the
/// view draws it in one colour beside the tool-centre path.
vtkSmartPointer<vtkPolyData> toolpathContour(const mtc::core::ToolpathGeometry& geometry,
                                             bool developed);

}  // namespace mtc::screens
