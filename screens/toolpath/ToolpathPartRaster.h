#pragma once

#include <QColor>
#include <QImage>
#include <QSize>
#include <array>
#include <vector>

namespace mtc::screens {

/// An orthographic projection onto an image (device pixels): where the
/// 2D view puts a scene point (PainterToolpathCanvas::project) and which
/// way the viewer looks.
struct PartProjection {
    std::array<double, 3> right{1, 0, 0};   ///< screen right (unit)
    std::array<double, 3> up{0, 1, 0};      ///< screen up (unit)
    std::array<double, 3> toward{0, 0, 1};  ///< from the scene to the viewer (unit)
    std::array<double, 3> focal{0, 0, 0};   ///< drawn at (centreX, centreY)
    double scale = 1.0;                     ///< device pixels per mm
    double centreX = 0.0, centreY = 0.0;    ///< device pixels
};

/// The part of the 2D view (TP-030): `triangles` (9 floats per triangle,
/// the 3D view's mesh of ToolpathPart) filled into a transparent image of
/// `size` device pixels with a depth buffer, so in every view the nearest
/// surface shows, flat-shaded as the 3D view lights it (ambient 0.35,
/// diffuse 0.65 from the viewer, both sides lit); with `shadeByHeight` (a
/// milled z-map) darker the lower it lies, as the 3D view colours it.
QImage rasterizePart(const std::vector<float>& triangles, const QColor& colour, bool shadeByHeight,
                     const PartProjection& view, QSize size);

}  // namespace mtc::screens
