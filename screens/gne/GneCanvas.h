#pragma once

#include <QRectF>
#include <QWidget>

namespace mtc::screens {

class GneEditModel;

/// The GNE screen's live 2D drawing (QPainter): the blank of the window,
/// every contour of the section with solved elements solid and
/// undetermined ones dashed, the alternatives of the selected element
/// (chosen one highlighted, the others dotted), forms, the tool paths of
/// the section's cycles (thin; rapid moves dotted), and the other
/// geometry of the program in grey. 1st plane axis to the right, 2nd up.
class GneCanvas : public QWidget {
    Q_OBJECT
  public:
    explicit GneCanvas(const GneEditModel* model, QWidget* parent = nullptr);

    /// Zoom to the window (blank) when true, to the contours when false.
    void setZoomToWindow(bool window);
    bool zoomToWindow() const { return zoomToWindow_; }
    /// Zoom in (factor > 1) or out about the middle of the view.
    void zoomBy(double factor);
    /// The world rectangle shown (plane coordinates).
    QRectF worldView() const;

  protected:
    void paintEvent(QPaintEvent* event) override;

  private:
    QRectF contentExtent() const;
    void drawWindow(class QPainter& painter) const;
    void drawContours(class QPainter& painter) const;
    void drawCycles(class QPainter& painter) const;
    void drawOtherGeometry(class QPainter& painter) const;
    void drawLegend(class QPainter& painter) const;
    QPointF toScreen(double x, double y) const;

    const GneEditModel* model_;
    bool zoomToWindow_ = true;
    double zoom_ = 1.0;
    mutable QRectF view_;
    mutable double scale_ = 1.0;
    mutable QPointF offset_;
};

}  // namespace mtc::screens
