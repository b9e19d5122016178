#pragma once

#include <QColor>
#include <QStringList>
#include <QWidget>
#include <utility>
#include <vector>

#include "cnc_core/afc/AfcTrendRecorder.h"

namespace mtc::screens {

/// The adaptive feed trend as a chart (seed 002 Fig. 2-1 and 6-1), painted
/// with QPainter: upper panel torques over time (actual value S-0-0084,
/// machining torque 007, dashed limiting 010 / minimum 009 / idling 005 /
/// maximum idling 006 lines, stall torque 014), the measuring periods of ITM
/// shaded; middle panel feed reduction 011, its peak and the maximum feed
/// reduction 013; lower strip the signals PxxS.EXCTH and PxxS.THMIS.
class AfcTrendPlot : public QWidget {
    Q_OBJECT
  public:
    explicit AfcTrendPlot(QWidget* parent = nullptr);
    /// The samples to draw, oldest first (copied; the widget repaints).
    void setSamples(std::vector<mtc::core::AfcTrendSample> samples);
    const std::vector<mtc::core::AfcTrendSample>& samples() const { return samples_; }
    QSize sizeHint() const override { return {900, 560}; }

    /// The names of the legend, in drawing order ("actual S-0-0084", ...).
    static QStringList legend();
    /// Measuring periods of ITM among the samples: [first, last] sample time.
    std::vector<std::pair<double, double>> itmPhases() const;
    /// Colour of the ITM shading (tests find it in the painted image).
    static QColor itmColor() { return {255, 236, 160}; }
    /// Widget x of simulated time `t` in the painted chart.
    double xOf(double t) const;

  protected:
    void paintEvent(QPaintEvent* event) override;

  private:
    std::vector<mtc::core::AfcTrendSample> samples_;
};

}  // namespace mtc::screens
