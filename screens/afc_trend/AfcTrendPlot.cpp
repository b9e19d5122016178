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

constexpr double kLeft = 60, kRight = 12, kGap = 40, kBottom = 30, kStrip = 44;

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

/// The three panels of a widget of `size` showing `samples`.
struct Layout {
    Panel torque, feed, strip;
};

Layout layoutFor(const QSize& size, const std::vector<Sample>& samples) {
    const double width = size.width() - kLeft - kRight;
    const double usable = size.height() - kBottom - 3 * kGap - kStrip;
    Layout l;
    l.torque.area = {kLeft, kGap, width, usable * 0.62};
    l.feed.area = {kLeft, kGap * 2 + usable * 0.62, width, usable * 0.38};
    l.strip.area = {kLeft, kGap * 3 + usable, width, kStrip};
    l.strip.v0 = -0.25;
    l.strip.v1 = 2.0;
    if (!samples.empty()) {
        for (Panel* p : {&l.torque, &l.feed, &l.strip}) {
            p->t0 = samples.front().time;
            p->t1 = std::max(samples.back().time, p->t0 + 1e-3);
        }
    }
    double top = 60.0;
    for (const Sample& s : samples)
        top = std::max({top, s.torqueActual, s.machiningTorque, s.limitingTorque,
                        s.maximumIdleTorque, s.stallTorque});
    l.torque.v1 = std::ceil(top * 1.1 / 20.0) * 20.0;
    return l;
}

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

/// The pens of the chart, by legend name.
struct Pens {
    QPen actual = pen(QColor(30, 90, 200), 1.2), machining = pen(QColor(0, 150, 60), 1.6);
    QPen limit = pen(Qt::red, 1.2, Qt::DashLine),
         minimum = pen(QColor(200, 120, 0), 1.2, Qt::DashLine);
    QPen idle = pen(Qt::darkGray, 1.2, Qt::DashLine),
         maxIdle = pen(Qt::black, 1.0, Qt::DashDotLine);
    QPen stall = pen(QColor(120, 70, 20), 1.2, Qt::DotLine);
    QPen reduction = pen(QColor(140, 0, 160), 1.6),
         peak = pen(QColor(140, 0, 160), 1.0, Qt::DotLine);
    QPen maximum = pen(Qt::red, 1.2, Qt::DashLine);
    QPen excth = pen(QColor(200, 30, 30), 1.6), thmis = pen(QColor(30, 30, 200), 1.6);
};

void drawItmPhases(QPainter& p, const Panel& panel,
                   const std::vector<std::pair<double, double>>& phases) {
    for (const auto& [from, to] : phases) {
        const double x0 = panel.at(from, 0).x(), x1 = std::max(panel.at(to, 0).x(), x0 + 2.0);
        const QRectF band(x0, panel.area.top() + 1, x1 - x0, panel.area.height() - 2);
        p.fillRect(band, AfcTrendPlot::itmColor());
        p.setPen(QColor(120, 90, 0));
        p.drawText(QRectF(x0, panel.area.bottom() - 18, 60, 16), Qt::AlignLeft, "ITM");
    }
}

void drawTorques(QPainter& p, const Panel& panel, const std::vector<Sample>& s, const Pens& k) {
    drawCurve(
        p, panel, s, [](const Sample& x) { return x.limitingTorque; }, k.limit);
    drawCurve(
        p, panel, s, [](const Sample& x) { return x.minimumTorque; }, k.minimum);
    drawCurve(
        p, panel, s, [](const Sample& x) { return x.maximumIdleTorque; }, k.maxIdle);
    drawCurve(
        p, panel, s, [](const Sample& x) { return x.idleTorque; }, k.idle);
    drawCurve(
        p, panel, s, [](const Sample& x) { return x.stallTorque; }, k.stall);
    drawCurve(
        p, panel, s, [](const Sample& x) { return x.torqueActual; }, k.actual);
    drawCurve(
        p, panel, s, [](const Sample& x) { return x.machiningTorque; }, k.machining);
}

void drawSignals(QPainter& p, const Panel& panel, const std::vector<Sample>& s, const Pens& k) {
    p.setPen(QColor(70, 70, 70));
    p.drawRect(panel.area);
    p.setPen(Qt::black);
    p.drawText(QRectF(0, panel.at(0, 1.25).y() - 8, panel.area.left() - 4, 16),
               Qt::AlignRight | Qt::AlignVCenter, "EXCTH");
    p.drawText(QRectF(0, panel.at(0, 0.25).y() - 8, panel.area.left() - 4, 16),
               Qt::AlignRight | Qt::AlignVCenter, "THMIS");
    drawCurve(
        p, panel, s, [](const Sample& x) { return x.excessiveThrust ? 1.75 : 1.0; }, k.excth);
    drawCurve(
        p, panel, s, [](const Sample& x) { return x.thrustMissing ? 0.75 : 0.0; }, k.thmis);
}

}  // namespace

AfcTrendPlot::AfcTrendPlot(QWidget* parent) : QWidget(parent) {
    setObjectName("afcTrendPlot");
    setMinimumSize(400, 300);
}

void AfcTrendPlot::setSamples(std::vector<mtc::core::AfcTrendSample> samples) {
    samples_ = std::move(samples);
    update();
}

QStringList AfcTrendPlot::legend() {
    return {tr("actual S-0-0084"),
            tr("machining 007"),
            tr("limiting 010"),
            tr("minimum 009"),
            tr("idling 005"),
            tr("max. idling 006"),
            tr("stall 014"),
            tr("feed reduction 011"),
            tr("peak 012"),
            tr("maximum 013"),
            "PxxS.EXCTH",
            "PxxS.THMIS",
            tr("ITM measuring period")};
}

std::vector<std::pair<double, double>> AfcTrendPlot::itmPhases() const {
    std::vector<std::pair<double, double>> phases;
    bool open = false;
    for (const Sample& s : samples_) {
        if (s.measuringIdle && !open) phases.push_back({s.time, s.time});
        if (s.measuringIdle) phases.back().second = s.time;
        open = s.measuringIdle;
    }
    return phases;
}

double AfcTrendPlot::xOf(double t) const {
    return layoutFor(size(), samples_).torque.at(t, 0).x();
}

void AfcTrendPlot::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(rect(), Qt::white);
    const Layout l = layoutFor(size(), samples_);
    drawItmPhases(p, l.torque, itmPhases());
    drawFrame(p, l.torque, tr("torque %"), 5);
    drawFrame(p, l.feed, tr("feed red. %"), 4);
    const double right = width() - kRight;
    p.drawText(QRectF(kLeft, height() - 22.0, right - kLeft, 18), Qt::AlignCenter,
               samples_.empty() ? tr("no samples yet: run a program with G26 / ITM")
                                : tr("simulated time %1 s ... %2 s")
                                      .arg(l.torque.t0, 0, 'f', 2)
                                      .arg(l.torque.t1, 0, 'f', 2));
    const Pens k;
    drawTorques(p, l.torque, samples_, k);
    drawCurve(
        p, l.feed, samples_, [](const Sample& s) { return s.maximumReduction; }, k.maximum);
    drawCurve(
        p, l.feed, samples_, [](const Sample& s) { return s.peakReduction; }, k.peak);
    drawCurve(
        p, l.feed, samples_, [](const Sample& s) { return s.feedReduction; }, k.reduction);
    drawSignals(p, l.strip, samples_, k);
    const QStringList names = legend();
    drawLegend(p, {kLeft, 10},
               {{names[0], k.actual},
                {names[1], k.machining},
                {names[2], k.limit},
                {names[3], k.minimum}});
    drawLegend(p, {kLeft, 26},
               {{names[4], k.idle},
                {names[5], k.maxIdle},
                {names[6], k.stall},
                {names[12], pen(itmColor().darker(130), 6)}});
    drawLegend(p, {kLeft, l.feed.area.top() - 14},
               {{names[7], k.reduction}, {names[8], k.peak}, {names[9], k.maximum}});
    drawLegend(p, {kLeft, l.strip.area.top() - 14}, {{names[10], k.excth}, {names[11], k.thmis}});
}

}  // namespace mtc::screens
