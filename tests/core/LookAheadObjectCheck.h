#pragma once

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "cnc_core/compiler/lookahead/PathGeometry.h"
#include "cnc_core/language/Parser.h"

/// Numerical check of a compiled object program (tests only): every block
/// with G1/G2/G3 and its own F word between two rests is read back from the
/// text and checked against the axis limits, independently of the planner.
namespace mtc::core::lookahead::testing {

struct ObjectMove {
    PathElement element;
    double feed = 0.0;  ///< mm/min
    std::string id;
};

/// The moves of `objectText` that carry their own F (the look-ahead parts),
/// G90 absolute, axes in `limits` order; arcs in G17 (X/Y, centre I/J).
inline std::vector<ObjectMove> objectMoves(const std::string& objectText,
                                           const AxisLimits& limits) {
    const Program program = parseProgram(objectText);
    std::vector<ObjectMove> moves;
    AxisVector at = AxisVector::Zero(limits.size());
    int motion = 0;
    for (std::size_t b = 0; b < program.blocks.size(); ++b) {
        const Block block = program.blocks[b];
        AxisVector target = at, center = at;
        double feed = 0.0;
        for (std::uint32_t w = block.firstWord; w < block.firstWord + block.wordCount; ++w) {
            const Word word = program.words[w];
            if (word.kind == WordKind::G && word.number <= 3)
                motion = static_cast<int>(word.number);
            if (word.kind == WordKind::F) feed = word.number;
            if (word.kind == WordKind::Axis) {
                std::string name(1, word.letter);
                if (word.axisIndex) name += static_cast<char>('0' + word.axisIndex);
                target[limits.indexOf(name)] = word.number;
            }
            if (word.kind == WordKind::CircleCenter) center[word.letter - 'I'] = word.number;
        }
        if (feed > 0.0 && motion >= 1 && (target - at).norm() > 0.0) {
            ObjectMove m;
            m.element.kind = motion == 1   ? ElementKind::Line
                             : motion == 2 ? ElementKind::ArcCw
                                           : ElementKind::ArcCcw;
            m.element.start = at;
            m.element.end = target;
            m.element.center = center;
            m.element.axisFeed = AxisVector::Zero(limits.size());
            m.feed = feed;
            m.id = program.blockId(b);
            moves.push_back(m);
        }
        at = target;
    }
    return moves;
}

/// Violations of the moves read from an object program: axis velocity at F,
/// centripetal acceleration at F, block time at F >= METB, and every change
/// of F fits into one block at the axes' acceleration (from and to rest at
/// the ends). `accelerationFactor` = ACC_EFF / 100 of the program.
inline std::vector<std::string> objectViolations(const std::vector<ObjectMove>& moves,
                                                 const AxisLimits& limits, double metbMs,
                                                 double accelerationFactor = 1.0) {
    std::vector<std::string> out;
    auto fail = [&](const std::string& what, const std::string& id, double v, double limit) {
        std::ostringstream s;
        s << id << ": " << what << " " << v << " > " << limit;
        out.push_back(s.str());
    };
    const AxisVector accel = limits.maxAcceleration * accelerationFactor;
    for (std::size_t k = 0; k < moves.size(); ++k) {
        const ObjectMove& m = moves[k];
        const ElementGeometry g = describeElement(m.element);
        const double v = m.feed / 60.0;
        const bool arc = m.element.kind != ElementKind::Line;
        if (arc && std::abs(g.radiusStart - g.radiusEnd) > 0.002)
            fail("arc radius mismatch", m.id, std::abs(g.radiusStart - g.radiusEnd), 0.002);
        double aPath = 1e300;
        for (int i = 0; i < limits.size(); ++i) {
            if (v * g.maxAbsTangent[i] * 60.0 > limits.maxVelocity[i] * (1 + 1e-9))
                fail("axis velocity " + limits.names[i], m.id, v * g.maxAbsTangent[i] * 60.0,
                     limits.maxVelocity[i]);
            const double centripetal = v * v * g.curvature * g.maxAbsNormal[i];
            if (centripetal > accel[i] * (1 + 1e-6))
                fail("centripetal " + limits.names[i], m.id, centripetal, accel[i]);
            if (g.maxAbsTangent[i] > 1e-12)
                aPath = std::min(aPath, (accel[i] - centripetal) / g.maxAbsTangent[i]);
        }
        if (g.length / v * 1000.0 < metbMs * (1 - 1e-9))
            fail("block time below METB (ms)", m.id, metbMs, g.length / v * 1000.0);
        const double prev = k == 0 ? 0.0 : moves[k - 1].feed / 60.0;
        const double next = k + 1 == moves.size() ? 0.0 : moves[k + 1].feed / 60.0;
        if (v * v - prev * prev > 2 * aPath * g.length * (1 + 1e-6))
            fail("acceleration into block", m.id, v * v - prev * prev, 2 * aPath * g.length);
        if (v * v - next * next > 2 * aPath * g.length * (1 + 1e-6))
            fail("deceleration in block", m.id, v * v - next * next, 2 * aPath * g.length);
    }
    return out;
}

}  // namespace mtc::core::lookahead::testing
