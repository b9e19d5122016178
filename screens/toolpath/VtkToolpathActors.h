#pragma once

// Small helpers of the VTK toolpath view that place and label its actors
// (VtkToolpathCanvas): the axes box, the stock cylinder, the tool marker.
#include <vtkActor.h>
#include <vtkCubeAxesActor.h>

#include <QColor>
#include <QString>

#include <array>
#include <string>
#include <vector>

#include "cnc_core/toolpath/ToolpathGeometry.h"

namespace mtc::screens {

struct ToolpathMarks;

/// The box the axes actor labels.
void setBounds(vtkCubeAxesActor* axes, const mtc::core::ToolpathBounds& b);
/// Tick labels on an axis far shorter than the longest (a plate's
/// thickness) crowd into one blot: such an axis keeps its title and grid,
/// its length is in the caption's extents (TP-014).
void labelLongAxesOnly(vtkCubeAxesActor* axes, const mtc::core::ToolpathBounds& b);
/// Tick labels in the workpiece frame (TP-019): the box stays where the
/// scene (machine) coordinates put it, its ticks read scene - offset (x 2 on
/// a diameter axis, TP-020); the titles name the zero offset ("X (mm, G54)").
void labelInFrame(vtkCubeAxesActor* axes, const mtc::core::ToolpathFrame& frame,
                  const std::array<std::string, 3>& titles);
/// The range the tick labels of axis `axis` (0 X, 1 Y, 2 Z) read, and its title.
std::array<double, 2> axisRange(vtkCubeAxesActor* axes, int axis);
QString axisTitleOf(vtkCubeAxesActor* axes, int axis);
/// "extents 100.0 x 60.0 x 12.0 mm" of a picture (without the third with `flat`).
QString extentsText(const mtc::core::ToolpathBounds& b, bool flat);
/// A cylinder along scene axis `axis` from `from` to `to`.
void placeCylinder(vtkActor* actor, int axis, double radius, double from, double to);
/// The finished part (TP-023) from its triangles (9 floats each, scene mm):
/// an opaque, lit surface in `colour`, flat-shaded so its cells show; with
/// `shadeByHeight` (a milled z-map) darker the lower a corner lies.
void placeFinishedPart(vtkActor* actor, const std::vector<float>& triangles, const QColor& colour,
                       bool shadeByHeight);
/// The tool at the actual position (TP-015): on the mill a cylinder of the
/// edge's radius up the Z axis from the tip, as long as L1 (at least four
/// radii); on the lathe a ball of the nose radius. Never smaller than a
/// hundredth of the picture, so that it stays visible.
void placeTool(vtkActor* actor, const ToolpathMarks& marks, double pictureSize);

}  // namespace mtc::screens
