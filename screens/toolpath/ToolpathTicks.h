#pragma once

// Tick labels of the 2D toolpath view (TP-025): along the part's frame, in
// workpiece coordinates, spaced to the zoom so that labels never run into
// each other. Plain geometry on QPainter types, no VTK.

#include <QFontMetricsF>
#include <QMarginsF>
#include <QPointF>
#include <QRectF>
#include <QString>
#include <array>
#include <functional>
#include <vector>

#include "cnc_core/toolpath/ToolpathGeometry.h"

namespace mtc::screens {

/// The values of a ruler: multiples of a 1-2-5 step over [from, to].
struct TickValues {
    double step = 0.0;
    int decimals = 0;  ///< digits after the point the step needs
    std::vector<double> values;
};

/// The smallest 1-2-5 step (1, 2, 5 x 10^k) of at least `minimumStep`, its
/// decimals, and its multiples in [from, to] (from <= to).
TickValues tickValues(double from, double to, double minimumStep);
/// `value` with `decimals` digits after the point ("-0" written "0").
QString tickText(double value, int decimals);

/// One label the view draws: on scene axis `axis`, the workpiece `value`,
/// its text, the tick's end on the frame and the text's box (widget pixels).
struct ToolpathTick {
    int axis = 0;
    double value = 0.0;
    QString text;
    QPointF at;
    QRectF box;
};

/// A title of an axis ("X (mm, G54)") and its box; `upright` text reads
/// upwards (beside a ruler that runs up the picture).
struct ToolpathAxisTitle {
    int axis = 0;
    QString text;
    QRectF box;
    bool upright = false;
};

/// Room a picture keeps free for its rulers: left (labels and title of a
/// ruler running up) and bottom (labels and title of one running across).
QMarginsF rulerMargins(const QFontMetricsF& metrics, double tickLength);

/// What the 2D view draws along the frame of one picture.
struct ToolpathRulers {
    std::vector<std::array<QPointF, 2>> lines;  ///< the frame edges that carry ticks
    std::vector<std::array<QPointF, 2>> marks;  ///< the tick marks
    std::vector<ToolpathTick> ticks;
    std::vector<ToolpathAxisTitle> titles;
};

/// Lays out the rulers of a picture: `project` maps a scene point to widget
/// pixels (orthographic, linear), `box` is the part's frame
/// (scene mm), `frame` the workpiece frame the labels read, `titles` the
/// three axis titles, `area` the picture and `taken` boxes labels must keep
/// clear of (caption, triad). An axis seen end-on gets no ruler; each other
/// axis one edge of the box, the lowest (an axis running across) or the
/// leftmost (an axis running up), moved into the picture when it is out of
/// it. `tickLength` is the tick marks' length (pixels). The step is the smallest 1-2-5 step whose
/// labels do not touch; a label that would overlap another or leave the picture is left out.
ToolpathRulers layoutRulers(const std::function<QPointF(const std::array<double, 3>&)>& project,
                            const mtc::core::ToolpathBounds& box,
                            const mtc::core::ToolpathFrame& frame,
                            const std::array<QString, 3>& titles, const QFontMetricsF& metrics,
                            double tickLength, const QRectF& area, std::vector<QRectF> taken);

}  // namespace mtc::screens
