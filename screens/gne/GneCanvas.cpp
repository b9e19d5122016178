#include "screens/gne/GneCanvas.h"

#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

#include "cnc_core/contour/Geometry2D.h"
#include "cnc_core/text/Numbers.h"
#include "screens/gne/GneEditModel.h"

namespace mtc::screens {

namespace gne = mtc::core::gne;

namespace {

const QColor kSolved(20, 40, 160);
const QColor kRaw(150, 90, 20);
const QColor kOpen(200, 30, 30);
const QColor kSelected(240, 130, 0);
const QColor kOther(150, 150, 150);
const QColor kForm(0, 130, 60);
const QColor kCycle(0, 150, 170);

void grow(QRectF& r, double x, double y) {
    if (r.isNull())
        r = QRectF(x, y, 0, 0);
    else
        r = r.united(QRectF(x, y, 0, 0));
}

}  // namespace

GneCanvas::GneCanvas(const GneEditModel* model, QWidget* parent) : QWidget(parent), model_(model) {
    setObjectName("gneCanvas");
    setMinimumSize(360, 280);
    setFocusPolicy(Qt::NoFocus);
    setAutoFillBackground(true);
    QPalette p = palette();
    p.setColor(QPalette::Window, Qt::white);
    setPalette(p);
}

void GneCanvas::setZoomToWindow(bool window) {
    zoomToWindow_ = window;
    zoom_ = 1.0;
    update();
}

void GneCanvas::zoomBy(double factor) {
    zoom_ = std::clamp(zoom_ * factor, 0.05, 200.0);
    update();
}

QRectF GneCanvas::contentExtent() const {
    QRectF r;
    for (std::size_t i = 0; i < model_->items().size(); ++i)
        for (const auto& element : model_->solution(static_cast<int>(i)).elements) {
            for (const gne::Segment& s : element.segments)
                for (const gne::Point& p : gne::tessellate({s}, 0.05))
                    grow(r, p.x(), p.y());
            for (const gne::Segment& s : element.candidates)
                grow(r, s.end.x(), s.end.y());
        }
    for (const gne::Geometry& g : model_->expansion().geometries)
        for (const auto& path : g.paths)
            for (const gne::Point& p : gne::tessellate(path, 0.05))
                grow(r, p.x(), p.y());
    return r;
}

QRectF GneCanvas::worldView() const {
    QRectF world;
    double l0 = 0, l1 = 0, h0 = 0, h1 = 0;
    if (zoomToWindow_ && model_->window(l0, l1, h0, h1)) world = QRectF(l0, l1, h0 - l0, h1 - l1);
    if (world.isNull()) world = contentExtent();
    if (world.isNull()) world = QRectF(-10, -10, 20, 20);
    const double margin = 0.08 * std::max(world.width(), world.height()) + 1.0;
    world.adjust(-margin, -margin, margin, margin);
    const QPointF c = world.center();
    const double w = world.width() / zoom_, h = world.height() / zoom_;
    return QRectF(c.x() - w / 2, c.y() - h / 2, w, h);
}

QPointF GneCanvas::toScreen(double x, double y) const {
    return QPointF(offset_.x() + (x - view_.left()) * scale_,
                   offset_.y() - (y - view_.top()) * scale_);
}

void GneCanvas::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    view_ = worldView();
    scale_ = std::min((width() - 20) / view_.width(), (height() - 40) / view_.height());
    const double usedW = view_.width() * scale_, usedH = view_.height() * scale_;
    offset_ = QPointF((width() - usedW) / 2, (height() - 20 + usedH) / 2);
    drawWindow(painter);
    drawOtherGeometry(painter);
    drawCycles(painter);
    drawContours(painter);
    drawLegend(painter);
}

void GneCanvas::drawWindow(QPainter& painter) const {
    double l0 = 0, l1 = 0, h0 = 0, h1 = 0;
    painter.setPen(QPen(QColor(200, 200, 200), 1, Qt::DashDotLine));
    const QPointF o = toScreen(0, 0);  // axes through the zero point
    painter.drawLine(QPointF(0, o.y()), QPointF(width(), o.y()));
    painter.drawLine(QPointF(o.x(), 0), QPointF(o.x(), height()));
    if (!model_->window(l0, l1, h0, h1)) return;
    painter.setPen(QPen(QColor(120, 120, 120), 1));
    painter.setBrush(QColor(235, 235, 228));
    painter.drawRect(QRectF(toScreen(l0, h1), toScreen(h0, l1)));
    painter.setBrush(Qt::NoBrush);
}

void GneCanvas::drawOtherGeometry(QPainter& painter) const {
    // Forms (and the program's other geometry) as the expansion built them;
    // the section's contours are drawn from their solutions instead.
    std::vector<int> contours;
    for (const auto& item : model_->items())
        if (item.isContour) contours.push_back(item.contour.number);
    for (const gne::Geometry& g : model_->expansion().geometries) {
        if (std::find(contours.begin(), contours.end(), g.number) != contours.end()) continue;
        painter.setPen(QPen(g.line >= 100000 ? kForm : kOther, 2));
        for (const auto& path : g.paths) {
            QPolygonF polygon;
            for (const gne::Point& p : gne::tessellate(path, 0.5 / std::max(scale_, 1e-6)))
                polygon << toScreen(p.x(), p.y());
            painter.drawPolyline(polygon);
        }
    }
}

void GneCanvas::drawCycles(QPainter& painter) const {
    // The section's cycles as their expanded blocks: rapid moves dotted,
    // cutting moves thin (plane words only; the centre words are absolute).
    for (const gne::ExpandedCall& call : model_->expansion().calls) {
        if (call.line < 100000) continue;
        const auto item = static_cast<std::size_t>((call.line - 100000) / 1000);
        const bool turning = model_->planeOf(static_cast<int>(item)) == gne::GnePlane::Turning;
        const char first = turning ? 'Z' : 'X', second = turning ? 'X' : 'Y';
        const char centreFirst = turning ? 'K' : 'I', centreSecond = turning ? 'I' : 'J';
        double pos[2] = {0, 0};
        bool known[2] = {false, false};
        int motion = 0;
        for (const std::string& block : call.blocks) {
            double word[2] = {pos[0], pos[1]}, centre[2] = {0, 0};
            const std::string code = block.substr(0, block.find(';'));
            for (std::size_t i = 0; i < code.size(); ++i) {
                const char letter = code[i];
                if (!std::isalpha(static_cast<unsigned char>(letter))) continue;
                const double value = core::leadingNumber(std::string_view(code).substr(i + 1));
                if (letter == 'G' && value >= 0 && value <= 3) motion = static_cast<int>(value);
                if (letter == first) word[0] = value, known[0] = true;
                if (letter == second) word[1] = value, known[1] = true;
                if (letter == centreFirst) centre[0] = value;
                if (letter == centreSecond) centre[1] = value;
            }
            const bool draw = known[0] && known[1] && (word[0] != pos[0] || word[1] != pos[1]);
            if (draw) {
                gne::Segment s;
                s.kind = motion == 2   ? gne::Segment::ArcCW
                         : motion == 3 ? gne::Segment::ArcCCW
                                       : gne::Segment::Line;
                s.start = gne::Point(pos[0], pos[1]);
                s.end = gne::Point(word[0], word[1]);
                s.centre = gne::Point(centre[0], centre[1]);
                QPolygonF polygon;
                for (const gne::Point& p : gne::tessellate({s}, 0.5 / std::max(scale_, 1e-6)))
                    polygon << toScreen(p.x(), p.y());
                painter.setPen(motion == 0 ? QPen(kCycle, 1, Qt::DotLine) : QPen(kCycle, 1));
                painter.drawPolyline(polygon);
            }
            pos[0] = word[0], pos[1] = word[1];
        }
    }
}

void GneCanvas::drawContours(QPainter& painter) const {
    const int currentRow = model_->currentRow();
    const GneRow selected = model_->rows().empty()
                                ? GneRow{-1, -1}
                                : model_->rows()[static_cast<std::size_t>(currentRow)];
    auto drawPath = [&](const std::vector<gne::Segment>& path, const QPen& pen) {
        QPolygonF polygon;
        for (const gne::Point& p : gne::tessellate(path, 0.5 / std::max(scale_, 1e-6)))
            polygon << toScreen(p.x(), p.y());
        painter.setPen(pen);
        painter.drawPolyline(polygon);
    };
    for (std::size_t i = 0; i < model_->items().size(); ++i) {
        const auto& item = model_->items()[i];
        if (!item.isContour) continue;
        const gne::ContourSolution& solution = model_->solution(static_cast<int>(i));
        const QColor colour = item.contour.raw ? kRaw : kSolved;
        gne::Point last(0, 0);
        bool haveLast = false;
        for (std::size_t j = 0; j < solution.elements.size(); ++j) {
            const auto& es = solution.elements[j];
            const bool isSelected =
                selected.item == static_cast<int>(i) && selected.element == static_cast<int>(j);
            if (isSelected && es.candidates.size() > 1)
                for (std::size_t k = 0; k < es.candidates.size(); ++k)
                    if (static_cast<int>(k) != es.chosen)
                        drawPath({es.candidates[k]}, QPen(kOther, 1.5, Qt::DotLine));
            if (es.solved()) {
                drawPath(es.segments, QPen(isSelected ? kSelected : colour, isSelected ? 3.5 : 2));
                if (!es.segments.empty()) last = es.segments.back().end, haveLast = true;
                if (item.contour.elements[j].kind == gne::ElementKind::Start) {
                    const auto& e = item.contour.elements[j];
                    if (e.end[0] && e.end[1]) {
                        last = gne::Point(*e.end[0], *e.end[1]), haveLast = true;
                        painter.setPen(QPen(isSelected ? kSelected : colour, 2));
                        painter.drawEllipse(toScreen(last.x(), last.y()), 4, 4);
                    }
                }
                continue;
            }
            // Not solved: dashed from the last known point to what is known.
            const QPen dashed(isSelected ? kSelected : kOpen, 2, Qt::DashLine);
            if (!es.candidates.empty()) {
                drawPath(es.candidates, dashed);
                continue;
            }
            const auto& e = item.contour.elements[j];
            if (haveLast && e.end[0] && e.end[1]) {
                painter.setPen(dashed);
                painter.drawLine(toScreen(last.x(), last.y()), toScreen(*e.end[0], *e.end[1]));
                last = gne::Point(*e.end[0], *e.end[1]);
            } else if (haveLast) {
                painter.setPen(dashed);
                painter.drawEllipse(toScreen(last.x(), last.y()), 7, 7);
            }
        }
    }
}

void GneCanvas::drawLegend(QPainter& painter) const {
    painter.setPen(Qt::black);
    const bool turning =
        model_->planeOf(
            model_->rows().empty()
                ? 0
                : model_->rows()[static_cast<std::size_t>(model_->currentRow())].item) ==
        gne::GnePlane::Turning;
    QString text = turning ? tr("Z ->   X ^   (turning, G18)") : tr("X ->   Y ^   (milling, G17)");
    text += "   " + (zoomToWindow_ ? tr("zoom: window") : tr("zoom: contour"));
    if (zoom_ != 1.0) text += QString(" x%1").arg(zoom_, 0, 'g', 3);
    const int alternatives = model_->alternativeCount();
    if (alternatives > 1) text += "   " + tr("alternatives: %1").arg(alternatives);
    painter.drawText(QRect(6, height() - 20, width() - 12, 18), Qt::AlignLeft, text);
    painter.drawText(QRect(6, 2, width() - 12, 18), Qt::AlignRight,
                     tr("solid: solved  dashed: open  dotted: other solution"));
}

}  // namespace mtc::screens
