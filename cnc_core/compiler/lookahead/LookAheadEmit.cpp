// Writing a planned look-ahead segment back into the block sequence.
#include <map>

#include "cnc_core/compiler/CompilerText.h"
#include "cnc_core/compiler/lookahead/LookAheadAnalysis.h"
#include "cnc_core/compiler/lookahead/LookAheadScan.h"

namespace mtc::core::lookahead {
namespace {

/// "X12.5", or "Z1 4.5" for an axis name with an index digit.
std::string axisWord(const std::string& name, double value) {
    const bool indexed = name.size() > 1 && name.back() >= '0' && name.back() <= '9';
    return name + (indexed ? " " : "") + formatCoordinate(value);
}

/// Words of one part: motion, changed axes (both plane axes of an arc), the
/// centre of an arc and F.
std::string partText(const PlannedBlock& part, const PathElement& e, const LookAheadSegment& s) {
    const bool arc = e.kind != ElementKind::Line;
    std::string text = e.kind == ElementKind::Line    ? "G1"
                       : e.kind == ElementKind::ArcCw ? "G2"
                                                      : "G3";
    for (int a = 0; a < s.limits.size(); ++a) {
        const bool plane = arc && (a == e.planeFirst || a == e.planeSecond);
        if (plane || formatCoordinate(part.end[a]) != formatCoordinate(part.start[a]))
            text += " " + axisWord(s.limits.names[static_cast<std::size_t>(a)], part.end[a]);
    }
    if (arc)
        for (int a : {e.planeFirst, e.planeSecond})
            text += std::string(" ") + s.centerLetter[static_cast<std::size_t>(a)] +
                    formatCoordinate(e.center[a]);
    return text + " F" + formatCoordinate(part.feed);
}

/// Texts of the parts of every motion block of `s`, by sequence index.
std::map<std::size_t, std::vector<std::string>> segmentParts(const LookAheadSegment& s) {
    std::map<std::size_t, std::vector<std::string>> parts;
    for (const PlannedBlock& part : s.plan.blocks) {
        const PathElement& e = s.polygon[static_cast<std::size_t>(part.element)];
        parts[static_cast<std::size_t>(e.ref.blockIndex)].push_back(partText(part, e, s));
    }
    for (const SegmentMotion& m : s.motions) {
        auto found = parts.find(m.block);
        if (found == parts.end() || found->second.empty()) continue;
        found->second.front() = detail::joinWords(found->second.front(), m.kept, m.comment);
    }
    return parts;
}

}  // namespace

void emitLookAhead(BlockSequence& blocks, const LookAheadAnalysis& analysis) {
    std::map<std::size_t, std::string> rewrites(analysis.rewrites.begin(), analysis.rewrites.end());
    std::map<std::size_t, std::vector<std::string>> parts;
    for (const LookAheadSegment& s : analysis.segments) {
        if (s.failed) continue;
        for (auto& [block, texts] : segmentParts(s))
            parts[block] = std::move(texts);
        // The source's modal G and F hold again after LA_OFF.
        std::string restore = "G" + std::to_string(s.motionAfter);
        if (s.feedAfter > 0.0) restore += " F" + formatCoordinate(s.feedAfter);
        const std::string& old = blocks[s.offBlock].text;
        rewrites[s.offBlock] =
            detail::joinWords(restore, {}, std::string(old.substr(commentOffset(old))));
    }
    if (rewrites.empty() && parts.empty()) return;
    BlockSequence out;
    out.reserve(blocks.size() + parts.size());
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        CompileBlock block = std::move(blocks[i]);
        const auto p = parts.find(i);
        const auto r = rewrites.find(i);
        if (p != parts.end()) {
            block.text = p->second.front();
            block.changed = true;
            CompileBlock intermediate = block;
            intermediate.intermediate = true;
            intermediate.prefix.clear();
            out.push_back(std::move(block));
            for (std::size_t k = 1; k < p->second.size(); ++k) {
                intermediate.text = p->second[k];
                out.push_back(intermediate);
            }
            continue;
        }
        if (r != rewrites.end()) {
            block.text = r->second;
            block.changed = true;
        }
        out.push_back(std::move(block));
    }
    blocks = std::move(out);
}

}  // namespace mtc::core::lookahead
