#pragma once

#include <QImage>
#include <array>
#include <vector>

#include "screens/toolpath/ToolpathCanvas.h"
#include "screens/toolpath/ToolpathFramePacer.h"
#include "screens/toolpath/ToolpathModel.h"
#include "screens/toolpath/ToolpathTicks.h"

namespace mtc::core {
struct ToolpathLayer;
}

namespace mtc::screens {

/// The toolpath view without OpenGL: an orthographic 2D drawing with
/// QPainter (same presets, zoom, pan, rotation, picking, highlight, marks
/// and part as the VTK view; the path is drawn over the part). Used where no OpenGL context can be
/// made (QT_QPA_PLATFORM=offscreen, no X server), where VTK would abort.
class PainterToolpathCanvas : public ToolpathCanvas {
    Q_OBJECT
  public:
    PainterToolpathCanvas(ToolpathModel* model, QWidget* parent = nullptr);

    void showPreset(ToolpathPreset preset) override;
    void fit() override;
    void fitAll() override;
    void zoom(double factor) override;
    void pan(double right, double up) override;
    void rotate(double azimuth, double elevation) override;
    QImage picture() override;
    bool threeD() const override { return false; }
    std::optional<QPoint> positionOfMove(long move) override;
    /// The text drawn in the top left corner of the scene (developed) area:
    /// what it is, its extents and, in the scene, the zero offset (TP-019).
    QString caption(bool developed) const;
    /// The ticks, labels and titles drawn at the last paint along the
    /// scene's (developed plane's) frame, in workpiece coordinates (TP-025).
    const ToolpathRulers& rulers(bool developed) const { return rulers_[developed ? 1 : 0]; }
    /// Least time between two repaints the model's changes ask for (0: one
    /// per event-loop pass), as the 3D view's (TP-029).
    void setFrameInterval(int milliseconds) { pacer_.setInterval(milliseconds); }
    /// Times the part's image was made (it is kept while nothing changes).
    int partImagesMade() const { return partImagesMade_; }
    /// Where the last framing put the framed box, and what the axis triad
    /// covers, in the scene's (developed plane's) area: apart (TP-031).
    QRectF framedRect(bool developed) const;
    QRectF triadRect(bool developed) const;

  protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

  private:
    using Vec = std::array<double, 3>;
    /// One picture area: the scene (3D, orbiting) or the developed plane (flat).
    struct View {
        CameraPose pose;
        Vec focal{0, 0, 0};
        double scale = 1.0;  ///< pixels per mm
        QPointF centre;      ///< where the focal point is drawn
        QRect rect;
        bool developed = false;
        QSizeF framed{1e-3, 1e-3};  ///< the framed box across and up (mm)
    };
    void layout();
    void fitView(View& view, bool all);
    /// Share of the free area the framed box takes (a margin around it).
    static constexpr double kFitShare = 0.92;
    /// Centres a box of `box` millimetres in `area` at the largest scale
    /// that leaves the margin of kFitShare.
    static void fitInto(View& view, const QRectF& area, const QSizeF& box);
    /// Where a box of `box` millimetres framed by fitInto() is drawn
    /// (without the margin).
    static QRectF framedArea(const View& view, const QSizeF& box);
    /// Frames the part, or with `all` every move, and remembers which.
    void frame(bool all);
    QPointF project(const View& view, const Vec& p) const;
    const mtc::core::ToolpathLayer* layerOf(const View& view) const;
    void drawView(QPainter& painter, const View& view);
    void drawLayer(QPainter& painter, const View& view);
    /// The programmed contour of compensated moves (TC-012), under the path.
    void drawContour(QPainter& painter, const View& view);
    /// What the running program has travelled since Start (TP-016), over the path.
    void drawBackplot(QPainter& painter, const View& view);
    void drawHighlight(QPainter& painter, const View& view);
    void drawMarks(QPainter& painter, const View& view);
    /// The tool at the actual position: a disc of its radius (at least 5
    /// pixels), on the mill with its shank up the Z axis.
    void drawTool(QPainter& painter, const View& view, const ToolpathMarks& marks);
    void drawStock(QPainter& painter, const View& view);
    /// The part (TP-030): the model's mesh filled with a depth buffer into an
    /// image, made again when the part or the view changed.
    void drawPart(QPainter& painter, const View& view);
    void drawTriad(QPainter& painter, const View& view);
    /// Where the axis triad and its names are drawn (top right).
    QRectF triadBox(const View& view) const;
    /// The end of the triad's arm of `axis` (0..2) in `view` from the
    /// triad's middle `origin`, and the arm's name.
    QPointF triadTip(const View& view, QPointF origin, int axis) const;
    static QString triadName(const View& view, int axis);
    /// What the triad covers in `view`: its arms and names, with a margin.
    QRectF triadInk(const View& view) const;
    /// Ticks and titles along the frame (TP-025), clear of the caption's box.
    void drawRulers(QPainter& painter, const View& view, const QRect& caption);
    long pickIn(const View& view, QPointF at) const;

    View scene_;
    View developed_;
    bool split_ = false;
    bool framedAll_ = false;                ///< the last fit was fitAll()
    std::array<ToolpathRulers, 2> rulers_;  ///< scene, developed plane
    ToolpathFramePacer pacer_;              ///< repaints at a bounded rate (TP-029)
    QImage partImage_;                      ///< the part as drawPart made it last
    std::vector<double> partKey_;           ///< the view it was made for
    bool partChanged_ = true;               ///< the model's part changed since
    int partImagesMade_ = 0;
};

}  // namespace mtc::screens
