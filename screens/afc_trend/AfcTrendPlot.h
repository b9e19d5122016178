#pragma once

#include <QWidget>
#include <vector>

#include "cnc_core/afc/AfcTrendRecorder.h"

namespace mtc::screens {

/// The adaptive feed trend as a chart (seed 002 Fig. 2-1), painted with
/// QPainter: upper panel torques over time (actual value S-0-0084, machining
/// torque 007, dashed limiting 010 / minimum 009 / idling 005 lines), lower
/// panel feed reduction 011, its peak and the maximum feed reduction 013.
class AfcTrendPlot : public QWidget {
    Q_OBJECT
  public:
    explicit AfcTrendPlot(QWidget* parent = nullptr);
    /// The samples to draw, oldest first (copied; the widget repaints).
    void setSamples(std::vector<mtc::core::AfcTrendSample> samples);
    const std::vector<mtc::core::AfcTrendSample>& samples() const { return samples_; }
    QSize sizeHint() const override { return {900, 520}; }

  protected:
    void paintEvent(QPaintEvent* event) override;

  private:
    std::vector<mtc::core::AfcTrendSample> samples_;
};

}  // namespace mtc::screens
