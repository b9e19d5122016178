#include "screens/runtime/VelocityPlot.h"

#include <QPainter>
#include <QPainterPath>

namespace mtc::screens {

VelocityPlot::VelocityPlot(QWidget* parent) : QWidget(parent) {
    setMinimumHeight(150);
}

void VelocityPlot::setSegment(const mtc::hmi::SegmentProfile& segment, const QString& caption) {
    segment_ = segment;
    caption_ = caption;
    maxV_ = 1.0;
    for (const auto& p : segment_.caps)
        maxV_ = std::max(maxV_, p.v);
    for (const auto& p : segment_.curve)
        maxV_ = std::max(maxV_, p.v);
    update();
}

QPointF VelocityPlot::toScreen(const QRectF& area, double s, double v) const {
    const double length = segment_.length > 0 ? segment_.length : 1.0;
    return {area.left() + area.width() * s / length,
            area.bottom() - area.height() * v / (maxV_ * 1.05)};
}

void VelocityPlot::drawAxes(QPainter& painter, const QRectF& area) const {
    painter.setPen(QColor(60, 60, 60));
    painter.drawLine(area.bottomLeft(), area.bottomRight());
    painter.drawLine(area.bottomLeft(), area.topLeft());
    painter.drawText(QRectF(area.left() + 4, area.top() - 16, area.width(), 16),
                     QString("F [mm/min]  max %1").arg(maxV_, 0, 'f', 0));
    painter.drawText(
        QRectF(area.right() - 200, area.bottom() + 2, 200, 16), Qt::AlignRight,
        tr("path %1 mm, %2 s").arg(segment_.length, 0, 'f', 1).arg(segment_.time, 0, 'f', 3));
}

void VelocityPlot::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.fillRect(rect(), Qt::white);
    const int line = painter.fontMetrics().height();
    const QRectF area = QRectF(rect()).adjusted(40, line + 4, -10, -line - 2);
    if (segment_.curve.empty()) {
        painter.setPen(QColor(90, 90, 90));
        painter.drawText(rect(), Qt::AlignCenter, caption_);
        return;
    }
    painter.drawText(QRectF(area.left(), 2, area.width(), line), Qt::AlignRight, caption_);
    painter.setPen(QPen(QColor(190, 190, 190), 1));
    for (double s : segment_.blockStarts)
        painter.drawLine(toScreen(area, s, 0), toScreen(area, s, 0) - QPointF(0, 6));
    painter.setPen(QPen(QColor(200, 40, 40), 1, Qt::DashLine));
    for (size_t i = 0; i + 1 < segment_.caps.size(); i += 2)
        painter.drawLine(toScreen(area, segment_.caps[i].s, segment_.caps[i].v),
                         toScreen(area, segment_.caps[i + 1].s, segment_.caps[i + 1].v));
    QPainterPath curve(toScreen(area, segment_.curve.front().s, segment_.curve.front().v));
    for (const auto& p : segment_.curve)
        curve.lineTo(toScreen(area, p.s, p.v));
    painter.setPen(QPen(QColor(20, 70, 180), 2));
    painter.drawPath(curve);
    drawAxes(painter, area);
}

}  // namespace mtc::screens
