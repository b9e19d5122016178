#include "cnc_core/compiler/lookahead/RadiusCorrection.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <optional>

#include "cnc_core/geometry/ArcSweep.h"

namespace mtc::core::lookahead {
namespace {

using Vec2 = Eigen::Vector2d;
constexpr double kEps = 1e-9;
constexpr double kPi = 3.14159265358979323846;

double cross(const Vec2& a, const Vec2& b) {
    return a.x() * b.y() - a.y() * b.x();
}
Vec2 leftNormal(const Vec2& t) {
    return Vec2(-t.y(), t.x());
}

struct Planar {
    int p = 0, q = 1;
    Vec2 of(const AxisVector& v) const { return Vec2(v[p], v[q]); }
    void set(AxisVector& v, const Vec2& x) const {
        v[p] = x.x();
        v[q] = x.y();
    }
};

bool isArc(const PathElement& e) {
    return e.kind != ElementKind::Line;
}
double arcDirection(const PathElement& e) {
    return e.kind == ElementKind::ArcCcw ? 1.0 : -1.0;
}

/// Unit tangent in the plane at the start (atEnd = false) or end of `e`.
std::optional<Vec2> planeTangent(const PathElement& e, const Planar& pl, bool atEnd) {
    if (!isArc(e)) {
        const Vec2 d = pl.of(e.end) - pl.of(e.start);
        if (d.norm() < kEps) return std::nullopt;
        return Vec2(d.normalized());
    }
    const Vec2 radial = pl.of(atEnd ? e.end : e.start) - pl.of(e.center);
    if (radial.norm() < kEps) return std::nullopt;
    return Vec2(arcDirection(e) * leftNormal(radial.normalized()));
}

/// Angle from `from` to `to` around `center`, measured in the arc's sense, 0..2pi.
double sweptAngle(const PathElement& e, const Planar& pl, const Vec2& from, const Vec2& to) {
    const Vec2 a = from - pl.of(e.center), b = to - pl.of(e.center);
    double angle = arcDirection(e) * std::atan2(cross(a, b), a.dot(b));
    if (angle < 0) angle += 2 * kPi;
    return angle;
}

/// Position of `x` along element `e` in the plane: 0 at the start, 1 at the end.
double parameterOn(const PathElement& e, const Planar& pl, const Vec2& x) {
    const Vec2 s = pl.of(e.start), t = pl.of(e.end);
    if (!isArc(e)) return (x - s).dot(t - s) / (t - s).squaredNorm();
    const Vec2 c = pl.of(e.center);
    const double sweep = std::abs(arcSweep(s.x(), s.y(), t.x(), t.y(), c.x(), c.y(),
                                           e.kind == ElementKind::ArcCw, e.fullCircle));
    double at = sweptAngle(e, pl, s, x);
    if (at > sweep + 1e-9 && at > 2 * kPi - 1e-9) at -= 2 * kPi;  // just before the start
    return at / sweep;
}

/// Intersections of the (unbounded) line or full circle carrying `a` and `b`.
std::vector<Vec2> intersections(const PathElement& a, const PathElement& b, const Planar& pl) {
    std::vector<Vec2> out;
    if (!isArc(a) && !isArc(b)) {
        const Vec2 p = pl.of(a.start), d = pl.of(a.end) - p;
        const Vec2 r = pl.of(b.start), e = pl.of(b.end) - r;
        const double den = cross(d, e);
        if (std::abs(den) > kEps * d.norm() * e.norm())
            out.push_back(p + d * cross(r - p, e) / den);
        return out;
    }
    if (!isArc(a) || !isArc(b)) {
        const PathElement& l = isArc(a) ? b : a;
        const PathElement& c = isArc(a) ? a : b;
        const Vec2 p = pl.of(l.start), d = (pl.of(l.end) - p).normalized();
        const Vec2 m = pl.of(c.center);
        const double radius = (pl.of(c.start) - m).norm();
        const double along = (m - p).dot(d);
        const Vec2 foot = p + along * d;
        const double h2 = radius * radius - (m - foot).squaredNorm();
        if (h2 < -1e-9) return out;
        const double h = std::sqrt(std::max(0.0, h2));
        out.push_back(foot + h * d);
        out.push_back(foot - h * d);
        return out;
    }
    const Vec2 m1 = pl.of(a.center), m2 = pl.of(b.center);
    const double r1 = (pl.of(a.start) - m1).norm(), r2 = (pl.of(b.start) - m2).norm();
    const double dist = (m2 - m1).norm();
    if (dist < kEps || dist > r1 + r2 + 1e-9 || dist < std::abs(r1 - r2) - 1e-9) return out;
    const double along = (dist * dist + r1 * r1 - r2 * r2) / (2 * dist);
    const double h = std::sqrt(std::max(0.0, r1 * r1 - along * along));
    const Vec2 u = (m2 - m1) / dist;
    const Vec2 base = m1 + along * u;
    out.push_back(base + h * leftNormal(u));
    out.push_back(base - h * leftNormal(u));
    return out;
}

class Corrector {
  public:
    Corrector(const std::vector<PathElement>& contour, const RadiusCorrectionSettings& s)
        : contour_(contour),
          s_(s),
          pl_{s.planeFirst, s.planeSecond},
          sign_(s.side == 2 ? -1.0 : 1.0) {}

    CorrectedPolygon run() {
        if (s_.radius <= 0.0) problem(0, "LA_TRC_NO_RADIUS", "TRC without a tool radius");
        for (size_t k = 0; k < contour_.size() && result_.ok(); ++k)
            offsetElement(k);
        for (size_t k = 0; k + 1 < offset_.size() && result_.ok(); ++k)
            joinCorner(k);
        if (result_.ok()) checkBottlenecks();
        if (result_.ok()) assemble();
        return std::move(result_);
    }

  private:
    void problem(size_t element, const char* code, const char* message) {
        result_.problems.push_back({static_cast<int>(element), code, message});
    }

    void offsetElement(size_t k) {
        const PathElement& e = contour_[k];
        const auto t0 = planeTangent(e, pl_, false), t1 = planeTangent(e, pl_, true);
        if (!t0 || !t1)
            return problem(k, "LA_TRC_NO_PLANE_MOTION", "TRC: block without motion in the plane");
        PathElement o = e;
        if (!isArc(e)) {
            const Vec2 shift = sign_ * s_.radius * leftNormal(*t0);
            pl_.set(o.start, pl_.of(e.start) + shift);
            pl_.set(o.end, pl_.of(e.end) + shift);
        } else {
            const Vec2 m = pl_.of(e.center);
            const double change = -sign_ * arcDirection(e) * s_.radius;
            const Vec2 rs = pl_.of(e.start) - m, re = pl_.of(e.end) - m;
            if (rs.norm() + change <= 1e-6 || re.norm() + change <= 1e-6)
                return problem(k, "LA_TRC_RADIUS_TOO_LARGE", "TRC: tool radius larger than arc");
            pl_.set(o.start, m + rs.normalized() * (rs.norm() + change));
            pl_.set(o.end, m + re.normalized() * (re.norm() + change));
        }
        offset_.push_back(o);
        corners_.emplace_back();
    }

    /// Joins offset elements k and k + 1 at the programmed corner between them.
    void joinCorner(size_t k) {
        PathElement& a = offset_[k];
        PathElement& b = offset_[k + 1];
        const Vec2 end = pl_.of(a.end), start = pl_.of(b.start);
        if ((end - start).norm() < 1e-7) return;
        const Vec2 ta = *planeTangent(contour_[k], pl_, true);
        const Vec2 tb = *planeTangent(contour_[k + 1], pl_, false);
        const double turn = cross(ta, tb);
        if (std::abs(turn) < 1e-12 && ta.dot(tb) < 0)
            return problem(k + 1, "LA_TRC_REVERSAL", "TRC: contour reverses its direction");
        if (sign_ * turn < 0 || (std::abs(turn) < 1e-12)) return insertCornerArc(k);
        trimInsideCorner(k, a, b);
    }

    void insertCornerArc(size_t k) {
        PathElement arc = offset_[k];
        arc.kind = sign_ > 0 ? ElementKind::ArcCw : ElementKind::ArcCcw;
        arc.start = offset_[k].end;
        arc.end = offset_[k].end;
        pl_.set(arc.end, pl_.of(offset_[k + 1].start));
        arc.center = contour_[k].end;
        arc.generated = kCornerArc;
        arc.fullCircle = false;
        corners_[k] = arc;
    }

    void trimInsideCorner(size_t k, PathElement& a, PathElement& b) {
        const Vec2 corner = pl_.of(contour_[k].end);
        std::optional<Vec2> best;
        for (const Vec2& x : intersections(a, b, pl_))
            if (!best || (x - corner).norm() < (*best - corner).norm()) best = x;
        if (!best)
            return problem(k + 1, "LA_TRC_NO_INTERSECTION", "TRC: no intersection at corner");
        const double onA = parameterOn(a, pl_, *best), onB = parameterOn(b, pl_, *best);
        if (onA <= 1e-9 || onA > 1.0 + 1e-9)
            return problem(k, "LA_TRC_ELEMENT_TOO_SHORT", "TRC: block too short for tool radius");
        if (onB < -1e-9 || onB >= 1.0 - 1e-9)
            return problem(k + 1, "LA_TRC_ELEMENT_TOO_SHORT",
                           "TRC: block too short for tool radius");
        pl_.set(a.end, *best);
        pl_.set(b.start, *best);
        a.fullCircle = b.fullCircle = false;  // trimmed: no longer a whole turn
    }

    /// Offset lines within BBTRC elements of each other must not cross.
    void checkBottlenecks() {
        const int window = std::clamp(s_.blockBuffer, 1, 10);
        for (size_t k = 0; k < offset_.size(); ++k) {
            if (isArc(offset_[k])) continue;
            for (size_t j = k + 2; j < offset_.size() && j <= k + window; ++j) {
                if (isArc(offset_[j])) continue;
                for (const Vec2& x : intersections(offset_[k], offset_[j], pl_)) {
                    const double u = parameterOn(offset_[k], pl_, x),
                                 v = parameterOn(offset_[j], pl_, x);
                    if (u > 1e-9 && u < 1 - 1e-9 && v > 1e-9 && v < 1 - 1e-9)
                        return problem(j, "LA_TRC_BOTTLENECK", "TRC: contour too narrow for tool");
                }
            }
        }
    }

    PathElement straight(const AxisVector& from, const AxisVector& to, const PathElement& like,
                         int kind) const {
        PathElement e = like;
        e.kind = ElementKind::Line;
        e.start = from;
        e.end = to;
        e.center = AxisVector::Zero(from.size());
        e.generated = kind;
        return e;
    }

    void assemble() {
        const PathElement& first = offset_.front();
        const PathElement& last = offset_.back();
        const Vec2 t0 = *planeTangent(contour_.front(), pl_, false);
        const Vec2 t1 = *planeTangent(contour_.back(), pl_, true);
        AxisVector approachStart = first.start, retractEnd = last.end;
        pl_.set(approachStart, pl_.of(first.start) - s_.approach * t0);
        pl_.set(retractEnd, pl_.of(last.end) + s_.approach * t1);
        auto& out = result_.elements;
        out.push_back(straight(contour_.front().start, approachStart, contour_.front(), kLeadIn));
        if (s_.approach > 0.0)
            out.push_back(straight(approachStart, first.start, first, kApproachLine));
        for (size_t k = 0; k < offset_.size(); ++k) {
            out.push_back(offset_[k]);
            if (corners_[k]) out.push_back(*corners_[k]);
        }
        if (s_.approach > 0.0) out.push_back(straight(last.end, retractEnd, last, kRetractLine));
        out.push_back(straight(retractEnd, contour_.back().end, contour_.back(), kLeadOut));
    }

    const std::vector<PathElement>& contour_;
    const RadiusCorrectionSettings& s_;
    Planar pl_;
    double sign_;
    std::vector<PathElement> offset_;
    std::vector<std::optional<PathElement>> corners_;
    CorrectedPolygon result_;
};

}  // namespace

CorrectedPolygon correctToolRadius(const std::vector<PathElement>& contour,
                                   const RadiusCorrectionSettings& settings) {
    if (contour.empty()) return {};
    return Corrector(contour, settings).run();
}

}  // namespace mtc::core::lookahead
