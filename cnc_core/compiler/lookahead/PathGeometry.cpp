#include "cnc_core/compiler/lookahead/PathGeometry.h"

#include <algorithm>
#include <cmath>

#include "cnc_core/geometry/ArcSweep.h"

namespace mtc::core::lookahead {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// Largest |cos| and |sin| of the angles between `from` and `from + sweep`.
void trigExtremes(double from, double sweep, double& maxCos, double& maxSin) {
    if (std::abs(sweep) >= 2.0 * kPi - 1e-12) {
        maxCos = maxSin = 1.0;
        return;
    }
    const double lo = std::min(from, from + sweep);
    const double hi = std::max(from, from + sweep);
    maxCos = std::max(std::abs(std::cos(lo)), std::abs(std::cos(hi)));
    maxSin = std::max(std::abs(std::sin(lo)), std::abs(std::sin(hi)));
    // Multiples of pi/2 inside the range are where |cos| or |sin| reach 1.
    for (double k = std::ceil(lo / (kPi / 2)); k * (kPi / 2) <= hi; k += 1.0) {
        const long quarter = static_cast<long>(k);
        if (quarter % 2 == 0)
            maxCos = 1.0;
        else
            maxSin = 1.0;
    }
}

/// Linear motion of the axes outside the arc's plane.
AxisVector offPlaneDelta(const PathElement& e) {
    AxisVector d = e.end - e.start;
    d[e.planeFirst] = 0.0;
    d[e.planeSecond] = 0.0;
    return d;
}

ElementGeometry describeLine(const PathElement& e) {
    ElementGeometry g;
    const AxisVector d = e.end - e.start;
    g.length = d.norm();
    g.maxAbsTangent = g.length > 0.0 ? AxisVector(d.cwiseAbs() / g.length)
                                     : AxisVector(AxisVector::Zero(d.size()));
    g.maxAbsNormal = AxisVector::Zero(d.size());
    return g;
}

ElementGeometry describeArc(const PathElement& e) {
    ElementGeometry g;
    const int p = e.planeFirst, q = e.planeSecond;
    const double sp = e.start[p] - e.center[p], sq = e.start[q] - e.center[q];
    const double ep = e.end[p] - e.center[p], eq = e.end[q] - e.center[q];
    g.radiusStart = std::hypot(sp, sq);
    g.radiusEnd = std::hypot(ep, eq);
    g.angleStart = std::atan2(sq, sp);
    g.sweep = arcSweep(e.start[p], e.start[q], e.end[p], e.end[q], e.center[p], e.center[q],
                       e.kind == ElementKind::ArcCw, e.fullCircle);
    const AxisVector other = offPlaneDelta(e);
    const double radius = 0.5 * (g.radiusStart + g.radiusEnd);
    const double planeLength = radius * std::abs(g.sweep);
    g.length = std::hypot(planeLength, other.norm());
    const double pitch = other.norm() / std::abs(g.sweep);  // per radian
    const double rMin = std::min(g.radiusStart, g.radiusEnd);
    g.curvature = rMin > 0.0 ? rMin / (rMin * rMin + pitch * pitch) : 0.0;
    double maxCos = 0.0, maxSin = 0.0;
    trigExtremes(g.angleStart, g.sweep, maxCos, maxSin);
    const double planeShare =
        g.length > 0.0 ? std::max(g.radiusStart, g.radiusEnd) * std::abs(g.sweep) / g.length : 0.0;
    g.maxAbsTangent = g.length > 0.0 ? AxisVector(other.cwiseAbs() / g.length)
                                     : AxisVector(AxisVector::Zero(other.size()));
    g.maxAbsTangent[p] = std::min(1.0, planeShare * maxSin);
    g.maxAbsTangent[q] = std::min(1.0, planeShare * maxCos);
    g.maxAbsNormal = AxisVector::Zero(other.size());
    g.maxAbsNormal[p] = maxCos;
    g.maxAbsNormal[q] = maxSin;
    return g;
}

}  // namespace

int AxisLimits::indexOf(const std::string& name) const {
    for (size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return static_cast<int>(i);
    return -1;
}

ElementGeometry describeElement(const PathElement& element) {
    return element.kind == ElementKind::Line ? describeLine(element) : describeArc(element);
}

AxisVector pointAt(const PathElement& e, const ElementGeometry& g, double s) {
    const double u = g.length > 0.0 ? std::clamp(s / g.length, 0.0, 1.0) : 0.0;
    if (e.kind == ElementKind::Line) return e.start + u * (e.end - e.start);
    if (u >= 1.0) return e.end;
    AxisVector point = e.start + u * offPlaneDelta(e);
    const double angle = g.angleStart + u * g.sweep;
    const double radius = g.radiusStart + u * (g.radiusEnd - g.radiusStart);
    point[e.planeFirst] = e.center[e.planeFirst] + radius * std::cos(angle);
    point[e.planeSecond] = e.center[e.planeSecond] + radius * std::sin(angle);
    return point;
}

AxisVector tangentAt(const PathElement& e, const ElementGeometry& g, double s) {
    if (e.kind == ElementKind::Line || g.length <= 0.0)
        return g.length > 0.0 ? AxisVector((e.end - e.start) / g.length)
                              : AxisVector(AxisVector::Zero(e.start.size()));
    const double u = std::clamp(s / g.length, 0.0, 1.0);
    const double angle = g.angleStart + u * g.sweep;
    const double radius = g.radiusStart + u * (g.radiusEnd - g.radiusStart);
    const double dr = g.radiusEnd - g.radiusStart;
    AxisVector d = offPlaneDelta(e);
    d[e.planeFirst] = dr * std::cos(angle) - radius * g.sweep * std::sin(angle);
    d[e.planeSecond] = dr * std::sin(angle) + radius * g.sweep * std::cos(angle);
    const double n = d.norm();
    return n > 0.0 ? AxisVector(d / n) : d;
}

AxisVector normalAt(const PathElement& e, const ElementGeometry& g, double s) {
    AxisVector n = AxisVector::Zero(e.start.size());
    if (e.kind == ElementKind::Line || g.length <= 0.0) return n;
    const double u = std::clamp(s / g.length, 0.0, 1.0);
    const double angle = g.angleStart + u * g.sweep;
    n[e.planeFirst] = -std::cos(angle);
    n[e.planeSecond] = -std::sin(angle);
    return n;
}

}  // namespace mtc::core::lookahead
