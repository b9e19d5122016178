#include "cnc_core/toolpath/ToolpathBuilder.h"

#include <algorithm>
#include <cmath>

#include "cnc_core/geometry/ArcSweep.h"
#include "cnc_core/toolpath/CurveMath.h"

namespace mtc::core {

/// The transformation of one move: which plane axes are linear / rotary.
struct ToolpathBuilder::Transform {
    int kind = 30;
    int linear = -1;  ///< G31/G32: the linear plane axis (-1: both rotary)
    int rotary = -1;  ///< G31/G32: the rotary plane axis
    int axis1 = -1, axis2 = -1;
    double radius = 0.0;  ///< RI (G32)
};

namespace {
int sceneAxisOfDefinition(AxisDefinition definition) {
    switch (definition) {
        case AxisDefinition::X:
            return 0;
        case AxisDefinition::Y:
            return 1;
        case AxisDefinition::Z:
            return 2;
        default:
            return -1;
    }
}

ToolpathKind kindOf(MotionType type) {
    switch (type) {
        case MotionType::Rapid:
            return ToolpathKind::Rapid;
        case MotionType::Linear:
            return ToolpathKind::Feed;
        default:
            return ToolpathKind::Arc;
    }
}
}  // namespace

ToolpathBuilder::ToolpathBuilder(const ProcessAxes& axes, ToolpathSettings settings)
    : axes_(axes), settings_(settings) {
    geometry_.tolerance = settings_.tolerance;
    for (int a = 0; a < axes_.count(); ++a) {
        const AxisModel& m = axes_.axis(a);
        if (m.rotary || m.spindle) continue;
        const int d = sceneAxisOfDefinition(m.baseDefinition());
        if (d >= 0 && machineAxisOfScene_[static_cast<std::size_t>(d)] < 0)
            machineAxisOfScene_[static_cast<std::size_t>(d)] = a;
    }
}

int ToolpathBuilder::sceneAxis(int axis) const {
    for (int d = 0; d < 3; ++d)
        if (machineAxisOfScene_[static_cast<std::size_t>(d)] == axis && axis >= 0) return d;
    return -1;
}

ToolpathGeometry ToolpathBuilder::take() {
    ToolpathGeometry out = std::move(geometry_);
    geometry_ = ToolpathGeometry{};
    geometry_.tolerance = settings_.tolerance;
    return out;
}

std::array<double, 3> ToolpathBuilder::scenePoint(const Position& machine) const {
    std::array<double, 3> p{0, 0, 0};
    for (std::size_t d = 0; d < 3; ++d)
        if (machineAxisOfScene_[d] >= 0)
            p[d] = machine[static_cast<std::size_t>(machineAxisOfScene_[d])];
    return p;
}

ToolpathBuilder::Transform ToolpathBuilder::transformOf(const Motion& m) const {
    Transform t;
    const bool valid = m.transformAxis1 >= 0 && m.transformAxis2 >= 0 &&
                       m.transformAxis1 < axes_.count() && m.transformAxis2 < axes_.count();
    if (m.transformation == 30 || !valid) return t;
    t.kind = m.transformation;
    t.axis1 = m.transformAxis1;
    t.axis2 = m.transformAxis2;
    t.radius = m.effectiveRadius;
    const bool rotary1 = axes_.axis(t.axis1).rotary, rotary2 = axes_.axis(t.axis2).rotary;
    t.rotary = rotary1 ? t.axis1 : (rotary2 ? t.axis2 : -1);
    t.linear = !rotary1 ? t.axis1 : (!rotary2 ? t.axis2 : -1);
    if (t.kind == 32 && !(t.radius > 0.0)) t.kind = 30;  // cannot happen: G32 checks RI > 0
    if (t.kind == 31 && (t.rotary < 0 || t.linear < 0)) t.kind = 30;
    return t;
}

void ToolpathBuilder::toPlaneSpace(const Transform& t, const Position& machine,
                                   Position& plane) const {
    plane = machine;
    if (t.kind == 32) {
        for (int a : {t.axis1, t.axis2})
            if (axes_.axis(a).rotary)
                plane[static_cast<std::size_t>(a)] = curve::developedFromDegrees(
                    machine[static_cast<std::size_t>(a)], t.radius, axes_.axis(a).polarDirection);
    } else if (t.kind == 31) {
        const double sign = axes_.axis(t.rotary).polarDirection == 1 ? -1.0 : 1.0;
        const double r = machine[static_cast<std::size_t>(t.linear)];
        const double angle =
            sign * machine[static_cast<std::size_t>(t.rotary)] * curve::kPi / 180.0;
        plane[static_cast<std::size_t>(t.linear)] = r * std::cos(angle);
        plane[static_cast<std::size_t>(t.rotary)] = r * std::sin(angle);
    }
}

bool ToolpathBuilder::scenePointOf(const Transform& t, const Position& plane,
                                   std::array<double, 3>& p) const {
    if (t.kind == 30) {
        p = scenePoint(plane);
        return true;
    }
    const int along = t.linear >= 0 ? sceneAxis(t.linear) : -1;
    if (along < 0 || t.rotary < 0) return false;
    const auto l = static_cast<std::size_t>(t.linear), r = static_cast<std::size_t>(t.rotary);
    if (t.kind == 32) {
        const double degrees =
            curve::degreesFromDeveloped(plane[r], t.radius, axes_.axis(t.rotary).polarDirection);
        p = curve::cylinderPoint(along, t.radius, plane[l], degrees);
        return true;
    }
    p = scenePoint(plane);  // G31: the fictitious plane, rotary coordinate on the next axis
    p[static_cast<std::size_t>(along)] = plane[l];
    p[static_cast<std::size_t>((along + 1) % 3)] = plane[r];
    return true;
}

void ToolpathBuilder::addChord(const Transform& t, const Position& from, const Position& to,
                               Layers layers) {
    std::array<double, 3> a{}, b{};
    ToolpathLayer& scene = contourPass_ ? geometry_.contour : geometry_.scene;
    ToolpathLayer& developed = contourPass_ ? geometry_.developedContour : geometry_.developed;
    if (layers != Layers::Developed && scenePointOf(t, from, a) && scenePointOf(t, to, b))
        scene.addSegment(a, b);
    if (t.kind != 32 || layers == Layers::Scene) return;
    const auto u = static_cast<std::size_t>(t.linear >= 0 ? t.linear : t.axis1);
    const auto v = static_cast<std::size_t>(t.linear >= 0 ? t.rotary : t.axis2);
    developed.addSegment({from[u], from[v], 0.0}, {to[u], to[v], 0.0});
}

int ToolpathBuilder::wrapChords(const Transform& t, double circumferentialTravel,
                                double tolerance) const {
    if (t.kind != 32) return 1;
    return curve::arcChords(t.radius, std::fabs(circumferentialTravel) / t.radius, tolerance);
}

void ToolpathBuilder::addLine(const Transform& t, const Position& start, const Position& end) {
    int chords = 1;
    if (t.kind == 32 && t.rotary >= 0) {
        const auto r = static_cast<std::size_t>(t.rotary);
        chords = wrapChords(t, end[r] - start[r], settings_.tolerance);
    }
    Position previous = start, current = start;
    const int count = axes_.count();
    for (int i = 1; i <= chords; ++i) {
        const double f = static_cast<double>(i) / chords;
        for (int a = 0; a < count; ++a) {
            const auto k = static_cast<std::size_t>(a);
            current[k] = i == chords ? end[k] : start[k] + (end[k] - start[k]) * f;
        }
        addChord(t, previous, current, Layers::Scene);
        previous = current;
    }
    addChord(t, start, end, Layers::Developed);  // straight in the developed plane
}

void ToolpathBuilder::addArc(const Motion& m, double c1, double c2, const Transform& t,
                             const Position& start, const Position& end) {
    const int p1 = m.planeAxis1, p2 = m.planeAxis2;
    if (p1 < 0 || p2 < 0 || p1 >= axes_.count() || p2 >= axes_.count())
        return addLine(t, start, end);
    if (t.kind == 32) {  // centre in machine positions: rotary axes in degrees
        if (axes_.axis(p1).rotary)
            c1 = curve::developedFromDegrees(c1, t.radius, axes_.axis(p1).polarDirection);
        if (axes_.axis(p2).rotary)
            c2 = curve::developedFromDegrees(c2, t.radius, axes_.axis(p2).polarDirection);
    }
    const auto k1 = static_cast<std::size_t>(p1), k2 = static_cast<std::size_t>(p2);
    const double r1 = std::hypot(start[k1] - c1, start[k2] - c2);
    const double r2 = std::hypot(end[k1] - c1, end[k2] - c2);
    const bool clockwise = m.type == MotionType::ArcCW;
    const double sweep = std::fabs(
        arcSweep(start[k1], start[k2], end[k1], end[k2], c1, c2, clockwise, m.fullCircle));
    const double radius = std::max(r1, r2);
    const double tolerance = t.kind == 32 ? settings_.tolerance / 2.0 : settings_.tolerance;
    int chords = curve::arcChords(radius, sweep, tolerance);
    if (t.kind == 32) chords = std::max(chords, wrapChords(t, radius * sweep, tolerance));
    const double a0 = std::atan2(start[k2] - c2, start[k1] - c1);
    const double direction = clockwise ? -1.0 : 1.0;
    Position previous = start, current = start;
    const int count = axes_.count();
    for (int i = 1; i <= chords; ++i) {
        const double f = static_cast<double>(i) / chords;
        if (i == chords) {
            current = end;
        } else {
            for (int a = 0; a < count; ++a) {
                const auto k = static_cast<std::size_t>(a);
                current[k] = start[k] + (end[k] - start[k]) * f;  // helix / other axes
            }
            const double angle = a0 + direction * sweep * f;
            const double r = r1 + (r2 - r1) * f;
            current[k1] = c1 + r * std::cos(angle);
            current[k2] = c2 + r * std::sin(angle);
        }
        addChord(t, previous, current, Layers::Both);
        previous = current;
    }
}

void ToolpathBuilder::addContour(const Motion& m, const Transform& t) {
    Position start{}, end{};
    toPlaneSpace(t, m.start, start);
    toPlaneSpace(t, m.end, end);
    contourPass_ = true;
    if (kindOf(m.type) == ToolpathKind::Arc)
        addArc(m, m.center1, m.center2, t, start, end);
    else
        addLine(t, start, end);
    contourPass_ = false;
}

std::uint16_t ToolpathBuilder::frameIndex(const Motion& m) {
    ToolpathFrame frame;
    frame.code = m.zeroOffset;
    for (std::size_t d = 0; d < 3; ++d)
        if (machineAxisOfScene_[d] >= 0)
            frame.offset[d] = m.zeroOffsetValues[static_cast<std::size_t>(machineAxisOfScene_[d])];
    frame.radialAxis = m.radialAxis >= 0 ? sceneAxis(m.radialAxis) : -1;
    frame.diameter = m.diameter && frame.radialAxis >= 0;
    auto& frames = geometry_.frames;
    // Newest first: a program stays in one frame for many moves.
    for (std::size_t i = frames.size(); i-- > 0;)
        if (frames[i] == frame) return static_cast<std::uint16_t>(i);
    if (frames.size() < kMaxToolpathFrames) {
        frames.push_back(frame);
        return static_cast<std::uint16_t>(frames.size() - 1);
    }
    return geometry_.moves.empty() ? 0 : geometry_.moves.back().frame;
}

void ToolpathBuilder::motion(const Motion& m) {
    ToolpathMove move;
    move.program = m.where.program;
    move.block = m.blockIndex;
    move.line = static_cast<std::uint32_t>(std::max(0, m.where.line));
    move.kind = kindOf(m.type);
    move.transformation = static_cast<std::uint8_t>(m.transformation);
    move.firstScene = static_cast<std::uint32_t>(geometry_.scene.segmentCount());
    move.firstDeveloped = static_cast<std::uint32_t>(geometry_.developed.segmentCount());
    move.frame = frameIndex(m);
    geometry_.moves.push_back(move);
    const Position offset = m.compensated ? m.toolOffset : Position{};
    const Position previousOffset = lastOffset_;
    const Position previousProgrammed = lastProgrammed_;
    lastOffset_ = offset;
    for (int a = 0; a < kMaxAxes; ++a)
        lastProgrammed_[static_cast<std::size_t>(a)] = programmedEndOf(m, a);
    if (geometry_.scene.segmentCount() + geometry_.developed.segmentCount() +
            geometry_.contour.segmentCount() + geometry_.developedContour.segmentCount() >=
        settings_.segmentLimit) {
        geometry_.truncated = true;
        return;
    }
    const Transform t = transformOf(m);
    // The tool centre: where the axes go minus the tool offset (length, edge).
    Position startCentre = m.start, endCentre = m.end;
    for (std::size_t a = 0; a < kMaxAxes; ++a) {
        startCentre[a] -= previousOffset[a];
        endCentre[a] -= offset[a];
    }
    Position start{}, end{};
    toPlaneSpace(t, startCentre, start);
    toPlaneSpace(t, endCentre, end);
    const auto centreOffset = [&](int axis) {
        return axis >= 0 && axis < kMaxAxes ? offset[static_cast<std::size_t>(axis)] : 0.0;
    };
    const double c1 = m.center1 - centreOffset(m.planeAxis1);
    const double c2 = m.center2 - centreOffset(m.planeAxis2);
    if (move.kind == ToolpathKind::Arc)
        addArc(m, c1, c2, t, start, end);
    else
        addLine(t, start, end);
    if (m.compensated && !m.inserted) {
        Motion programmed = m;  // the programmed contour: from the last programmed point
        programmed.start = previousProgrammed;
        programmed.end = m.programmedEnd;
        programmed.center1 = c1;
        programmed.center2 = c2;
        addContour(programmed, t);
    }
    if (t.kind == 32 && t.linear >= 0 && sceneAxis(t.linear) >= 0) {
        const auto l = static_cast<std::size_t>(t.linear);
        const bool first = geometry_.cylinderAxis < 0;
        geometry_.cylinderRadius = t.radius;
        geometry_.cylinderAxis = sceneAxis(t.linear);
        const double lo = std::min(start[l], end[l]), hi = std::max(start[l], end[l]);
        geometry_.cylinderFrom = first ? lo : std::min(geometry_.cylinderFrom, lo);
        geometry_.cylinderTo = first ? hi : std::max(geometry_.cylinderTo, hi);
    }
}

}  // namespace mtc::core
