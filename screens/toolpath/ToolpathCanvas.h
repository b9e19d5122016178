#pragma once

#include <QImage>
#include <QPoint>
#include <QWidget>
#include <algorithm>
#include <cmath>
#include <optional>

#include "screens/toolpath/ToolpathCamera.h"

namespace mtc::screens {

class ToolpathModel;

/// The drawing surface of the toolpath view. Two implementations: the VTK
/// view (VtkToolpathCanvas, needs an OpenGL context) and the 2D QPainter
/// view (PainterToolpathCanvas) for platforms without one. Both show the
/// model's geometry, highlight and marks, both pick with the mouse (a click
/// selects the move under it through ToolpathModel::pick).
class ToolpathCanvas : public QWidget {
    Q_OBJECT
  public:
    explicit ToolpathCanvas(ToolpathModel* model, QWidget* parent = nullptr)
        : QWidget(parent), model_(model) {}

    /// Looks at the path from a preset direction and fits it into the view.
    virtual void showPreset(ToolpathPreset preset) = 0;
    /// Frames the part: the cutting moves and the stock (ToolpathModel::frame).
    virtual void fit() = 0;
    /// Frames every move, the rapids of an approach or tool change too.
    virtual void fitAll() = 0;
    /// Magnifies by `factor` (> 1 closer).
    virtual void zoom(double factor) = 0;
    /// Moves the picture by fractions of the view's width and height.
    virtual void pan(double right, double up) = 0;
    /// Orbits the 3D view (degrees); the developed plane stays flat.
    virtual void rotate(double azimuth, double elevation) = 0;
    /// The picture as it is now (for the PNG export).
    virtual QImage picture() = 0;
    /// True for the 3D (VTK) view.
    virtual bool threeD() const = 0;
    /// Widget position of the middle of move `move`'s first scene segment
    /// (developed segment when the move has no scene segment), if visible.
    virtual std::optional<QPoint> positionOfMove(long move) = 0;
    /// How much wider than at 96 dpi the view draws its lines, in device
    /// pixels (TP-026): the screen's logical dpi / 96 in quarter steps (at
    /// least 1) times the device pixel ratio, so that at 144 dpi - whether Qt
    /// reports 144 dpi or scales by 1.5 - a path is not hair-thin beside text
    /// that grew with the screen.
    double deviceLineScale() const {
        // Quarter steps: Xvfb at -dpi 144 gives a ratio of 1.4985, not 1.5.
        return std::max(1.0, std::round(lineScale() * devicePixelRatioF() * 4.0) / 4.0);
    }
    /// As lineScale for sizes in widget (logical) pixels.
    double lineScale() const { return lineScaleAt(logicalDpiY()); }
    /// The width, in widget pixels, of a pen `width` pixels wide at 96 dpi:
    /// whole device pixels, at least 1 (crisp without antialiasing).
    double penWidth(double width) const {
        return scaledWidth(width, deviceLineScale()) / devicePixelRatioF();
    }
    static double lineScaleAt(int logicalDpi) {
        return std::max(1.0, std::round(logicalDpi / 96.0 * 4.0) / 4.0);
    }
    static double scaledWidth(double width, double scale) {
        return std::max(1.0, std::round(width * scale));
    }

  protected:
    ToolpathModel* model_;
};

}  // namespace mtc::screens
