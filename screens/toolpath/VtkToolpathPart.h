#pragma once

// One picture area of the VTK toolpath view (VtkToolpathCanvas): the scene
// (3D) or the developed plane (2D), with its renderer and actors.
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCubeAxesActor.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <QColor>
#include <memory>
#include <string>

#include "cnc_core/toolpath/ToolpathDecimation.h"
#include "screens/toolpath/ToolpathCamera.h"
#include "screens/toolpath/ToolpathCanvas.h"
#include "screens/toolpath/ToolpathPalette.h"
#include "screens/toolpath/VtkToolpathBackplot.h"

namespace mtc::screens {

/// The direction `camera` looks along and its screen up, as a pose (its
/// right() is the screen's right).
CameraPose poseOf(vtkCamera& camera);

/// Line widths in pixels at 96 dpi (TP-026 scales them with the screen):
/// the path 1, because wider lines cost llvmpipe frame time (TP-010); the
/// contour told apart by its colour (legend under the view).
inline constexpr double kPathWidth = 1.0;
inline constexpr double kContourWidth = 1.0;
inline constexpr double kHighlightWidth = 6.0;

inline void setColour(vtkProperty* property, const QColor& colour) {
    property->SetColor(colour.redF(), colour.greenF(), colour.blueF());
}

inline void setColour(vtkTextProperty* property, const QColor& colour) {
    property->SetColor(colour.redF(), colour.greenF(), colour.blueF());
}

/// One picture area: the scene (3D) or the developed plane (2D).
struct Part {
    bool developed = false;
    vtkNew<vtkRenderer> renderer;  ///< the steady picture (VtkStillCache)
    /// What follows the station (the highlight, the backplot's open piece;
    /// the scene's also the tool), over the steady picture.
    vtkNew<vtkRenderer> live;
    vtkNew<vtkPolyDataMapper> mapper, coarseMapper;
    vtkNew<vtkActor> path, coarsePath;  ///< full detail; coarse copy while moving
    vtkSmartPointer<vtkPolyData> full, coarse;
    mtc::core::DecimatedLayer decimated;  ///< what the coarse cells stand for
    vtkNew<vtkPolyDataMapper> highlightMapper;
    vtkNew<vtkActor> highlight;
    /// The programmed contour where compensation moves the tool off it
    /// (TC-012): thin, one colour, under the tool-centre path.
    vtkNew<vtkPolyDataMapper> contourMapper;
    vtkNew<vtkActor> contour;
    vtkNew<vtkCubeAxesActor> axes;
    vtkNew<vtkTextActor> caption;
    /// What the running program has travelled since Start (TP-016).
    std::unique_ptr<VtkBackplot> backplot;

    /// Colours and the actors in drawing order (the backplot last).
    void setUp(const ToolpathPalette& palette);
    /// Line widths and text sizes: the 96-dpi sizes times `scale` (device
    /// pixels per 96-dpi pixel, TP-026), widths in whole pixels.
    void setScreenScale(double scale);
    /// The caption's font size and margin, the axes' text size and its
    /// distance to the ticks at 96 dpi (pixels).
    static constexpr double kCaptionSize = 14.0;
    static constexpr double kCaptionMargin = 8.0;
    static constexpr double kAxesTextSize = 10.0;
    static constexpr double kAxesTextOffset = 20.0;
    /// The screen scale set last (setScreenScale).
    double screenScale = 1.0;
    /// Caption text, area width and scale fitCaptionToWidth() last sized it
    /// for (compared each render, rebuilt only when one of them changed).
    struct CaptionFit {
        std::string text;
        int width = -1;
        double scale = 0.0;
    } captionFittedFor;
    /// The caption at its size for the screen, smaller where it would be
    /// wider than its picture area (the halves beside a developed plane).
    /// True when its size changed.
    bool fitCaptionToWidth();
    /// Frames `box` (empty: everything shown), clear of the caption: the
    /// box and the labels hanging below it stay above the caption's lines.
    void frame(const mtc::core::ToolpathBounds& box);
    /// Moves and zooms the camera out so that `box`, with room for its tick
    /// labels and title below it, sits above the caption (parallel views).
    void keepClearOfCaption(const mtc::core::ToolpathBounds& box);
    /// The depth range of the camera: the steady and live props (the tool
    /// lives in the live renderer), with half their size to spare so that
    /// the tool stays inside it as it moves.
    void fitClippingRange();
};

}  // namespace mtc::screens
