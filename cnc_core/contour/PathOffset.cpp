#include "cnc_core/contour/PathOffset.h"

#include <cmath>
#include <limits>

namespace mtc::core::gne {
namespace {

bool offsetSegment(const Segment& s, int side, double d, Segment& out) {
    out = s;
    if (!s.isArc()) {
        const Point shift = side * d * leftNormal(s.startTangent());
        out.start += shift;
        out.end += shift;
        return true;
    }
    const bool centreLeft = s.kind == Segment::ArcCCW;
    const double r = s.radius() + ((centreLeft == (side > 0)) ? -d : d);
    if (r <= kTolerance) return false;
    out.start = s.centre + (s.start - s.centre).normalized() * r;
    out.end = s.centre + (s.end - s.centre).normalized() * r;
    return true;
}

Locus locusOf(const Segment& s) {
    return s.isArc() ? Locus::around(s.centre, s.radius()) : Locus::line(s.start, s.startTangent());
}

/// Joins offset a and b at the original corner; may append a corner arc.
bool join(Segment& a, Segment& b, const Point& corner, int side, std::vector<Segment>& arcs) {
    if ((a.end - b.start).norm() < 1e-7) {
        b.start = a.end;
        return true;
    }
    const double turn = cross(a.endTangent(), b.startTangent());
    if (turn * side < 0 || std::fabs(turn) < 1e-12) {  // convex: arc around the corner
        arcs.push_back({side > 0 ? Segment::ArcCW : Segment::ArcCCW, a.end, b.start, corner, -1});
        arcs.back().source = a.source;
        return true;
    }
    double best = std::numeric_limits<double>::max();
    bool found = false;
    for (const Point& p : intersect(locusOf(a), locusOf(b))) {
        if ((p - corner).norm() < best) best = (p - corner).norm(), found = true, a.end = p;
    }
    if (!found) return false;
    b.start = a.end;
    return true;
}

}  // namespace

int orientation(const std::vector<Point>& points) {
    double area = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i)
        area += cross(points[i], points[(i + 1) % points.size()]);
    return area >= 0 ? 1 : -1;
}

bool offsetPath(const std::vector<Segment>& path, int side, double distance, bool closed,
                std::vector<Segment>& result, std::string& problem) {
    result.clear();
    if (distance <= 0.0) {
        result = path;
        return true;
    }
    std::vector<Segment> moved(path.size());
    for (std::size_t i = 0; i < path.size(); ++i)
        if (!offsetSegment(path[i], side, distance, moved[i])) {
            problem = "the tool radius is larger than an arc of the contour";
            return false;
        }
    const std::size_t joints = closed ? path.size() : path.size() - 1;
    std::vector<std::vector<Segment>> arcs(path.size());
    for (std::size_t i = 0; i < joints; ++i) {
        const std::size_t j = (i + 1) % path.size();
        if (!join(moved[i], moved[j], path[i].end, side, arcs[i])) {
            problem = "two offset elements do not meet (the tool does not fit into a corner)";
            return false;
        }
    }
    for (std::size_t i = 0; i < moved.size(); ++i) {
        const bool reversed = !moved[i].isArc() &&
                              (moved[i].end - moved[i].start).dot(path[i].end - path[i].start) < 0;
        if (reversed) {
            problem = "the tool does not fit into the contour (an element vanishes)";
            return false;
        }
        result.push_back(moved[i]);
        result.insert(result.end(), arcs[i].begin(), arcs[i].end());
    }
    return true;
}

}  // namespace mtc::core::gne
