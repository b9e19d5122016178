#pragma once

#include <QWidget>

#include "hmi/VelocityProfile.h"

namespace mtc::screens {

/// Plot of one look-ahead segment's velocity profile (seed 001 ch. 6,
/// Fig. 6-1): path velocity over the path (blue), each element's velocity
/// cap (red, dashed) and the start of every emitted (sub-)block (grey ticks).
class VelocityPlot : public QWidget {
    Q_OBJECT
  public:
    explicit VelocityPlot(QWidget* parent = nullptr);

    /// Shows `segment` (an empty segment clears the plot).
    void setSegment(const mtc::hmi::SegmentProfile& segment, const QString& caption);
    const mtc::hmi::SegmentProfile& segment() const { return segment_; }
    QSize sizeHint() const override { return {600, 180}; }

  protected:
    void paintEvent(QPaintEvent* event) override;

  private:
    QPointF toScreen(const QRectF& area, double s, double v) const;
    void drawAxes(QPainter& painter, const QRectF& area) const;

    mtc::hmi::SegmentProfile segment_;
    QString caption_;
    double maxV_ = 1.0;
};

}  // namespace mtc::screens
