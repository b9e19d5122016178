// Transitions between solved contour elements: RD (rounding), CF (chamfer)
// and RELIEF (DIN 509 relief groove, forms E and F).

#include <cmath>
#include <limits>

#include "cnc_core/contour/ContourSolver.h"

namespace mtc::core::gne {
namespace {

constexpr double kOnTolerance = 1e-6;

bool onSegment(const Segment& s, const Point& p) {
    return distanceTo(s, p) < kOnTolerance;
}

/// The segment shifted by `distance` to the left (side > 0) or right.
bool offsetLocus(const Segment& s, int side, double distance, Locus& locus) {
    if (!s.isArc()) {
        const Point d = s.startTangent();
        locus = Locus::line(s.start + side * distance * leftNormal(d), d);
        return true;
    }
    const bool centreLeft = s.kind == Segment::ArcCCW;
    const double r = s.radius() + ((centreLeft == (side > 0)) ? -distance : distance);
    locus = Locus::around(s.centre, r);
    return r > kTolerance;
}

Point footOn(const Segment& s, const Point& p) {
    if (s.isArc()) return s.centre + (p - s.centre).normalized() * s.radius();
    const Point d = s.startTangent();
    return s.start + d * d.dot(p - s.start);
}

std::string roundCorner(Segment& a, Segment& b, double r, std::vector<Segment>& inserted) {
    const double turn = cross(a.endTangent(), b.startTangent());
    if (std::fabs(turn) < 1e-9) return "there is no corner to round (tangential transition)";
    const int side = turn > 0 ? 1 : -1;
    Locus la, lb;
    if (!offsetLocus(a, side, r, la) || !offsetLocus(b, side, r, lb))
        return "the radius is larger than the arc it meets";
    const Point corner = a.end;
    double best = std::numeric_limits<double>::max();
    std::optional<Point> centre;
    for (const Point& c : intersect(la, lb)) {
        const Point t1 = footOn(a, c), t2 = footOn(b, c);
        if (!onSegment(a, t1) || !onSegment(b, t2)) continue;
        if ((c - corner).norm() < best) best = (c - corner).norm(), centre = c;
    }
    if (!centre) return "the rounding does not fit between its neighbours";
    a.end = footOn(a, *centre);
    b.start = footOn(b, *centre);
    inserted.push_back({side > 0 ? Segment::ArcCCW : Segment::ArcCW, a.end, b.start, *centre, -1});
    return {};
}

/// The point at chord distance `w` from the segment's end (fromEnd) or start.
std::optional<Point> pointAtDistance(const Segment& s, double w, bool fromEnd) {
    const Point anchor = fromEnd ? s.end : s.start;
    if (!s.isArc()) {
        if (w >= s.length() - kOnTolerance) return std::nullopt;
        const Point d = s.startTangent();
        return fromEnd ? Point(anchor - w * d) : Point(anchor + w * d);
    }
    for (const Point& p : intersect(Locus::around(anchor, w), Locus::around(s.centre, s.radius())))
        if (onSegment(s, p) && (p - (fromEnd ? s.start : s.end)).norm() > kOnTolerance &&
            Segment{s.kind, fromEnd ? s.start : p, fromEnd ? p : s.end, s.centre, -1}.sweep() <
                s.sweep())
            return p;
    return std::nullopt;
}

std::string chamferCorner(Segment& a, Segment& b, double w, std::vector<Segment>& inserted) {
    if (std::fabs(cross(a.endTangent(), b.startTangent())) < 1e-9)
        return "there is no corner to chamfer (tangential transition)";
    const auto t1 = pointAtDistance(a, w, true), t2 = pointAtDistance(b, w, false);
    if (!t1 || !t2) return "the chamfer is wider than its neighbours";
    a.end = *t1;
    b.start = *t2;
    inserted.push_back({Segment::Line, a.end, b.start, Point::Zero(), -1});
    return {};
}

/// DIN 509 sizes r x t1 with width f and face depth t2 (forms E and F).
struct ReliefSize {
    double r, t1, f, t2;
};
constexpr ReliefSize kDin509[] = {
    {0.2, 0.1, 1.0, 0.1}, {0.4, 0.2, 2.0, 0.1}, {0.6, 0.2, 2.0, 0.1}, {0.6, 0.3, 2.5, 0.2},
    {0.8, 0.3, 2.5, 0.2}, {1.0, 0.2, 2.5, 0.1}, {1.0, 0.4, 4.0, 0.3}, {1.2, 0.2, 2.5, 0.1},
    {1.6, 0.3, 4.0, 0.2}, {2.5, 0.4, 5.0, 0.3}, {4.0, 0.5, 7.0, 0.3},
};

const ReliefSize* din509(double r, double t1) {
    for (const ReliefSize& s : kDin509)
        if (std::fabs(s.r - r) < 1e-9 && std::fabs(s.t1 - t1) < 1e-9) return &s;
    return nullptr;
}

std::string reliefCorner(const ContourElement& e, Segment& a, Segment& b,
                         std::vector<Segment>& inserted) {
    if (a.isArc() || b.isArc()) return "RELIEF needs a straight cylinder and a straight face";
    const Point u = a.endTangent(), n = b.startTangent();
    if (std::fabs(u.dot(n)) > 1e-6) return "RELIEF needs a right-angled corner";
    const ReliefSize* size = din509(*e.radius, *e.depth);
    if (!size && !e.width) return "R and T are not a DIN 509 size: give the width W";
    const double r = *e.radius, t = *e.depth, f = e.width.value_or(size ? size->f : 0.0);
    const double t2 = e.reliefForm == 'F' ? e.faceDepth.value_or(size ? size->t2 : 0.1) : 0.0;
    const double ramp = t / std::tan(15.0 * kPi / 180.0);
    if (f + t2 < r + ramp) return "the width W is too small for R, T and the 15 degree run-out";
    if (f >= a.length() - kOnTolerance) return "the relief is wider than the cylinder";
    const Point c = a.end;
    const int side = cross(u, n) > 0 ? 1 : -1;
    const Point p1 = c - u * f, p2 = p1 + u * ramp - n * t;
    const Point q1 = c + u * (t2 - r) - n * t, k = q1 + n * r, q2 = k + u * r;
    const double rise = std::max(0.0, r - t);
    if (rise + 2 * t2 >= b.length() - kOnTolerance) return "the relief is higher than the face";
    a.end = p1;
    inserted.push_back({Segment::Line, p1, p2, Point::Zero(), -1});
    inserted.push_back({Segment::Line, p2, q1, Point::Zero(), -1});
    inserted.push_back({side > 0 ? Segment::ArcCCW : Segment::ArcCW, q1, q2, k, -1});
    Point last = q2;
    if (t2 > 0) {  // form F: back to the face with a 2:1 ramp
        last = c + n * (rise + 2 * t2);
        inserted.push_back({Segment::Line, q2, last, Point::Zero(), -1});
    } else if (r < t) {
        last = c;
        inserted.push_back({Segment::Line, q2, c, Point::Zero(), -1});
    }
    b.start = last;
    return {};
}

}  // namespace

void applyTransitions(const Contour& contour, std::vector<Segment> primary,
                      ContourSolution& solution) {
    const auto& elements = contour.elements;
    std::vector<Segment> path;
    std::size_t next = 0;  // next primary segment to take
    for (std::size_t i = 0; i < elements.size(); ++i) {
        if (next < primary.size() && primary[next].source == static_cast<int>(i)) {
            path.push_back(primary[next++]);
            continue;
        }
        const ContourElement& e = elements[i];
        if (e.kind == ElementKind::Start) continue;
        ElementSolution& out = solution.elements[i];
        std::string problem;
        std::vector<Segment> inserted;
        const bool between =
            !path.empty() && next < primary.size() && path.back().source == static_cast<int>(i) - 1;
        if (!between)
            problem = "needs a LINE, CW or CCW directly before and after it";
        else if (e.kind == ElementKind::Round)
            problem = roundCorner(path.back(), primary[next], *e.radius, inserted);
        else if (e.kind == ElementKind::Chamfer)
            problem = chamferCorner(path.back(), primary[next], *e.width, inserted);
        else
            problem = reliefCorner(e, path.back(), primary[next], inserted);
        out.state = problem.empty() ? ElementState::Solved : ElementState::Impossible;
        out.message = problem;
        if (!problem.empty()) {
            solution.diagnostics.push_back(
                {e.line, "GNE_IMPOSSIBLE", std::string(elementKeyword(e.kind)) + ": " + problem});
            continue;
        }
        for (Segment& s : inserted)
            s.source = static_cast<int>(i);
        path.insert(path.end(), inserted.begin(), inserted.end());
    }
    for (const Segment& s : path)
        solution.elements[static_cast<std::size_t>(s.source)].segments.push_back(s);
    if (solution.diagnostics.empty()) solution.path = std::move(path);
}

}  // namespace mtc::core::gne
