#pragma once

// The VTK toolpath view's renderers, actors and what they show
// (VtkToolpathCanvas's private state), shared by its source files.
#include <vtkActor.h>
#include <vtkAxesActor.h>
#include <vtkCallbackCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkNew.h>
#include <vtkOrientationMarkerWidget.h>

#include <QPoint>
#include <QString>
#include <QTimer>
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "cnc_core/toolpath/ToolpathGeometry.h"
#include "screens/toolpath/ToolpathCamera.h"
#include "screens/toolpath/ToolpathModel.h"
#include "screens/toolpath/VtkToolpathCache.h"
#include "screens/toolpath/VtkToolpathCanvas.h"
#include "screens/toolpath/VtkToolpathPart.h"

namespace mtc::screens {

struct VtkToolpathCanvas::Scene {
    vtkNew<vtkGenericOpenGLRenderWindow> window;
    Part scene, developed;
    vtkNew<vtkActor> stock, cylinder, start, target, reentry, repos, tool;
    vtkNew<vtkActor> collision;  ///< where the way back first meets the part (D-021)
    vtkNew<vtkActor> part;       ///< the finished part (TP-023)
    vtkNew<vtkAxesActor> triadAxes;
    vtkNew<vtkOrientationMarkerWidget> triad;
    vtkNew<vtkCallbackCommand> interaction;
    ToolpathPreset preset = ToolpathPreset::Isometric;
    bool split = false, coarse = false;
    int renders = 0, coarsePicks = 0;
    /// A frame (of everything: true) made before the view had its size and
    /// scale: made again at the first render on screen (the caption's room).
    std::optional<bool> refitWhenShown;
    QTimer still;
    QPoint pressed;
    std::unique_ptr<VtkStillCache> stillCache;  ///< the steady picture kept as an image (TP-018)
    ToolpathMarks shownMarks;                   ///< the marks the steady picture shows
    std::vector<std::uint32_t> shownHighlight;  ///< the moves the highlight shows
    std::array<double, 4> toolShape{};          ///< has tool, turning, radius, length shown
    double toolPictureSize = 0.0;               ///< picture size the tool was made for
    std::array<double, 3> toolAt{};             ///< where the tool is drawn
    mtc::core::ToolpathFrame shownFrame;        ///< the frame the scene's labels are in
    QString sceneCaption;                       ///< the scene caption without the frame line
    /// Per area (scene, developed): backplot shown (0/1), its run and revision.
    std::array<std::array<std::uint64_t, 3>, 2> shownBackplot{};
};

}  // namespace mtc::screens
