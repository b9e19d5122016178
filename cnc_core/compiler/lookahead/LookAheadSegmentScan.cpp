// The rules inside an LA_ON ... LA_OFF segment (seed 001 ch. 6) and the
// planning of a finished segment.
#include <cmath>

#include "cnc_core/compiler/CompilerText.h"
#include "cnc_core/compiler/lookahead/LookAheadScan.h"
#include "cnc_core/geometry/ArcSweep.h"
#include "cnc_core/language/Keywords.h"

namespace mtc::core::lookahead::detail {
namespace {

constexpr double kArcTolerance = 0.002;  // mm, the interpreter's tolerance
constexpr double kAxisFeedPath = 1.0e7;  // mm/min: F<axis>= alone limits the path

/// A short name of a word for messages ("M8", "D2", "a jump", "@1=...").
std::string describeWord(const Word& w) {
    const bool constant = w.expr < 0;
    switch (w.kind) {
        case WordKind::M:
            return constant ? "M" + formatCoordinate(w.number) : "M";
        case WordKind::Q:
            return constant ? "Q" + formatCoordinate(w.number) : "Q";
        case WordKind::D:
            return constant ? "D" + formatCoordinate(w.number) : "D";
        case WordKind::EffectiveRadius:
            return "RI";
        case WordKind::Jump:
            return "a jump";
        case WordKind::Assign:
        case WordKind::AssignMTD:
            return "an assignment";
        default:
            return "this word";
    }
}

}  // namespace

bool Analyzer::startSegment(std::size_t i) {
    inside_ = true;
    segment_ = LookAheadSegment{};
    segment_.onBlock = i;
    segment_.onLine = static_cast<int>(blocks_[i].sourceLine);
    segment_.limits = limits_;
    for (char d : definitions_)
        segment_.centerLetter.push_back(d >= 'X' && d <= 'Z' ? static_cast<char>('I' + (d - 'X'))
                                                             : ' ');
    segment_.parameters.metbMs = state_.metbMs;
    segment_.parameters.vfbt = state_.vfbt;
    segment_.parameters.blockCycleMs = blockCycleMs_;
    const PlaneAxes plane = planeAxes(state_.plane, definitions_);
    if (state_.plane == 20 || plane.first < 0 || plane.second < 0)
        report(i, "LA_PLANE", "LA_ON needs the plane G17, G18 or G19");
    if (state_.incremental) report(i, "LA_INCREMENTAL", "LA_ON needs absolute dimensions (G90)");
    if (state_.metbMs <= blockCycleMs_)
        report(i, "LA_METB_CYCLE", "METB must exceed the block cycle time",
               {"METB " + formatCoordinate(state_.metbMs) + " ms, block cycle time " +
                formatCoordinate(blockCycleMs_) + " ms"});
    segment_.radiusCorrection = state_.trc != 0;
    segment_.correction.side = state_.trc;
    segment_.correction.approach = state_.adtrc;
    segment_.correction.blockBuffer = state_.bbtrc;
    segment_.correction.planeFirst = plane.first;
    segment_.correction.planeSecond = plane.second;
    if (segment_.radiusCorrection) {
        const std::optional<double> radius = toolRadiusForTrc(i);
        if (radius) segment_.correction.radius = *radius;
    }
    return true;
}

std::optional<double> Analyzer::toolRadiusForTrc(std::size_t i) {
    const auto programmed = state_.radii.find({state_.tool, state_.edge});
    if (programmed != state_.radii.end()) return programmed->second;
    const ProcessConfig* process = context_.options().process;
    const ToolConfig* tool = process ? process->tool(static_cast<int>(state_.tool)) : nullptr;
    // The setup list holds one radius per tool: (Rmin + Rmax) / 2 = that radius.
    if (tool && tool->radius > 0.0) return tool->radius;
    report(i, "LA_TRC_NO_RADIUS", "TRC: no tool radius (TL_RADIUS) for the tool",
           {"T" + std::to_string(state_.tool) + " E" + std::to_string(state_.edge) +
            ": neither TL_RADIUS nor a radius in the tools list."});
    return std::nullopt;
}

void Analyzer::insideBlock(std::size_t i, const Program& program, const Block& block,
                           const BlockWords& words, std::vector<bool>& drop) {
    if (block.flags & kBlockSkip) report(i, "LA_SKIP_BLOCK", "no skip blocks between LA_ON/LA_OFF");
    AxisVector target = state_.position, center = state_.position;
    unsigned centerMask = 0;
    int motion = state_.motion;
    bool off = false, moves = false;
    for (std::uint32_t k = 0; k < block.wordCount; ++k) {
        const Word w = program.words[block.firstWord + k];
        if (w.kind == WordKind::Command && keywordIn(program.text(w.text)) == "LA_OFF") {
            off = drop[k] = true;
            continue;
        }
        moves = moves || w.kind == WordKind::Axis;
        drop[k] = insideWord(i, program, w, target, center, centerMask, motion);
    }
    if (off) {
        if (block.wordCount > 1)
            report(i, "LA_KEYWORD_NOT_ALONE", "LA_OFF must stand alone in its block");
        return finishSegment(i);
    }
    state_.motion = motion;
    if (!moves) return;
    if (motion == 0) {
        report(i, "LA_COMMAND_NOT_ALLOWED", "G0 not allowed between LA_ON and LA_OFF");
        return;
    }
    const bool fullCircle = motion >= 2 && centerMask != 0;
    if ((target - state_.position).norm() > 1e-12 || fullCircle)
        addElement(i, motion, target, center, centerMask, words, drop);
    state_.position = target;
}

bool Analyzer::insideWord(std::size_t i, const Program& program, const Word& w, AxisVector& target,
                          AxisVector& center, unsigned& centerMask, int& motion) {
    const std::string raw(program.text(w.text));
    auto notAllowed = [&](const std::string& what) {
        report(i, "LA_COMMAND_NOT_ALLOWED", what + " not allowed in LA segment",
               {"Between LA_ON and LA_OFF only these may be programmed:",
                "G1, G2, G3, axis end points, I/J/K, F, F<axis>=, ACC_EFF=,",
                "events SE/RE and swift auxiliary functions (MQ, QQ, S)."});
        return true;
    };
    const bool constant = w.expr < 0;
    switch (w.kind) {
        case WordKind::G:
            if (constant && w.number >= 1 && w.number <= 3)
                motion = static_cast<int>(w.number);
            else
                return notAllowed(constant ? "G" + formatCoordinate(w.number) : "G=expression");
            return true;
        case WordKind::Axis: {
            const int axis = axisIndex(w);
            if (axis < 0) return report(i, "LA_UNKNOWN_AXIS", "axis not in this process"), true;
            if (!constant)
                return report(i, "LA_VARIABLE_ENDPOINT", "end point given by a variable"), true;
            if (!state_.known[static_cast<std::size_t>(axis)])
                report(i, "LA_START_UNKNOWN", "start point of an axis unknown at LA_ON",
                       {"The axis " + limits_.names[static_cast<std::size_t>(axis)] +
                        " was last programmed with a variable before LA_ON."});
            state_.known[static_cast<std::size_t>(axis)] = true;
            target[axis] = w.number;
            return true;
        }
        case WordKind::CircleCenter: {
            if (!constant)
                return report(i, "LA_VARIABLE_ENDPOINT", "circle centre given by a variable"), true;
            const PlaneAxes plane = planeAxes(state_.plane, definitions_);
            const char definition = static_cast<char>('X' + (w.letter - 'I'));
            int axis = -1;
            for (int a : {plane.first, plane.second})
                if (a >= 0 && definitions_[static_cast<std::size_t>(a)] == definition) axis = a;
            if (axis < 0)
                return report(i, "LA_ARC_CENTER", "circle centre outside the plane"), true;
            center[axis] = w.number;
            centerMask |= 1u << (w.letter - 'I');
            return true;
        }
        case WordKind::F:
            if (!constant) return report(i, "LA_VARIABLE_FEED", "F given by a variable"), true;
            state_.pathFeed = w.number;
            state_.axisFeedAxis = -1;
            return true;
        case WordKind::M:
        case WordKind::Q:
            // Only the swift outputs MQxxx / QQxxx (LA-008); a plain M or Q
            // waits for its acknowledgement and would break the profile.
            if (w.flags & kWordSwift) return false;
            return notAllowed(raw.empty() ? describeWord(w) : raw);
        case WordKind::S:
            return false;  // S counts as a swift auxiliary function (LA-008)
        case WordKind::T:
        case WordKind::E:
            report(i, "LA_TOOL_CHANGE", "tool change not allowed in LA segment",
                   {"Change tools (T, E) before LA_ON or after LA_OFF."});
            return true;
        case WordKind::Command:
            break;
        default:
            return notAllowed(raw.empty() ? describeWord(w) : raw);
    }
    const std::string keyword = keywordIn(raw);
    if (keyword == "SE" || keyword == "RE") return false;
    if (keyword == "ACC_EFF") return variableWord(i, keyword, program.text(w.args));
    if (lookupKeyword(keyword).keywordClass == KeywordClass::AxisFeed) {
        const int axis = limits_.indexOf(keyword.substr(1));
        const CompileTimeValue v = evaluate(i, valueAfterEquals(program.text(w.args)));
        if (axis < 0) return report(i, "LA_UNKNOWN_AXIS", keyword + ": axis unknown"), true;
        if (!v.ok || v.value <= 0.0)
            return report(i, "LA_BAD_VALUE", keyword + "= needs a velocity > 0"), true;
        state_.axisFeedAxis = axis;
        state_.axisFeedValue = v.value;
        return true;
    }
    if (keyword == "LA_ON") return report(i, "LA_NESTED", "LA_ON inside an LA segment"), true;
    return notAllowed(keyword.empty() ? raw : keyword);
}

void Analyzer::addElement(std::size_t i, int motion, const AxisVector& target,
                          const AxisVector& center, unsigned centerMask, const BlockWords& words,
                          const std::vector<bool>& drop) {
    PathElement e;
    e.kind = motion == 1   ? ElementKind::Line
             : motion == 2 ? ElementKind::ArcCw
                           : ElementKind::ArcCcw;
    e.start = state_.position;
    e.end = target;
    e.center = center;
    e.axisFeed = AxisVector::Zero(limits_.size());
    const PlaneAxes plane = planeAxes(state_.plane, definitions_);
    e.planeFirst = plane.first;
    e.planeSecond = plane.second;
    e.accelerationFactor = state_.accEff / 100.0;
    e.ref = {static_cast<int>(i), blocks_[i].number, static_cast<int>(blocks_[i].sourceLine)};
    if (motion >= 2 && centerMask == 0)
        return void(report(i, "LA_ARC_CENTER", "circle without centre (I, J, K)"));
    if (motion >= 2 && !arcCenter(i, target, e.center, centerMask, plane)) return;
    e.fullCircle = motion >= 2 && closesCircle(e.start[plane.first], e.start[plane.second],
                                               e.end[plane.first], e.end[plane.second]);
    const int a = state_.axisFeedAxis;
    if (a >= 0 && std::abs(e.end[a] - e.start[a]) > 1e-12) {
        e.feed = kAxisFeedPath;
        e.axisFeed[a] = state_.axisFeedValue;
    } else {
        e.feed = state_.pathFeed;
    }
    if (e.feed <= 0.0) return void(report(i, "LA_NO_FEED", "no F for this block"));
    SegmentMotion m;
    m.block = i;
    m.motionCode = "G" + std::to_string(motion);
    for (std::size_t k = 0; k < words.raw.size(); ++k)
        if (!drop[k]) m.kept.push_back(words.raw[k]);
    m.comment = words.comment;
    segment_.motions.push_back(std::move(m));
    segment_.contour.push_back(std::move(e));
    motionBlock_ = i;
}

bool Analyzer::arcCenter(std::size_t i, const AxisVector& target, AxisVector& center, unsigned,
                         PlaneAxes plane) {
    const int p = plane.first, q = plane.second;
    if (p < 0 || q < 0) return false;
    const double r1 = std::hypot(state_.position[p] - center[p], state_.position[q] - center[q]);
    const double r2 = std::hypot(target[p] - center[p], target[q] - center[q]);
    if (r1 < 1e-9) return report(i, "LA_ARC_RADIUS", "circle start point is its centre"), false;
    if (std::abs(r1 - r2) > kArcTolerance)
        return report(i, "LA_ARC_RADIUS", "start and end not on one circle",
                      {"radius at the start " + formatCoordinate(r1) + " mm, at the end " +
                       formatCoordinate(r2) + " mm"}),
               false;
    return true;
}

void Analyzer::finishSegment(std::size_t i) {
    segment_.offBlock = i;
    segment_.offLine = static_cast<int>(blocks_[i].sourceLine);
    segment_.motionAfter = state_.motion;
    segment_.feedAfter = state_.pathFeed;
    if (!segment_.failed && !segment_.contour.empty()) planSegment();
    result_.segments.push_back(std::move(segment_));
    segment_ = LookAheadSegment{};
    inside_ = false;
}

void Analyzer::planSegment() {
    auto reportProblems = [&](const std::vector<PlanProblem>& problems,
                              const std::vector<PathElement>& elements) {
        for (const PlanProblem& p : problems) {
            const std::size_t element = static_cast<std::size_t>(std::max(0, p.element));
            const int block = element < elements.size() ? elements[element].ref.blockIndex : -1;
            report(block >= 0 ? static_cast<std::size_t>(block) : segment_.onBlock, p.code,
                   p.message);
        }
    };
    segment_.polygon = segment_.contour;
    if (segment_.radiusCorrection) {
        CorrectedPolygon corrected = correctToolRadius(segment_.contour, segment_.correction);
        if (!corrected.ok()) return reportProblems(corrected.problems, segment_.contour);
        segment_.polygon = std::move(corrected.elements);
    }
    segment_.plan = planVelocityProfile(segment_.polygon, segment_.limits, segment_.parameters);
    if (!segment_.plan.ok()) reportProblems(segment_.plan.problems, segment_.polygon);
}

}  // namespace mtc::core::lookahead::detail
