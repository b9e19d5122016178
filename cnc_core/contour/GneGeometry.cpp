#include "cnc_core/contour/GneGeometry.h"

#include <cmath>

#include "cnc_core/contour/GneSchema.h"
#include "cnc_core/contour/StrokeFont.h"

namespace mtc::core::gne {
namespace {

Segment line(const Point& a, const Point& b) {
    return {Segment::Line, a, b, Point::Zero(), -1};
}
Segment arc(Segment::Kind k, const Point& a, const Point& b, const Point& c) {
    return {k, a, b, c, -1};
}

std::vector<Segment> polyline(const std::vector<Point>& points, bool close) {
    std::vector<Segment> path;
    for (std::size_t i = 0; i + 1 < points.size(); ++i)
        path.push_back(line(points[i], points[i + 1]));
    if (close && points.size() > 2) path.push_back(line(points.back(), points.front()));
    return path;
}

std::vector<Segment> slot(const Point& c1, const Point& c2, double r) {
    const Point d = (c2 - c1).normalized(), n = leftNormal(d);
    return {line(c1 - n * r, c2 - n * r), arc(Segment::ArcCCW, c2 - n * r, c2 + n * r, c2),
            line(c2 + n * r, c1 + n * r), arc(Segment::ArcCCW, c1 + n * r, c1 - n * r, c1)};
}

std::vector<Segment> arcSlot(const Point& c, double radius, double a1, double a2, double r) {
    const Point u1 = direction(a1), u2 = direction(a2);
    const Point p1 = c + radius * u1, p2 = c + radius * u2;
    return {arc(Segment::ArcCCW, c + (radius + r) * u1, c + (radius + r) * u2, c),
            arc(Segment::ArcCCW, c + (radius + r) * u2, c + (radius - r) * u2, p2),
            arc(Segment::ArcCW, c + (radius - r) * u2, c + (radius - r) * u1, c),
            arc(Segment::ArcCCW, c + (radius - r) * u1, c + (radius + r) * u1, p1)};
}

std::vector<Segment> circle(const Point& c, double r) {
    return {arc(Segment::ArcCCW, c + Point(r, 0), c - Point(r, 0), c),
            arc(Segment::ArcCCW, c - Point(r, 0), c + Point(r, 0), c)};
}

/// Text strokes: character k starts at base(k) with the unit vectors along and up.
template <typename Place>
bool textStrokes(const std::string& text, double height, Place place, Geometry& g,
                 std::string& problem) {
    const double scale = height / kGlyphHeight;
    for (std::size_t k = 0; k < text.size(); ++k) {
        bool known = false;
        const auto strokes = glyphStrokes(text[k], &known);
        if (!known) {
            problem = std::string("the font has no character '") + text[k] + "' (it has " +
                      fontCharacters() + ")";
            return false;
        }
        Point base, along, up;
        place(k, base, along, up);
        for (const Stroke& s : strokes) {
            std::vector<Point> points;
            for (const Point& p : s)
                points.push_back(base + scale * (p.x() * along + p.y() * up));
            std::vector<Segment> path = polyline(points, false);
            if (!path.empty()) g.paths.push_back(path);
        }
    }
    g.strokes = true;
    return true;
}

}  // namespace

std::vector<Segment> roundedRectangle(const Point& c, double hl, double hw, double degrees,
                                      double rc) {
    const Point a = direction(degrees), b = leftNormal(a);
    auto at = [&](double x, double y) -> Point { return c + x * a + y * b; };
    if (rc <= kTolerance)
        return polyline({at(-hl, -hw), at(hl, -hw), at(hl, hw), at(-hl, hw)}, true);
    return {line(at(-hl + rc, -hw), at(hl - rc, -hw)),
            arc(Segment::ArcCCW, at(hl - rc, -hw), at(hl, -hw + rc), at(hl - rc, -hw + rc)),
            line(at(hl, -hw + rc), at(hl, hw - rc)),
            arc(Segment::ArcCCW, at(hl, hw - rc), at(hl - rc, hw), at(hl - rc, hw - rc)),
            line(at(hl - rc, hw), at(-hl + rc, hw)),
            arc(Segment::ArcCCW, at(-hl + rc, hw), at(-hl, hw - rc), at(-hl + rc, hw - rc)),
            line(at(-hl, hw - rc), at(-hl, -hw + rc)),
            arc(Segment::ArcCCW, at(-hl, -hw + rc), at(-hl + rc, -hw), at(-hl + rc, -hw + rc))};
}

bool formGeometry(const GneCall& call, Geometry& g, std::string& problem) {
    const CallSpec* spec = findCallSpec(call.keyword);
    if (!spec || call.keyword.rfind("FORM_", 0) != 0) {
        problem = call.keyword + " is not a form";
        return false;
    }
    auto v = [&](std::size_t i) { return paramValue(*spec, call, i); };
    g.number = static_cast<int>(v(0));
    g.plane = spec->plane;
    g.line = call.line;
    g.closed = true;
    const std::string& k = call.keyword;
    if (k == "FORM_20") {
        const double z = v(1), x = v(2), w = v(3), d = v(4);
        if (d >= x) return problem = "the recess is deeper than its radius", false;
        g.closed = false;
        g.paths.push_back(polyline({{z, x}, {z, x - d}, {z - w, x - d}, {z - w, x}}, false));
    } else if (k == "FORM_50") {
        const Point c1(v(1), v(2)), c2(v(3), v(4));
        if ((c2 - c1).norm() < kTolerance) return problem = "both ends are at one point", false;
        g.paths.push_back(slot(c1, c2, v(5) / 2));
    } else if (k == "FORM_51") {
        if (v(6) / 2 >= v(3)) return problem = "the hole is wider than twice its radius", false;
        if (std::fabs(v(5) - v(4)) < 1e-9 || std::fabs(v(5) - v(4)) >= 360)
            return problem = "A2 must differ from A1 by less than 360 degrees", false;
        double a2 = v(5);
        while (a2 <= v(4))
            a2 += 360;
        g.paths.push_back(arcSlot({v(1), v(2)}, v(3), v(4), a2, v(6) / 2));
    } else if (k == "FORM_52") {
        g.paths.push_back(circle({v(1), v(2)}, v(3)));
    } else if (k == "FORM_53") {
        std::vector<Point> corners;
        const int n = static_cast<int>(v(4));
        for (int i = 0; i < n; ++i)
            corners.push_back(Point(v(1), v(2)) + v(3) * direction(v(5) + 360.0 * i / n));
        g.paths.push_back(polyline(corners, true));
    } else if (k == "FORM_54") {
        const Point origin(v(1), v(2)), along = direction(v(4)), up = leftNormal(along);
        const double advance = v(3) / kGlyphHeight * kGlyphAdvance;
        g.closed = false;
        return textStrokes(
            call.text, v(3),
            [&](std::size_t i, Point& base, Point& a, Point& u) {
                base = origin + along * advance * static_cast<double>(i), a = along, u = up;
            },
            g, problem);
    } else if (k == "FORM_55") {
        const Point c(v(1), v(2));
        const double radius = v(3), height = v(5);
        const double step = height / kGlyphHeight * kGlyphAdvance / radius * 180.0 / kPi;
        if (step * static_cast<double>(call.text.size()) > 360.0)
            return problem = "the text is longer than the circle", false;
        g.closed = false;
        return textStrokes(
            call.text, height,
            [&](std::size_t i, Point& base, Point& a, Point& u) {
                const double angle = v(4) - step * static_cast<double>(i);
                u = direction(angle), a = direction(angle - 90.0), base = c + radius * u;
            },
            g, problem);
    } else if (k == "FORM_56" || k == "FORM_57") {
        const bool centred = k == "FORM_57";
        const Point c = centred ? Point(v(1), v(2)) : Point((v(1) + v(3)) / 2, (v(2) + v(4)) / 2);
        const double hl = centred ? v(3) / 2 : std::fabs(v(3) - v(1)) / 2;
        const double hw = centred ? v(4) / 2 : std::fabs(v(4) - v(2)) / 2;
        const double rc = centred ? v(6) : v(5);
        if (hl < kTolerance || hw < kTolerance) return problem = "the rectangle has no area", false;
        if (rc > std::min(hl, hw) + kTolerance)
            return problem = "the corner radius is larger than half a side", false;
        g.paths.push_back(roundedRectangle(c, hl, hw, centred ? v(5) : 0.0, rc));
    } else {
        problem = call.keyword + " is not a form";
        return false;
    }
    return true;
}

}  // namespace mtc::core::gne
