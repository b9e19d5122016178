// CYCLE_10 (contour cut), CYCLE_11 (roughing) and CYCLE_12 (residual cut)
// of the turning plane (G18: 1st coordinate Z, 2nd coordinate X as radius).

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "cnc_core/contour/CycleSupport.h"
#include "cnc_core/contour/PathOffset.h"

namespace mtc::core::gne {
namespace {

bool turningInput(const CycleInput& in, std::string& problem) {
    if (!in.stock.known || in.stock.plane != GnePlane::Turning)
        return problem = "needs WINDOW_01 (the blank) before it", false;
    if (in.geometry->strokes || in.geometry->paths.size() != 1)
        return problem = "machines one contour", false;
    return true;
}

/// The outline of the part: the contour closed along the bore (XMIN).
std::vector<Point> partOutline(const Geometry& g, const Stock& stock, double chord) {
    std::vector<Point> points = tessellate(g.paths[0], chord);
    if (!g.closed) {
        const Point last = points.back(), first = points.front();
        points.push_back({last.x(), stock.low.y()});
        points.push_back({first.x(), stock.low.y()});
    } else {
        points.pop_back();
    }
    return points;
}

/// Left (+1) or right (-1) of the travel direction: the side without material.
int freeSide(const Geometry& g, const Stock& stock) {
    return -orientation(partOutline(g, stock, 0.01));
}

/// Interval of the 1st coordinate where the horizontal line at `v` comes
/// within distance 1 of the segment p-q (coordinates already scaled).
bool capsuleInterval(const Point& p, const Point& q, double v, double& lo, double& hi) {
    lo = std::numeric_limits<double>::max();
    hi = -lo;
    auto take = [&](double u) { lo = std::min(lo, u), hi = std::max(hi, u); };
    for (const Point& c : {p, q}) {
        const double dv = v - c.y();
        if (std::fabs(dv) <= 1.0) {
            const double w = std::sqrt(1.0 - dv * dv);
            take(c.x() - w), take(c.x() + w);
        }
    }
    const Point d = q - p;
    if (d.norm() > 1e-12) {
        const Point n = leftNormal(d.normalized());
        for (double s : {1.0, -1.0}) {
            const Point base = p + s * n;
            if (std::fabs(d.y()) > 1e-12) {
                const double t = (v - base.y()) / d.y();
                if (t >= 0.0 && t <= 1.0) take(base.x() + t * d.x());
            }
        }
    }
    return lo <= hi;
}

/// Where a pass of the nose centre at height `yc` moving towards -Z from
/// `zStart` is stopped by the allowance region around the outline.
struct Roughing {
    std::vector<Point> scaled;  ///< outline points scaled by the allowances
    double az = 1, ax = 1, radius = 0;

    /// Largest blocked centre Z below zStart; -inf when nothing blocks; +inf when blocked at once.
    double stop(double yc, double zStart) const {
        double stop = -std::numeric_limits<double>::infinity();
        const int samples = radius > 0 ? 48 : 1;
        for (int j = 0; j < samples; ++j) {
            const double a = 2.0 * kPi * j / samples;
            const double h = yc + radius * std::sin(a), dz = radius * std::cos(a);
            for (std::size_t i = 0; i < scaled.size(); ++i) {
                double lo = 0.0, hi = 0.0;
                if (!capsuleInterval(scaled[i], scaled[(i + 1) % scaled.size()], h / ax, lo, hi))
                    continue;
                const double zLo = lo * az - dz, zHi = hi * az - dz;
                if (zLo <= zStart && zHi >= zStart) return std::numeric_limits<double>::infinity();
                if (zHi < zStart) stop = std::max(stop, zHi);
            }
        }
        return stop;
    }
};

/// The largest Z of the closed `outline` between the heights `low` and
/// `high` (where a pass in that band first meets the material), -inf when
/// the outline does not reach into the band.
double rightmostMaterial(const std::vector<Point>& outline, double low, double high) {
    double right = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < outline.size(); ++i) {
        const Point& p = outline[i];
        const Point& q = outline[(i + 1) % outline.size()];
        if (std::max(p.y(), q.y()) < low || std::min(p.y(), q.y()) > high) continue;
        const double dy = q.y() - p.y();
        if (std::fabs(dy) < 1e-12) {
            right = std::max({right, p.x(), q.x()});
            continue;
        }
        // the part of the edge inside the band: Z is linear in the height
        for (double y : {std::clamp(low, std::min(p.y(), q.y()), std::max(p.y(), q.y())),
                         std::clamp(high, std::min(p.y(), q.y()), std::max(p.y(), q.y()))})
            right = std::max(right, p.x() + (q.x() - p.x()) * (y - p.y()) / dy);
    }
    return right;
}

}  // namespace

bool turningContourCut(const CycleInput& in, double allowance, BlockWriter& out,
                       std::string& problem) {
    if (!turningInput(in, problem)) return false;
    const Geometry& g = *in.geometry;
    const int side = freeSide(g, in.stock);
    const double radius = in.value(kCycleToolRadius), clearance = in.value(kCycleClearance);
    std::vector<Segment> centre;
    if (!offsetPath(g.paths[0], side, allowance + radius, g.closed, centre, problem)) return false;
    const std::vector<Segment> tip =
        translated(centre, radius * edgeVector(static_cast<int>(in.value(kCycleEdge))));
    const Point start = tip.front().start, end = tip.back().end;
    const Point approach = start + clearance * side * leftNormal(tip.front().startTangent());
    const Point retract = end + clearance * side * leftNormal(tip.back().endTangent());
    const Point safe = in.stock.high + Point(clearance, clearance) + radius * Point(2, 2);
    out.rapid(safe);
    out.rapid({safe.x(), approach.y()});
    out.rapid(approach);
    out.feed(start, in.value(kCycleFeed));
    for (const Segment& s : tip)
        out.segment(s);
    out.segment({Segment::Line, end, retract, Point::Zero(), -1});
    out.rapid({retract.x(), std::max(safe.y(), retract.y())});
    out.rapid(safe);
    return true;
}

bool turningRoughing(const CycleInput& in, BlockWriter& out, std::string& problem) {
    if (!turningInput(in, problem)) return false;
    const Geometry& g = *in.geometry;
    Roughing r;
    // The outline is tessellated with a chord error of 0.002 mm: the
    // allowances grow by that much so that the true arcs stay outside too.
    constexpr double kChord = 0.002;
    r.az = std::max(in.value(kCycleAllowanceZ), 0.0) + kChord;
    r.ax = std::max(in.value(kCycleAllowanceX), 0.0) + kChord;
    r.radius = in.value(kCycleToolRadius);
    for (const Point& p : partOutline(g, in.stock, kChord))
        r.scaled.emplace_back(p.x() / r.az, p.y() / r.ax);
    const double clearance = in.value(kCycleClearance), depth = in.value(kCycleDepth);
    const Point tipShift = r.radius * edgeVector(static_cast<int>(in.value(kCycleEdge)));
    const double zStart = in.stock.high.x() + clearance + r.radius;
    double minZ = std::numeric_limits<double>::max();
    for (const Point& p : tessellate(g.paths[0]))
        minZ = std::min(minZ, p.x());
    const double zLimit = std::max(in.stock.low.x(), minZ) + r.radius;
    // G-007: a RAW contour before the cycle is the blank: passes start where
    // its material starts and do not go above it
    std::vector<Point> raw;
    if (in.rawBlank) raw = partOutline(*in.rawBlank, in.stock, kChord);
    double top = in.stock.high.y();
    if (!raw.empty()) {
        double rawTop = -std::numeric_limits<double>::infinity();
        for (const Point& p : raw)
            rawTop = std::max(rawTop, p.y());
        top = std::min(top, rawTop);
    }
    const double bottom = in.stock.low.y() + in.value(kCycleAllowanceX);
    if (bottom >= top) return problem = "the allowance leaves nothing to rough", false;
    const double levelCount = std::ceil((top - bottom) / depth - 1e-9);
    if (!(levelCount <= kMaxRoughingPasses))
        return problem =
                   "needs more than " + std::to_string(kMaxRoughingPasses) + " passes: raise DEPTH",
               false;
    const int levels = static_cast<int>(levelCount);
    const double step = (top - bottom) / levels;
    const Point safe = in.stock.high + Point(clearance, clearance) + r.radius * Point(2, 2);
    out.rapid(safe);
    int passes = 0;
    for (int k = 1; k <= levels; ++k) {
        const double yc = top - k * step + r.radius;
        double zEnd = r.stop(yc, zStart);
        if (!std::isfinite(zEnd) && zEnd > 0) continue;  // blocked at once
        zEnd = std::max(zEnd + 1e-3, zLimit);
        if (zEnd - r.radius >= in.stock.high.x() - 1e-6) continue;  // no blank left at this level
        const double lift = std::min(clearance, step);
        double passStart = zStart;
        if (!raw.empty()) {  // the nose band of the pass and its lifted return
            const double material =
                rightmostMaterial(raw, yc - r.radius, yc + std::max(r.radius, lift));
            passStart = std::min(zStart, material + r.radius + clearance);
            if (passStart <= zEnd + 1e-6) continue;  // no raw material to cut at this level
        }
        out.rapid(Point(zStart, yc) + tipShift);
        if (passStart < zStart) out.rapid(Point(passStart, yc) + tipShift);
        out.feed(Point(zEnd, yc) + tipShift, in.value(kCycleFeed));
        out.segment({Segment::Line, Point(zEnd, yc) + tipShift,
                     Point(zEnd + lift, yc + lift) + tipShift, Point::Zero(), -1});
        out.rapid(Point(zStart, yc + lift) + tipShift);
        ++passes;
    }
    out.rapid(safe);
    if (passes == 0) return problem = "there is no blank outside the allowance", false;
    return true;
}

}  // namespace mtc::core::gne
