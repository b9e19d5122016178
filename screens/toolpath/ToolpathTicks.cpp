#include "screens/toolpath/ToolpathTicks.h"

#include <algorithm>
#include <cmath>

namespace mtc::screens {

namespace {

using Vec = std::array<double, 3>;
constexpr double kLabelGap = 8.0;       ///< pixels at least between neighbouring labels
constexpr double kTextMargin = 2.0;     ///< pixels between a tick mark and its text
constexpr std::size_t kMaxTicks = 200;  ///< per ruler; a wider step beyond

double norm(QPointF p) {
    return std::hypot(p.x(), p.y());
}

/// Extent of a w x h text box along the unit direction `u`.
double extentAlong(QPointF u, double w, double h) {
    return std::fabs(u.x()) * w + std::fabs(u.y()) * h;
}

/// The part [t0, t1] of the segment a + t (b - a), t in [0, 1], inside `r`
/// (Liang-Barsky); t0 > t1 when none of it is.
std::array<double, 2> clipToRect(QPointF a, QPointF b, const QRectF& r) {
    double t0 = 0.0, t1 = 1.0;
    const QPointF d = b - a;
    const double p[4] = {-d.x(), d.x(), -d.y(), d.y()};
    const double q[4] = {a.x() - r.left(), r.right() - a.x(), a.y() - r.top(), r.bottom() - a.y()};
    for (int i = 0; i < 4; ++i) {
        if (std::fabs(p[i]) < 1e-12) {
            if (q[i] < 0) return {1.0, 0.0};
            continue;
        }
        const double t = q[i] / p[i];
        if (p[i] < 0)
            t0 = std::max(t0, t);
        else
            t1 = std::min(t1, t);
    }
    return {t0, t1};
}

bool fits(const QRectF& box, const QRectF& area, const std::vector<QRectF>& taken) {
    if (!area.contains(box)) return false;
    return std::none_of(taken.begin(), taken.end(),
                        [&](const QRectF& other) { return other.intersects(box); });
}

QRectF boxAround(QPointF centre, double w, double h) {
    return {centre.x() - w / 2, centre.y() - h / 2, w, h};
}

/// One axis's ruler while it is laid out.
struct Ruler {
    int axis = 0;
    QPointF from, to;       ///< screen points of the box edge at box.min / box.max of the axis
    QPointF unit, normal;   ///< along the edge; outward, away from the box
    bool across = true;     ///< runs more across the picture than up it
    double t0 = 0, t1 = 1;  ///< the part of the edge inside the picture
};

/// The edge of `box` along `axis` a ruler goes on: the lowest on screen for
/// an axis running across, the leftmost for one running up.
Ruler chooseEdge(const std::function<QPointF(const Vec&)>& project,
                 const mtc::core::ToolpathBounds& box, int axis, QPointF direction) {
    Ruler ruler;
    ruler.axis = axis;
    ruler.across = std::fabs(direction.x()) >= std::fabs(direction.y());
    const auto a = static_cast<std::size_t>(axis), b = static_cast<std::size_t>((axis + 1) % 3),
               c = static_cast<std::size_t>((axis + 2) % 3);
    double best = -1e300;
    for (int corner = 0; corner < 4; ++corner) {
        Vec p{};
        p[b] = (corner & 1) ? box.max[b] : box.min[b];
        p[c] = (corner & 2) ? box.max[c] : box.min[c];
        p[a] = box.min[a];
        const QPointF from = project(p);
        p[a] = box.max[a];
        const QPointF to = project(p);
        const QPointF mid = (from + to) / 2;
        const double score = ruler.across ? mid.y() : -mid.x();
        if (score > best + 1e-6) {  // coincident edges (plane views): the first
            best = score;
            ruler.from = from;
            ruler.to = to;
        }
    }
    ruler.unit = direction / norm(direction);
    ruler.normal = QPointF(-ruler.unit.y(), ruler.unit.x());
    const Vec middle{(box.min[0] + box.max[0]) / 2, (box.min[1] + box.max[1]) / 2,
                     (box.min[2] + box.max[2]) / 2};
    const QPointF outward = (ruler.from + ruler.to) / 2 - project(middle);
    const double side = QPointF::dotProduct(outward, ruler.normal);
    const bool flip = std::fabs(side) > 1e-6
                          ? side < 0
                          : (ruler.across ? ruler.normal.y() < 0 : ruler.normal.x() > 0);
    if (flip) ruler.normal = -ruler.normal;
    return ruler;
}

/// Moves the ruler into `area` when its labels (`room` pixels outward)
/// would leave it, then keeps the part of it inside.
void bringIntoArea(Ruler& ruler, const QRectF& area, double room) {
    const QPointF mid = (ruler.from + ruler.to) / 2;
    QPointF shift(0, 0);
    if (ruler.across) {
        const double low = area.top() + (ruler.normal.y() < 0 ? room : 1.0);
        const double high = area.bottom() - (ruler.normal.y() > 0 ? room : 1.0);
        if (mid.y() > high) shift.setY(high - mid.y());
        if (mid.y() < low) shift.setY(low - mid.y());
    } else {
        const double low = area.left() + (ruler.normal.x() < 0 ? room : 1.0);
        const double high = area.right() - (ruler.normal.x() > 0 ? room : 1.0);
        if (mid.x() > high) shift.setX(high - mid.x());
        if (mid.x() < low) shift.setX(low - mid.x());
    }
    ruler.from += shift;
    ruler.to += shift;
    const auto t = clipToRect(ruler.from, ruler.to, area);
    ruler.t0 = t[0];
    ruler.t1 = t[1];
}

double widestText(const std::vector<double>& values, int decimals, const QFontMetricsF& metrics) {
    double widest = 0.0;
    for (double v : values)
        widest = std::max(widest, metrics.horizontalAdvance(tickText(v, decimals)));
    return widest;
}

/// The ticks of the visible part of `ruler` (workpiece values lo..hi, `pixels`
/// per workpiece mm): the smallest step whose labels keep kLabelGap apart.
TickValues rulerValues(const Ruler& ruler, double lo, double hi, double pixels,
                       const QFontMetricsF& metrics) {
    const double h = metrics.height();
    const double guess =
        metrics.horizontalAdvance(tickText(std::max(std::fabs(lo), std::fabs(hi)), 0));
    double minimum = (extentAlong(ruler.unit, guess, h) + kLabelGap) / pixels;
    minimum = std::max(minimum, (hi - lo) / static_cast<double>(kMaxTicks));
    TickValues values;
    for (int round = 0; round < 6; ++round) {
        values = tickValues(lo, hi, minimum);
        const double w = widestText(values.values, values.decimals, metrics);
        const double needed = (extentAlong(ruler.unit, w, h) + kLabelGap) / pixels;
        if (values.step >= needed * (1 - 1e-9)) break;
        minimum = needed;
    }
    return values;
}

void placeTitle(ToolpathRulers& out, const Ruler& ruler, const QString& title, double labelDepth,
                const QFontMetricsF& metrics, double tickLength, const QRectF& area,
                std::vector<QRectF>& taken) {
    if (title.isEmpty()) return;
    const double w = metrics.horizontalAdvance(title), h = metrics.height();
    const QPointF a = ruler.from + ruler.t0 * (ruler.to - ruler.from);
    const QPointF b = ruler.from + ruler.t1 * (ruler.to - ruler.from);
    const QPointF mid = (a + b) / 2;
    // The end of the visible edge to the right (across) or at the top (up).
    const bool bIsEnd = ruler.across ? b.x() >= a.x() : b.y() <= a.y();
    const QPointF end = bIsEnd ? b : a;
    const QPointF beyond = bIsEnd ? ruler.unit : -ruler.unit;
    // Beside the labels, read along the ruler as a plot's axis title (an
    // axis running up: turned to read upwards), in the middle, else from the
    // ruler's start (bottom or left) or up to its end, where the caption is
    // not; else past the ruler's end; else inside the frame at that end.
    const double bw = ruler.across ? w : h, bh = ruler.across ? h : w;
    struct Candidate {
        QPointF centre;
        double w = 0, h = 0;
        bool upright = false;
    };
    const QPointF beside = ruler.normal * (tickLength + kTextMargin + labelDepth + kTextMargin +
                                           extentAlong(ruler.normal, bw, bh) / 2);
    const double halfAlong = extentAlong(beyond, bw, bh) / 2;
    const QPointF start = bIsEnd ? a : b;
    const Candidate candidates[] = {
        {mid + beside, bw, bh, !ruler.across},
        {start + beyond * halfAlong + beside, bw, bh, !ruler.across},
        {end - beyond * halfAlong + beside, bw, bh, !ruler.across},
        {end + beyond * (extentAlong(beyond, w, h) / 2 + 2 * kTextMargin), w, h, false},
        {end - beyond * (extentAlong(beyond, w, h) / 2) -
             ruler.normal * (kTextMargin + extentAlong(ruler.normal, w, h) / 2),
         w, h, false},
    };
    for (const Candidate& c : candidates) {
        const QRectF box = boxAround(c.centre, c.w, c.h);
        if (!fits(box, area, taken)) continue;
        taken.push_back(box);
        out.titles.push_back({ruler.axis, title, box, c.upright});
        return;
    }
}

}  // namespace

QMarginsF rulerMargins(const QFontMetricsF& metrics, double tickLength) {
    const double h = metrics.height(), label = metrics.horizontalAdvance("-000.0");
    const double depth = tickLength + 2 * kTextMargin;
    return {depth + label + kTextMargin + h + 4, h, h, depth + 2 * h + kTextMargin + 4};
}

TickValues tickValues(double from, double to, double minimumStep) {
    TickValues out;
    if (!std::isfinite(from) || !std::isfinite(to) || !(minimumStep > 0) ||
        !std::isfinite(minimumStep))
        return out;
    const double power = std::pow(10.0, std::floor(std::log10(minimumStep)));
    out.step = 10 * power;
    for (double m : {1.0, 2.0, 5.0})
        if (m * power >= minimumStep * (1 - 1e-9)) {
            out.step = m * power;
            break;
        }
    out.decimals = std::max(0, -static_cast<int>(std::floor(std::log10(out.step) + 1e-9)));
    const double first = std::ceil(from / out.step - 1e-9), last = std::floor(to / out.step + 1e-9);
    for (double k = first; k <= last && out.values.size() <= kMaxTicks; ++k)
        out.values.push_back(k * out.step);
    return out;
}

QString tickText(double value, int decimals) {
    if (std::fabs(value) < 0.5 * std::pow(10.0, -decimals)) value = 0.0;  // no "-0"
    return QString::number(value, 'f', decimals);
}

ToolpathRulers layoutRulers(const std::function<QPointF(const Vec&)>& project,
                            const mtc::core::ToolpathBounds& box,
                            const mtc::core::ToolpathFrame& frame,
                            const std::array<QString, 3>& titles, const QFontMetricsF& metrics,
                            double tickLength, const QRectF& area, std::vector<QRectF> taken) {
    ToolpathRulers out;
    if (box.empty) return out;
    const QPointF origin = project({0, 0, 0});
    std::array<QPointF, 3> direction;  // pixels per scene mm along each axis
    double longest = 0.0;
    for (std::size_t a = 0; a < 3; ++a) {
        Vec unit{0, 0, 0};
        unit[a] = 1.0;
        direction[a] = project(unit) - origin;
        longest = std::max(longest, norm(direction[a]));
    }
    const double h = metrics.height();
    for (int axis = 0; axis < 3; ++axis) {
        const auto a = static_cast<std::size_t>(axis);
        const double pixelsPerMm = norm(direction[a]);
        const double along = box.max[a] - box.min[a];
        // Seen end-on (the third axis of a plane view) or a flat box: no ruler.
        if (pixelsPerMm < 0.3 * longest || along * pixelsPerMm < 1.0) continue;
        Ruler ruler = chooseEdge(project, box, axis, direction[a]);
        const double sample = metrics.horizontalAdvance("-000.0");
        const double room = tickLength + kTextMargin + extentAlong(ruler.normal, sample, h);
        bringIntoArea(ruler, area, room);
        if (ruler.t1 <= ruler.t0) continue;
        out.lines.push_back({ruler.from + ruler.t0 * (ruler.to - ruler.from),
                             ruler.from + ruler.t1 * (ruler.to - ruler.from)});
        const double w0 = frame.workpiece(axis, box.min[a] + ruler.t0 * along);
        const double w1 = frame.workpiece(axis, box.min[a] + ruler.t1 * along);
        const TickValues values = rulerValues(ruler, std::min(w0, w1), std::max(w0, w1),
                                              pixelsPerMm / frame.scale(axis), metrics);
        double depth = 0.0;  // how far the labels reach out from their ticks
        for (double v : values.values) {
            const double t = (frame.sceneOf(axis, v) - box.min[a]) / along;
            const QPointF at = ruler.from + t * (ruler.to - ruler.from);
            const QString text = tickText(v, values.decimals);
            const double w = metrics.horizontalAdvance(text);
            const double reach = extentAlong(ruler.normal, w, h);
            const QRectF label =
                boxAround(at + ruler.normal * (tickLength + kTextMargin + reach / 2), w, h);
            out.marks.push_back({at, at + ruler.normal * tickLength});
            if (!fits(label, area, taken)) continue;
            taken.push_back(label);
            depth = std::max(depth, reach);
            out.ticks.push_back({axis, v, text, at, label});
        }
        placeTitle(out, ruler, titles[a], depth, metrics, tickLength, area, taken);
    }
    return out;
}

}  // namespace mtc::screens
