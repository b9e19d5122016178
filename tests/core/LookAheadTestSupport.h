#pragma once

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <sstream>
#include <string>
#include <vector>

#include "cnc_core/compiler/lookahead/VelocityPlanner.h"

/// Builders for look-ahead polygons and an independent numerical check of a
/// plan against the axis limits (tests only).
namespace mtc::core::lookahead::testing {

inline AxisVector point(std::initializer_list<double> values) {
    AxisVector p = AxisVector::Zero(static_cast<int>(values.size()));
    int i = 0;
    for (double v : values)
        p[i++] = v;
    return p;
}

/// X Y Z with the demo mill's limits (30000/30000/20000 mm/min, 2500/2500/2000 mm/s^2).
inline AxisLimits millLimits() {
    AxisLimits limits;
    limits.names = {"X", "Y", "Z"};
    limits.maxVelocity = point({30000, 30000, 20000});
    limits.maxAcceleration = point({2500, 2500, 2000});
    return limits;
}

inline PathElement line(const AxisVector& from, const AxisVector& to, double feed) {
    PathElement e;
    e.kind = ElementKind::Line;
    e.start = from;
    e.end = to;
    e.center = AxisVector::Zero(from.size());
    e.axisFeed = AxisVector::Zero(from.size());
    e.feed = feed;
    return e;
}

inline PathElement arc(const AxisVector& from, const AxisVector& to, const AxisVector& center,
                       bool clockwise, double feed) {
    PathElement e = line(from, to, feed);
    e.kind = clockwise ? ElementKind::ArcCw : ElementKind::ArcCcw;
    e.center = center;
    return e;
}

/// A polyline through `points` (X Y Z) at feed `feed`.
inline std::vector<PathElement> polyline(const std::vector<AxisVector>& points, double feed) {
    std::vector<PathElement> elements;
    for (size_t i = 1; i < points.size(); ++i)
        elements.push_back(line(points[i - 1], points[i], feed));
    return elements;
}

/// Everything in `plan` that breaks a limit, one line each (empty = fine).
/// Checks, independently of the planner's caps: the sampled profile (axis
/// velocity and acceleration incl. the centripetal part), the transitions
/// (VFBT), the F sequence (each change of F fits into one block at the
/// axes' acceleration), block times >= METB and F <= F<axis> / programmed F.
inline std::vector<std::string> limitViolations(const LookAheadPlan& plan,
                                                const std::vector<PathElement>& elements,
                                                const AxisLimits& limits,
                                                const LookAheadParameters& parameters) {
    std::vector<std::string> out;
    auto fail = [&](const std::string& what, int index, double value, double limit) {
        std::ostringstream s;
        s << what << " at " << index << ": " << value << " > " << limit;
        out.push_back(s.str());
    };
    const double rel = 1.0 + 1e-9;
    for (size_t k = 0; k < elements.size(); ++k) {
        const PathElement& e = elements[k];
        const ElementGeometry g = describeElement(e);
        const ElementProfile& p = plan.profiles[k];
        const AxisVector accel = limits.maxAcceleration * e.accelerationFactor;
        const int samples = 200;
        for (int m = 0; m < samples; ++m) {
            const double s0 = g.length * m / samples, s1 = g.length * (m + 1) / samples;
            const double v0 = p.velocityAt(s0), v1 = p.velocityAt(s1);
            const double at = (v1 * v1 - v0 * v0) / (2.0 * (s1 - s0));
            for (double s : {s0, s1}) {
                const double v = p.velocityAt(s);
                const AxisVector t = tangentAt(e, g, s), n = normalAt(e, g, s);
                for (int i = 0; i < limits.size(); ++i) {
                    if (std::abs(v * t[i]) * 60.0 > limits.maxVelocity[i] * rel)
                        fail("axis velocity " + limits.names[i], int(k), std::abs(v * t[i]) * 60.0,
                             limits.maxVelocity[i]);
                    const double ai = std::abs(at * t[i] + v * v * g.curvature * n[i]);
                    if (ai > accel[i] * (1.0 + 1e-6))
                        fail("axis acceleration " + limits.names[i], int(k), ai, accel[i]);
                }
            }
        }
        if (p.velocityAt(g.length) > 0.0 && k + 1 < elements.size()) {
            const ElementGeometry gn = describeElement(elements[k + 1]);
            const AxisVector jump = tangentAt(elements[k + 1], gn, 0.0) - tangentAt(e, g, g.length);
            const double v = p.velocityAt(g.length);
            const AxisVector nextAccel =
                limits.maxAcceleration * elements[k + 1].accelerationFactor;
            for (int i = 0; i < limits.size(); ++i) {
                const double allowed = 2.0 * std::min(accel[i], nextAccel[i]) * parameters.vfbt *
                                       parameters.blockCycleMs / 1000.0;
                if (v * std::abs(jump[i]) > allowed * (1.0 + 1e-6))
                    fail("transition jump " + limits.names[i], int(k), v * std::abs(jump[i]),
                         allowed);
            }
        }
    }
    // The F sequence of the emitted blocks.
    for (size_t b = 0; b < plan.blocks.size(); ++b) {
        const PlannedBlock& block = plan.blocks[b];
        const PathElement& e = elements[block.element];
        const ElementGeometry g = describeElement(e);
        const double length = block.sEnd - block.sStart;
        if (length / (block.feed / 60.0) * 1000.0 < parameters.metbMs * (1.0 - 1e-9))
            fail("block time at F below METB", int(b), parameters.metbMs,
                 length / (block.feed / 60.0) * 1000.0);
        if (block.time * 1000.0 < parameters.metbMs * (1.0 - 1e-9))
            fail("profile time below METB", int(b), parameters.metbMs, block.time * 1000.0);
        if (block.feed > e.feed * rel) fail("F above programmed F", int(b), block.feed, e.feed);
        for (int i = 0; i < limits.size(); ++i) {
            const double v = block.feed * g.maxAbsTangent[i];
            if (v > limits.maxVelocity[i] * rel)
                fail("F axis velocity", int(b), v, limits.maxVelocity[i]);
            if (e.axisFeed[i] > 0.0 && v > e.axisFeed[i] * rel)
                fail("F above F<axis>", int(b), v, e.axisFeed[i]);
        }
        const double fPrev = b == 0 ? 0.0 : plan.blocks[b - 1].feed / 60.0;
        const double f = block.feed / 60.0;
        const double fNext = b + 1 == plan.blocks.size() ? 0.0 : plan.blocks[b + 1].feed / 60.0;
        const double share = e.kind == ElementKind::Line ? 1.0 : 0.5;
        double aPath = 1e300;
        for (int i = 0; i < limits.size(); ++i)
            if (g.maxAbsTangent[i] > 1e-12)
                aPath = std::min(aPath, share * limits.maxAcceleration[i] * e.accelerationFactor /
                                            g.maxAbsTangent[i]);
        if (f * f - fPrev * fPrev > 2.0 * aPath * length * (1.0 + 1e-6))
            fail("acceleration into block", int(b), f * f - fPrev * fPrev, 2.0 * aPath * length);
        if (f * f - fNext * fNext > 2.0 * aPath * length * (1.0 + 1e-6))
            fail("deceleration within block", int(b), f * f - fNext * fNext, 2.0 * aPath * length);
    }
    return out;
}

}  // namespace mtc::core::lookahead::testing
