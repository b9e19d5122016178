#include "screens/afc_trend/AfcTrendPlot.h"

#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>
#include <functional>

namespace mtc::screens {
namespace {

using Sample = mtc::core::AfcTrendSample;
using Value = std::function<double(const Sample&)>;

/// One panel: where it lies and which values it spans.
struct Panel {
    QRectF area;
    double t0 = 0, t1 = 1, v0 = 0, v1 = 100;
    QPointF at(double t, double v) const {
        const double x = area.left() + (t - t0) / std::max(1e-9, t1 - t0) * area.width();
        const double y = area.bottom() - (v - v0) / std::max(1e-9, v1 - v0) * area.height();
        return {x, std::clamp(y, area.top(), area.bottom())};
    }
};

void drawFrame(QPainter& p, const Panel& panel, const QString& unit, int steps) {
    p.setPen(QColor(70, 70, 70));
    p.drawRect(panel.area);
    p.setPen(QColor(200, 200, 200));
    for (int i = 1; i < steps; ++i) {
        const double v = panel.v0 + (panel.v1 - panel.v0) * i / steps;
        p.drawLine(panel.at(panel.t0, v), panel.at(panel.t1, v));
    }
    p.setPen(Qt::black);
    for (int i = 0; i <= steps; ++i) {
        const double v = panel.v0 + (panel.v1 - panel.v0) * i / steps;
        const QPointF point = panel.at(panel.t0, v);
        p.drawText(QRectF(0, point.y() - 8, panel.area.left() - 4, 16),
                   Qt::AlignRight | Qt::AlignVCenter, QString::number(v, 'f', 0));
    }
    p.setPen(QColor(90, 90, 90));
    p.drawText(QRectF(panel.area.left() + 6, panel.area.top() + 2, 160, 16), Qt::AlignLeft, unit);
}

void drawCurve(QPainter& p, const Panel& panel, const std::vector<Sample>& samples,
               const Value& value, const QPen& pen) {
    if (samples.empty()) return;
    QPainterPath path(panel.at(samples.front().time, value(samples.front())));
    for (const Sample& s : samples)
        path.lineTo(panel.at(s.time, value(s)));
    p.setPen(pen);
    p.drawPath(path);
}

void drawLegend(QPainter& p, QPointF origin, const std::vector<std::pair<QString, QPen>>& items) {
    double x = origin.x();
    for (const auto& [text, pen] : items) {
        p.setPen(pen);
        p.drawLine(QPointF(x, origin.y()), QPointF(x + 22, origin.y()));
        p.setPen(Qt::black);
        p.drawText(QPointF(x + 26, origin.y() + 4), text);
        x += 36 + p.fontMetrics().horizontalAdvance(text);
    }
}

QPen pen(QColor color, double width, Qt::PenStyle style = Qt::SolidLine) {
    QPen result(color, width, style);
    result.setCosmetic(true);
    return result;
}

double torqueTop(const std::vector<Sample>& samples) {
    double top = 60.0;
    for (const Sample& s : samples)
        top = std::max({top, s.torqueActual, s.machiningTorque, s.limitingTorque});
    return std::ceil(top * 1.1 / 20.0) * 20.0;
}

}  // namespace

AfcTrendPlot::AfcTrendPlot(QWidget* parent) : QWidget(parent) {
    setObjectName("afcTrendPlot");
    setMinimumSize(400, 260);
}

void AfcTrendPlot::setSamples(std::vector<mtc::core::AfcTrendSample> samples) {
    samples_ = std::move(samples);
    update();
}

void AfcTrendPlot::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(rect(), Qt::white);
    const double left = 48, right = width() - 12.0, gap = 40;
    const double usable = height() - 30.0 - 2 * gap;
    Panel torque{{left, gap, right - left, usable * 0.62}};
    Panel feed{{left, gap * 2 + usable * 0.62, right - left, usable * 0.38}};
    if (!samples_.empty()) {
        torque.t0 = feed.t0 = samples_.front().time;
        torque.t1 = feed.t1 = std::max(samples_.back().time, torque.t0 + 1e-3);
    }
    torque.v1 = torqueTop(samples_);
    drawFrame(p, torque, "torque %", 5);
    drawFrame(p, feed, "feed red. %", 4);
    p.drawText(QRectF(left, height() - 22.0, right - left, 18), Qt::AlignCenter,
               samples_.empty() ? QString("no samples yet: run a program with G26 / ITM")
                                : QString("simulated time %1 s ... %2 s")
                                      .arg(torque.t0, 0, 'f', 2)
                                      .arg(torque.t1, 0, 'f', 2));
    const QPen actual = pen(QColor(30, 90, 200), 1.2), machining = pen(QColor(0, 150, 60), 1.6);
    const QPen limit = pen(Qt::red, 1.2, Qt::DashLine),
               minimum = pen(QColor(200, 120, 0), 1.2, Qt::DashLine);
    const QPen idle = pen(Qt::darkGray, 1.2, Qt::DashLine),
               reduction = pen(QColor(140, 0, 160), 1.6);
    const QPen peak = pen(QColor(140, 0, 160), 1.0, Qt::DotLine),
               maximum = pen(Qt::red, 1.2, Qt::DashLine);
    drawCurve(
        p, torque, samples_, [](const Sample& s) { return s.limitingTorque; }, limit);
    drawCurve(
        p, torque, samples_, [](const Sample& s) { return s.minimumTorque; }, minimum);
    drawCurve(
        p, torque, samples_, [](const Sample& s) { return s.idleTorque; }, idle);
    drawCurve(
        p, torque, samples_, [](const Sample& s) { return s.torqueActual; }, actual);
    drawCurve(
        p, torque, samples_, [](const Sample& s) { return s.machiningTorque; }, machining);
    drawCurve(
        p, feed, samples_, [](const Sample& s) { return s.maximumReduction; }, maximum);
    drawCurve(
        p, feed, samples_, [](const Sample& s) { return s.peakReduction; }, peak);
    drawCurve(
        p, feed, samples_, [](const Sample& s) { return s.feedReduction; }, reduction);
    drawLegend(p, {left, 14},
               {{"actual S-0-0084", actual},
                {"machining 007", machining},
                {"limiting 010", limit},
                {"minimum 009", minimum},
                {"idling 005", idle}});
    drawLegend(p, {left, feed.area.top() - 14},
               {{"feed reduction 011", reduction}, {"peak 012", peak}, {"maximum 013", maximum}});
}

}  // namespace mtc::screens
