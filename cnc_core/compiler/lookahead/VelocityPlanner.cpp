#include "cnc_core/compiler/lookahead/VelocityPlanner.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cnc_core/language/CheckedNumber.h"

namespace mtc::core::lookahead {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kTiny = 1e-12;
constexpr double kContiguityTolerance = 1e-6;  // mm
constexpr double kArcAccelerationShare = 0.5;  // arcs: half for the centripetal part
constexpr double kMinimumPiece = 0.001;        // mm: shortest sub-block (written to 0.0001)

/// Cap of the path velocity (mm/s) from F, the axis velocities and F<axis>=.
double velocityCap(const PathElement& e, const ElementGeometry& g, const AxisLimits& limits) {
    double cap = e.feed / 60.0;
    for (int i = 0; i < limits.size(); ++i) {
        const double share = g.maxAbsTangent[i];
        if (share <= kTiny) continue;
        cap = std::min(cap, limits.maxVelocity[i] / 60.0 / share);
        if (e.axisFeed.size() > i && e.axisFeed[i] > 0.0)
            cap = std::min(cap, e.axisFeed[i] / 60.0 / share);
    }
    return cap;
}

/// Cap (mm/s) that keeps the centripetal acceleration within half of every axis's limit.
double centripetalCap(const ElementGeometry& g, const AxisVector& accel) {
    double cap = kInfinity;
    if (g.curvature <= kTiny) return cap;
    for (int i = 0; i < accel.size(); ++i) {
        const double share = g.maxAbsNormal[i] * g.curvature;
        if (share > kTiny) cap = std::min(cap, std::sqrt(kArcAccelerationShare * accel[i] / share));
    }
    return cap;
}

/// Path acceleration (mm/s^2) that keeps every axis within its limit.
double pathAcceleration(const PathElement& e, const ElementGeometry& g, const AxisVector& accel) {
    const double share = e.kind == ElementKind::Line ? 1.0 : kArcAccelerationShare;
    double a = kInfinity;
    for (int i = 0; i < accel.size(); ++i)
        if (g.maxAbsTangent[i] > kTiny) a = std::min(a, share * accel[i] / g.maxAbsTangent[i]);
    return a * kAccelerationMargin;
}

/// Velocity limit (mm/s) of the transition from element `a` into element `b`.
double junctionVelocity(const PathElement& a, const ElementGeometry& ga, const PathElement& b,
                        const ElementGeometry& gb, const AxisLimits& limits,
                        const LookAheadParameters& parameters) {
    const AxisVector jump = tangentAt(b, gb, 0.0) - tangentAt(a, ga, ga.length);
    const AxisVector accel =
        effectiveAcceleration(a, limits).cwiseMin(effectiveAcceleration(b, limits));
    const AxisVector allowed = transitionVelocityChange(accel, parameters);
    double v = kInfinity;
    for (int i = 0; i < jump.size(); ++i)
        if (std::abs(jump[i]) > kTiny) v = std::min(v, allowed[i] / std::abs(jump[i]));
    return v;
}

bool checkElements(const std::vector<PathElement>& elements, const AxisLimits& limits,
                   LookAheadPlan& plan) {
    for (int i = 0; i < limits.size(); ++i)
        if (!(limits.maxVelocity[i] > 0.0) || !(limits.maxAcceleration[i] > 0.0) ||
            !std::isfinite(limits.maxVelocity[i]) || !std::isfinite(limits.maxAcceleration[i])) {
            plan.problems.push_back({0, "LA_AXIS_LIMITS", "axis without velocity or acceleration"});
            return false;
        }
    for (size_t k = 0; k < elements.size(); ++k) {
        const PathElement& e = elements[k];
        const int id = static_cast<int>(k);
        if (e.start.size() != limits.size() || e.end.size() != limits.size())
            plan.problems.push_back({id, "LA_AXES", "element axes differ from the axis table"});
        else if (e.feed <= 0.0)
            plan.problems.push_back({id, "LA_NO_FEED", "no path velocity F programmed"});
        else if (plan.geometry[k].length <= kContiguityTolerance)
            plan.problems.push_back({id, "LA_ZERO_LENGTH", "motion block without path length"});
        else if (k > 0 && (elements[k - 1].end - e.start).norm() > kContiguityTolerance)
            plan.problems.push_back(
                {id, "LA_NOT_CONTIGUOUS", "block does not start at the end of the previous one"});
    }
    return plan.problems.empty();
}

/// Node velocities (mm/s) after the backward and forward passes.
std::vector<double> nodeVelocities(const std::vector<double>& caps, const LookAheadPlan& plan,
                                   const std::vector<double>& accel) {
    const size_t n = caps.size();
    std::vector<double> v(n + 1, 0.0);
    for (size_t j = 1; j < n; ++j)
        v[j] = std::min({plan.junctionLimit[j], caps[j - 1], caps[j]});
    for (size_t k = n; k-- > 0;)
        v[k] = std::min(v[k],
                        std::sqrt(v[k + 1] * v[k + 1] + 2.0 * accel[k] * plan.geometry[k].length));
    for (size_t k = 0; k < n; ++k)
        v[k + 1] =
            std::min(v[k + 1], std::sqrt(v[k] * v[k] + 2.0 * accel[k] * plan.geometry[k].length));
    return v;
}

/// Candidate split positions of one element: ramp steps of equal velocity change.
std::vector<double> splitCandidates(const ElementProfile& p,
                                    const LookAheadParameters& parameters) {
    std::vector<double> cuts{0.0};
    const double stepTime = 2.0 * parameters.metbMs / 1000.0;
    auto ramp = [&](double vFrom, double vTo, double sFrom, double sTo) {
        const double rampTime = std::abs(vTo - vFrom) / p.acceleration;
        const int steps =
            clampedInteger(rampTime / stepTime, 1, std::max(1, parameters.maxSubBlocksPerRamp));
        for (int m = 1; m < steps; ++m) {
            const double v = vFrom + (vTo - vFrom) * m / steps;
            const double s = vTo > vFrom ? (v * v - vFrom * vFrom) / (2.0 * p.acceleration)
                                         : (vFrom * vFrom - v * v) / (2.0 * p.acceleration);
            cuts.push_back(sFrom + std::min(s, sTo - sFrom));
        }
        cuts.push_back(sTo);
    };
    if (p.rampUpEnd > 0.0) ramp(p.vStart, p.velocityAt(p.rampUpEnd), 0.0, p.rampUpEnd);
    if (p.rampDownStart > p.rampUpEnd) cuts.push_back(p.rampDownStart);
    if (p.rampDownStart < p.length)
        ramp(p.velocityAt(p.rampDownStart), p.vEnd, p.rampDownStart, p.length);
    cuts.push_back(p.length);
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end(),
                           [](double x, double y) { return std::abs(x - y) < 1e-9; }),
               cuts.end());
    return cuts;
}

/// Feed to program for a peak velocity: mm/min rounded down to 0.1.
double programmedFeed(double peakMmPerSecond) {
    return std::max(0.1, std::floor(peakMmPerSecond * 600.0 + 1e-9) / 10.0);
}

/// Drops cuts between two pieces that would get the same F.
std::vector<double> mergeEqualFeeds(const ElementProfile& p, const std::vector<double>& cuts) {
    std::vector<double> kept{cuts.front()};
    for (size_t i = 1; i + 1 < cuts.size(); ++i) {
        const double left = programmedFeed(p.peakOn(kept.back(), cuts[i]));
        const double right = programmedFeed(p.peakOn(cuts[i], cuts[i + 1]));
        if (left != right) kept.push_back(cuts[i]);
    }
    kept.push_back(cuts.back());
    return kept;
}

/// Merges candidate pieces until every piece lasts at least METB at its F.
std::vector<double> mergeShortPieces(const ElementProfile& p, const std::vector<double>& cuts,
                                     double metbSeconds) {
    std::vector<double> kept{0.0};
    for (size_t i = 1; i < cuts.size(); ++i) {
        const double from = kept.back(), to = cuts[i];
        const double peak = p.peakOn(from, to);
        if (peak > 0.0 && (to - from) / peak >= metbSeconds && to - from >= kMinimumPiece)
            kept.push_back(to);
    }
    if (kept.back() < p.length) {
        if (kept.size() > 1) kept.pop_back();
        kept.push_back(p.length);
    }
    return kept;
}

void emitBlocks(const std::vector<PathElement>& elements, const LookAheadParameters& parameters,
                LookAheadPlan& plan) {
    double sOffset = 0.0;
    for (size_t k = 0; k < elements.size(); ++k) {
        const ElementProfile& p = plan.profiles[k];
        const ElementGeometry& g = plan.geometry[k];
        const std::vector<double> cuts = mergeEqualFeeds(
            p, mergeShortPieces(p, splitCandidates(p, parameters), parameters.metbMs / 1000.0));
        const int count = static_cast<int>(cuts.size()) - 1;
        for (int m = 0; m < count; ++m) {
            PlannedBlock b;
            b.element = static_cast<int>(k);
            b.subIndex = m;
            b.subCount = count;
            b.sStart = sOffset + cuts[m];
            b.sEnd = sOffset + cuts[m + 1];
            b.vStart = p.velocityAt(cuts[m]) * 60.0;
            b.vEnd = p.velocityAt(cuts[m + 1]) * 60.0;
            b.vMax = p.vMax * 60.0;
            b.feed = programmedFeed(p.peakOn(cuts[m], cuts[m + 1]));
            b.time = p.timeTo(cuts[m + 1]) - p.timeTo(cuts[m]);
            b.start = m == 0 ? elements[k].start : pointAt(elements[k], g, cuts[m]);
            b.end = m + 1 == count ? elements[k].end : pointAt(elements[k], g, cuts[m + 1]);
            plan.totalTime += b.time;
            plan.blocks.push_back(std::move(b));
        }
        sOffset += g.length;
    }
    plan.totalLength = sOffset;
}

}  // namespace

AxisVector effectiveAcceleration(const PathElement& element, const AxisLimits& limits) {
    return limits.maxAcceleration * element.accelerationFactor;
}

AxisVector transitionVelocityChange(const AxisVector& acceleration,
                                    const LookAheadParameters& parameters) {
    return acceleration * (2.0 * parameters.vfbt * parameters.blockCycleMs / 1000.0);
}

LookAheadPlan planVelocityProfile(const std::vector<PathElement>& elements,
                                  const AxisLimits& limits, const LookAheadParameters& parameters) {
    LookAheadPlan plan;
    plan.geometry.reserve(elements.size());
    for (const PathElement& e : elements)
        plan.geometry.push_back(describeElement(e));
    if (elements.empty() || !checkElements(elements, limits, plan)) return plan;
    const size_t n = elements.size();
    std::vector<double> caps(n), accel(n);
    const double metbSeconds = parameters.metbMs / 1000.0;
    for (size_t k = 0; k < n; ++k) {
        const ElementGeometry& g = plan.geometry[k];
        const AxisVector axisAccel = effectiveAcceleration(elements[k], limits);
        caps[k] = std::min({velocityCap(elements[k], g, limits), centripetalCap(g, axisAccel),
                            g.length / metbSeconds});
        accel[k] = pathAcceleration(elements[k], g, axisAccel);
    }
    plan.junctionLimit.assign(n + 1, 0.0);
    for (size_t j = 1; j < n; ++j)
        plan.junctionLimit[j] = junctionVelocity(elements[j - 1], plan.geometry[j - 1], elements[j],
                                                 plan.geometry[j], limits, parameters);
    const std::vector<double> v = nodeVelocities(caps, plan, accel);
    plan.profiles.resize(n);
    for (size_t k = 0; k < n; ++k)
        plan.profiles[k].shape(plan.geometry[k].length, v[k], v[k + 1], caps[k], accel[k]);
    emitBlocks(elements, parameters, plan);
    return plan;
}

}  // namespace mtc::core::lookahead
