#include "screens/toolpath/PainterToolpathCanvas.h"

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>

#include "screens/toolpath/ToolpathModel.h"
#include "screens/toolpath/ToolpathPartRaster.h"

namespace mtc::screens {

namespace {
using Vec = std::array<double, 3>;
constexpr std::size_t kMaxDrawnSegments = 400000;  ///< more are thinned out (level of detail)

double dot(const Vec& a, const Vec& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// The eight corners of a box.
std::array<Vec, 8> corners(const Vec& lo, const Vec& hi) {
    std::array<Vec, 8> c{};
    for (int i = 0; i < 8; ++i)
        c[static_cast<std::size_t>(i)] = {(i & 1) ? hi[0] : lo[0], (i & 2) ? hi[1] : lo[1],
                                          (i & 4) ? hi[2] : lo[2]};
    return c;
}

double segmentDistance(QPointF p, QPointF a, QPointF b) {
    const QPointF ab = b - a, ap = p - a;
    const double len2 = QPointF::dotProduct(ab, ab);
    const double t = len2 > 0 ? std::clamp(QPointF::dotProduct(ap, ab) / len2, 0.0, 1.0) : 0.0;
    const QPointF d = ap - t * ab;
    return std::hypot(d.x(), d.y());
}
}  // namespace

PainterToolpathCanvas::PainterToolpathCanvas(ToolpathModel* model, QWidget* parent)
    : ToolpathCanvas(model, parent), pacer_([this] { update(); }) {
    setObjectName("toolpathPainter");
    setMinimumSize(320, 240);
    setFocusPolicy(Qt::NoFocus);
    developed_.developed = true;
    developed_.pose = presetPose(ToolpathPreset::G17);
    scene_.pose = presetPose(ToolpathPreset::Isometric);
    connect(model_, &ToolpathModel::geometryChanged, this, [this] {
        layout();
        fit();
    });
    // A running program changes the marks at every tick: repaints are paced.
    connect(model_, &ToolpathModel::marksChanged, &pacer_, &ToolpathFramePacer::request);
    connect(model_, &ToolpathModel::partChanged, this, [this] {
        partChanged_ = true;
        pacer_.request();
    });
}

void PainterToolpathCanvas::layout() {
    const auto g = model_->geometry();
    split_ = g && g->developed.segmentCount() > 0;
    const QRect all = rect();
    if (split_) {
        developed_.rect = QRect(all.left(), all.top(), all.width() / 2, all.height());
        scene_.rect = QRect(all.left() + all.width() / 2, all.top(), all.width() - all.width() / 2,
                            all.height());
    } else {
        scene_.rect = all;
    }
}

void PainterToolpathCanvas::resizeEvent(QResizeEvent* event) {
    ToolpathCanvas::resizeEvent(event);
    layout();
    frame(framedAll_);  // the same framing at the new size
}

const mtc::core::ToolpathLayer* PainterToolpathCanvas::layerOf(const View& view) const {
    const auto g = model_->geometry();
    if (!g) return nullptr;
    return view.developed ? &g->developed : &g->scene;
}

QPointF PainterToolpathCanvas::project(const View& view, const Vec& p) const {
    const Vec d{p[0] - view.focal[0], p[1] - view.focal[1], p[2] - view.focal[2]};
    return {view.centre.x() + view.scale * dot(d, view.pose.right()),
            view.centre.y() - view.scale * dot(d, view.pose.up)};
}

void PainterToolpathCanvas::fitView(View& view, bool all) {
    mtc::core::ToolpathBounds box = model_->frame(view.developed, all);
    if (box.empty) box.add(0, 0, 0);
    view.focal = {(box.min[0] + box.max[0]) / 2, (box.min[1] + box.max[1]) / 2,
                  (box.min[2] + box.max[2]) / 2};
    double w = 1e-3, h = 1e-3;
    for (const Vec& c :
         corners({box.min[0], box.min[1], box.min[2]}, {box.max[0], box.max[1], box.max[2]})) {
        const Vec d{c[0] - view.focal[0], c[1] - view.focal[1], c[2] - view.focal[2]};
        w = std::max(w, 2 * std::fabs(dot(d, view.pose.right())));
        h = std::max(h, 2 * std::fabs(dot(d, view.pose.up)));
    }
    // The part in the middle of what the rulers leave free (TP-025) ...
    const QRectF free =
        QRectF(view.rect).marginsRemoved(rulerMargins(QFontMetricsF(font()), 5.0 * lineScale()));
    const QSizeF extent(w, h);
    view.framed = extent;
    fitInto(view, free, extent);
    // ... and clear of the triad in the top right corner: below it or left
    // of it, whichever leaves the part larger (TP-031).
    const QRectF triad = triadInk(view);
    if (!framedArea(view, extent).intersects(triad)) return;
    QRectF below = free, beside = free;
    below.setTop(std::max(free.top(), triad.bottom()));
    beside.setRight(std::min(free.right(), triad.left()));
    View underTriad = view;
    fitInto(underTriad, below, extent);
    fitInto(view, beside, extent);
    if (underTriad.scale > view.scale) view = underTriad;
}

QRectF PainterToolpathCanvas::framedRect(bool developed) const {
    const View& view = developed ? developed_ : scene_;
    return framedArea(view, view.framed);
}

QRectF PainterToolpathCanvas::triadRect(bool developed) const {
    return triadInk(developed ? developed_ : scene_);
}

void PainterToolpathCanvas::fitInto(View& view, const QRectF& area, const QSizeF& box) {
    view.centre = area.center();
    view.scale = kFitShare * std::min(std::max(area.width(), 1.0) / box.width(),
                                      std::max(area.height(), 1.0) / box.height());
}

QRectF PainterToolpathCanvas::framedArea(const View& view, const QSizeF& box) {
    const QSizeF size = box * view.scale;
    return {view.centre - QPointF(size.width() / 2, size.height() / 2), size};
}

void PainterToolpathCanvas::showPreset(ToolpathPreset preset) {
    scene_.pose = presetPose(preset);
    fit();
}

void PainterToolpathCanvas::fit() {
    frame(false);
}

void PainterToolpathCanvas::fitAll() {
    frame(true);
}

void PainterToolpathCanvas::frame(bool all) {
    framedAll_ = all;
    fitView(scene_, all);
    if (split_) fitView(developed_, all);
    update();
}

void PainterToolpathCanvas::zoom(double factor) {
    scene_.scale *= factor;
    developed_.scale *= factor;
    update();
}

void PainterToolpathCanvas::pan(double right, double up) {
    for (View* v : {&scene_, &developed_}) {
        const double dx = right * v->rect.width() / v->scale, dy = up * v->rect.height() / v->scale;
        const Vec r = v->pose.right();
        for (std::size_t i = 0; i < 3; ++i)
            v->focal[i] -= dx * r[i] + dy * v->pose.up[i];
    }
    update();
}

void PainterToolpathCanvas::rotate(double azimuth, double elevation) {
    scene_.pose.rotate(azimuth, elevation);
    update();
}

QImage PainterToolpathCanvas::picture() {
    return grab().toImage();
}

void PainterToolpathCanvas::paintEvent(QPaintEvent*) {
    pacer_.drawn();
    QPainter painter(this);
    painter.fillRect(rect(), model_->palette().background);
    if (!model_->geometry()) {
        painter.setPen(Qt::white);
        painter.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap, model_->summary());
        return;
    }
    if (split_) drawView(painter, developed_);
    drawView(painter, scene_);
    if (split_) {
        painter.setPen(model_->palette().grid);
        painter.drawLine(scene_.rect.topLeft(), scene_.rect.bottomLeft());
    }
}

void PainterToolpathCanvas::drawView(QPainter& painter, const View& view) {
    painter.save();
    painter.setClipRect(view.rect);
    painter.setRenderHint(QPainter::Antialiasing, false);
    if (!view.developed) {
        drawStock(painter, view);
        drawPart(painter, view);
    }
    drawContour(painter, view);
    drawLayer(painter, view);
    drawHighlight(painter, view);
    drawBackplot(painter, view);  // over the highlight: the running block's travelled part shows
    if (!view.developed) drawMarks(painter, view);
    drawTriad(painter, view);
    painter.setPen(Qt::white);
    const QRect captionArea = view.rect.adjusted(6, 4, -6, -4);
    const int flags = Qt::AlignTop | Qt::AlignLeft;
    const QString text = caption(view.developed);
    painter.drawText(captionArea, flags, text);
    drawRulers(painter, view, painter.boundingRect(captionArea, flags, text));
    painter.restore();
}

void PainterToolpathCanvas::drawRulers(QPainter& painter, const View& view, const QRect& caption) {
    const QString developedTitles[3] = {tr("axial (mm)"), tr("circumferential (mm)"), {}};
    std::array<QString, 3> titles;
    for (int i = 0; i < 3; ++i)
        titles[static_cast<std::size_t>(i)] =
            view.developed ? developedTitles[i] : model_->axisTitle(i);
    ToolpathRulers& rulers = rulers_[view.developed ? 1 : 0];
    rulers = layoutRulers(
        [&](const Vec& p) { return project(view, p); }, model_->frame(view.developed, framedAll_),
        view.developed ? mtc::core::ToolpathFrame{} : model_->workFrame(), titles,
        QFontMetricsF(painter.font()), 5.0 * lineScale(), QRectF(view.rect).adjusted(2, 2, -2, -2),
        {QRectF(caption), triadBox(view)});
    painter.setPen(QPen(model_->palette().grid, penWidth(1)));
    for (const auto& line : rulers.lines)
        painter.drawLine(line[0], line[1]);
    for (const auto& mark : rulers.marks)
        painter.drawLine(mark[0], mark[1]);
    painter.setPen(Qt::white);
    for (const ToolpathTick& tick : rulers.ticks)
        painter.drawText(tick.box, Qt::AlignCenter, tick.text);
    for (const ToolpathAxisTitle& title : rulers.titles) {
        if (!title.upright) {
            painter.drawText(title.box, Qt::AlignCenter, title.text);
            continue;
        }
        painter.save();  // reads upwards beside a ruler that runs up
        painter.translate(title.box.center());
        painter.rotate(-90);
        painter.drawText(QRectF(-title.box.height() / 2, -title.box.width() / 2, title.box.height(),
                                title.box.width()),
                         Qt::AlignCenter, title.text);
        painter.restore();
    }
}

QString PainterToolpathCanvas::caption(bool developed) const {
    const auto* layer = layerOf(developed ? developed_ : scene_);
    QString text = developed ? tr("Developed plane (G32)") : tr("Toolpath (2D view, no OpenGL)");
    if (layer && !layer->bounds.empty) {
        const auto& b = layer->bounds;
        text += "\n" + tr("extents %1 x %2 x %3 mm")
                           .arg(b.max[0] - b.min[0], 0, 'f', 1)
                           .arg(b.max[1] - b.min[1], 0, 'f', 1)
                           .arg(b.max[2] - b.min[2], 0, 'f', 1);
    }
    if (!developed && model_->geometry()) text += "\n" + model_->frameCaption();  // TP-019
    return text;
}

void PainterToolpathCanvas::drawLayer(QPainter& painter, const View& view) {
    const auto g = model_->geometry();
    const auto* layer = layerOf(view);
    if (!layer || layer->segmentCount() == 0) return;
    const std::size_t stride = std::max<std::size_t>(1, layer->segmentCount() / kMaxDrawnSegments);
    QVector<QLineF> lines[mtc::core::kToolpathKinds];
    for (std::size_t m = 0; m < g->moves.size(); ++m) {
        const auto [first, last] = view.developed ? g->developedRange(m) : g->sceneRange(m);
        auto& out = lines[static_cast<int>(g->moves[m].kind)];
        for (std::uint32_t s = first; s < last; s += static_cast<std::uint32_t>(stride)) {
            const std::uint32_t v = layer->segmentStart[s];
            const std::uint32_t end =
                std::min<std::uint32_t>(s + static_cast<std::uint32_t>(stride), last);
            const std::uint32_t w = layer->segmentStart[end - 1] + 1;
            out.push_back({project(view, layer->vertex(v)), project(view, layer->vertex(w))});
        }
    }
    for (int k = 0; k < mtc::core::kToolpathKinds; ++k) {
        painter.setPen(
            QPen(model_->palette().colour(static_cast<mtc::core::ToolpathKind>(k)), penWidth(1)));
        painter.drawLines(lines[k]);
    }
}

void PainterToolpathCanvas::drawContour(QPainter& painter, const View& view) {
    const auto g = model_->geometry();
    if (!g) return;
    const auto& layer = view.developed ? g->developedContour : g->contour;
    const std::size_t count = layer.segmentCount();
    if (count == 0) return;
    const std::size_t stride = std::max<std::size_t>(1, count / kMaxDrawnSegments);
    QVector<QLineF> lines;
    lines.reserve(static_cast<int>(count / stride + 1));
    for (std::size_t s = 0; s < count; s += stride) {
        const std::uint32_t v = layer.segmentStart[s];
        lines.push_back({project(view, layer.vertex(v)), project(view, layer.vertex(v + 1))});
    }
    // Dashed and thin: the tool-centre path in the motion colours stays on top.
    painter.setPen(QPen(model_->palette().contour, penWidth(1), Qt::DashLine));
    painter.drawLines(lines);
}

void PainterToolpathCanvas::drawBackplot(QPainter& painter, const View& view) {
    const ToolpathBackplot backplot = model_->backplot(view.developed);
    if (backplot.empty()) return;
    const auto& layer = *backplot.layer;
    // Thinned out like the path beyond kMaxDrawnSegments; the stretch of a
    // thinned step ends on a vertex of the path.
    const std::uint32_t stride =
        static_cast<std::uint32_t>(std::max<std::size_t>(1, backplot.segments / kMaxDrawnSegments));
    QVector<QLineF> lines;
    lines.reserve(static_cast<int>(backplot.segments / stride + 2));
    for (std::uint32_t s = 0; s < backplot.segments; s += stride) {
        const std::uint32_t end = std::min(s + stride, backplot.segments);
        lines.push_back({project(view, layer.vertex(layer.segmentStart[s])),
                         project(view, layer.vertex(layer.segmentStart[end - 1] + 1))});
    }
    if (backplot.partial)
        lines.push_back({project(view, backplot.partialFrom), project(view, backplot.partialTo)});
    painter.setPen(QPen(model_->palette().backplot, penWidth(3), Qt::SolidLine, Qt::RoundCap));
    painter.drawLines(lines);
}

void PainterToolpathCanvas::drawHighlight(QPainter& painter, const View& view) {
    const auto g = model_->geometry();
    const auto* layer = layerOf(view);
    painter.setPen(QPen(model_->palette().highlight, penWidth(4), Qt::SolidLine, Qt::RoundCap));
    for (std::uint32_t m : model_->highlighted()) {
        const auto [first, last] = view.developed ? g->developedRange(m) : g->sceneRange(m);
        for (std::uint32_t s = first; s < last; ++s) {
            const std::uint32_t v = layer->segmentStart[s];
            painter.drawLine(project(view, layer->vertex(v)), project(view, layer->vertex(v + 1)));
        }
    }
}

void PainterToolpathCanvas::drawMarks(QPainter& painter, const View& view) {
    const ToolpathMarks marks = model_->marks();
    const auto& palette = model_->palette();
    auto dot = [&](bool shown, const Vec& p, const QColor& colour) {
        if (!shown) return;
        painter.setPen(QPen(Qt::black, penWidth(1)));
        painter.setBrush(colour);
        painter.drawEllipse(project(view, p), 6 * lineScale(), 6 * lineScale());
    };
    if (marks.hasRepos) {
        painter.setPen(QPen(palette.repos, penWidth(2), Qt::DashLine));
        QPolygonF path;  // the corners of ADJUST / REPOS (TP-007)
        for (const auto& p : marks.repos)
            path << project(view, p);
        painter.drawPolyline(path);
    }
    for (const auto& p : marks.collisions)  // where the way back meets the part (D-021)
        dot(true, p, QColor(0xd0, 0x00, 0x00));
    dot(marks.hasStart, marks.start, palette.start);
    dot(marks.hasTarget, marks.target, palette.target);
    dot(marks.hasReentry, marks.reentry, palette.reentry);
    drawTool(painter, view, marks);
    painter.setBrush(Qt::NoBrush);
}

void PainterToolpathCanvas::drawTool(QPainter& painter, const View& view,
                                     const ToolpathMarks& marks) {
    if (!marks.hasTool) return;
    const QColor& colour = model_->palette().tool;
    const QPointF tip = project(view, marks.tool);
    const double radius = std::max(5.0 * lineScale(), marks.toolRadius * view.scale);
    painter.setPen(QPen(colour, penWidth(2)));
    if (!marks.turning) {  // the shank up the tool axis (Z), as long as L1
        const double length = std::max(marks.toolLength, 4.0 * std::max(marks.toolRadius, 1.0));
        const Vec top{marks.tool[0], marks.tool[1], marks.tool[2] + length};
        painter.drawLine(tip, project(view, top));
    }
    painter.setBrush(colour);
    painter.drawEllipse(tip, radius, radius);
}

void PainterToolpathCanvas::drawStock(QPainter& painter, const View& view) {
    const auto& stock = model_->stock();
    painter.setPen(QPen(model_->palette().stock, penWidth(1), Qt::DotLine));
    if (stock.shape == mtc::core::Stock::Shape::Block) {
        const auto c = corners(stock.min, stock.max);
        for (int i = 0; i < 8; ++i)
            for (int bit : {1, 2, 4})
                if (!(i & bit))
                    painter.drawLine(project(view, c[static_cast<std::size_t>(i)]),
                                     project(view, c[static_cast<std::size_t>(i | bit)]));
    } else if (stock.shape == mtc::core::Stock::Shape::Cylinder) {
        for (double along : {stock.from, stock.to}) {
            QPainterPath ring;
            for (int i = 0; i <= 72; ++i) {
                Vec p{};
                const double a = i * 5.0 * 3.14159265358979323846 / 180.0;
                p[static_cast<std::size_t>(stock.axis)] = along;
                p[static_cast<std::size_t>((stock.axis + 1) % 3)] = stock.radius * std::cos(a);
                p[static_cast<std::size_t>((stock.axis + 2) % 3)] = stock.radius * std::sin(a);
                i == 0 ? ring.moveTo(project(view, p)) : ring.lineTo(project(view, p));
            }
            painter.drawPath(ring);
        }
    }
}

void PainterToolpathCanvas::drawPart(QPainter& painter, const View& view) {
    if (!model_->partShown()) return;
    const double ratio = devicePixelRatioF();  // the image has the screen's pixels
    const Vec right = view.pose.right();
    std::vector<double> key{view.pose.direction[0],
                            view.pose.direction[1],
                            view.pose.direction[2],
                            view.pose.up[0],
                            view.pose.up[1],
                            view.pose.up[2],
                            view.focal[0],
                            view.focal[1],
                            view.focal[2],
                            view.scale,
                            view.centre.x(),
                            view.centre.y(),
                            double(view.rect.x()),
                            double(view.rect.y()),
                            double(view.rect.width()),
                            double(view.rect.height()),
                            ratio};
    if (partChanged_ || key != partKey_) {
        PartProjection projection;
        projection.right = right;
        projection.up = view.pose.up;
        projection.toward = {-view.pose.direction[0], -view.pose.direction[1],
                             -view.pose.direction[2]};
        projection.focal = view.focal;
        projection.scale = view.scale * ratio;
        projection.centreX = (view.centre.x() - view.rect.x()) * ratio;
        projection.centreY = (view.centre.y() - view.rect.y()) * ratio;
        const ToolpathPart& part = model_->part();
        partImage_ = rasterizePart(part.triangles, model_->palette().part, part.heightField,
                                   projection, (QSizeF(view.rect.size()) * ratio).toSize());
        partImage_.setDevicePixelRatio(ratio);
        partKey_ = std::move(key);
        partChanged_ = false;
        ++partImagesMade_;
    }
    painter.drawImage(view.rect.topLeft(), partImage_);
}

QRectF PainterToolpathCanvas::triadBox(const View& view) const {
    // Top right: the bottom and the left carry the rulers (TP-025). The
    // arms reach 28 px (at 96 dpi) from the middle, their names beyond.
    const QFontMetricsF metrics(font());
    const double name = view.developed
                            ? std::max({metrics.horizontalAdvance(tr("axial")),
                                        metrics.horizontalAdvance(tr("circ.")), metrics.height()})
                            : std::max(metrics.horizontalAdvance("X"), metrics.height());
    const double side = 2 * (28 * lineScale() + name + 6);
    return {view.rect.right() - side, double(view.rect.top()), side, side};
}

QPointF PainterToolpathCanvas::triadTip(const View& view, QPointF origin, int axis) const {
    Vec unit{0, 0, 0};
    unit[static_cast<std::size_t>(axis)] = 1.0;
    const double arm = 28 * lineScale();
    return origin + QPointF(arm * dot(unit, view.pose.right()), -arm * dot(unit, view.pose.up));
}

QString PainterToolpathCanvas::triadName(const View& view, int axis) {
    const char* names[3] = {"X", "Y", "Z"};
    if (view.developed && axis < 2) return axis == 0 ? tr("axial") : tr("circ.");
    return QString(names[axis]);
}

QRectF PainterToolpathCanvas::triadInk(const View& view) const {
    const QFontMetricsF metrics(font());
    const QPointF origin = triadBox(view).center();
    QRectF ink(origin, QSizeF(0, 0));
    for (int axis = 0; axis < 3; ++axis) {
        const QPointF tip = triadTip(view, origin, axis);
        const QPointF text = tip + QPointF(3, 3);  // the baseline's start
        ink |= QRectF(tip, QSizeF(0, 0));
        ink |= QRectF(text.x(), text.y() - metrics.ascent(),
                      metrics.horizontalAdvance(triadName(view, axis)), metrics.height());
    }
    return ink.marginsAdded(QMarginsF(4, 4, 4, 4));
}

void PainterToolpathCanvas::drawTriad(QPainter& painter, const View& view) {
    const QPointF origin = triadBox(view).center();
    const QColor colours[3] = {Qt::red, Qt::green, QColor(80, 140, 255)};
    for (int axis = 0; axis < 3; ++axis) {
        const QPointF tip = triadTip(view, origin, axis);
        painter.setPen(QPen(colours[axis], penWidth(2)));
        painter.drawLine(origin, tip);
        painter.drawText(tip + QPointF(3, 3), triadName(view, axis));
    }
}

long PainterToolpathCanvas::pickIn(const View& view, QPointF at) const {
    const auto g = model_->geometry();
    const auto* layer = layerOf(view);
    if (!layer) return -1;
    double best = 6.0;  // pixels
    long bestSegment = -1;
    for (std::size_t s = 0; s < layer->segmentCount(); ++s) {
        const std::uint32_t v = layer->segmentStart[s];
        const double d = segmentDistance(at, project(view, layer->vertex(v)),
                                         project(view, layer->vertex(v + 1)));
        if (d < best) {
            best = d;
            bestSegment = static_cast<long>(s);
        }
    }
    if (bestSegment < 0) return -1;
    const auto segment = static_cast<std::uint32_t>(bestSegment);
    return view.developed ? g->moveOfDevelopedSegment(segment) : g->moveOfSceneSegment(segment);
}

void PainterToolpathCanvas::mousePressEvent(QMouseEvent* event) {
    const View& view = split_ && developed_.rect.contains(event->pos()) ? developed_ : scene_;
    const long move = pickIn(view, event->pos());
    if (move >= 0) model_->pick(move);
}

std::optional<QPoint> PainterToolpathCanvas::positionOfMove(long move) {
    const auto g = model_->geometry();
    if (!g || move < 0 || static_cast<std::size_t>(move) >= g->moves.size()) return std::nullopt;
    const auto m = static_cast<std::size_t>(move);
    const bool inScene = g->sceneRange(m).first < g->sceneRange(m).second;
    const View& view = inScene ? scene_ : developed_;
    const auto [first, last] = inScene ? g->sceneRange(m) : g->developedRange(m);
    if (first == last) return std::nullopt;
    const auto* layer = layerOf(view);
    const std::uint32_t v = layer->segmentStart[first];
    const QPointF mid = (project(view, layer->vertex(v)) + project(view, layer->vertex(v + 1))) / 2;
    if (!view.rect.contains(mid.toPoint())) return std::nullopt;
    return mid.toPoint();
}

}  // namespace mtc::screens
