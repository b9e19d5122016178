#include "hmi/VelocityProfile.h"

#include "cnc_core/compiler/lookahead/LookAheadAnalysis.h"

namespace mtc::hmi {

namespace {

constexpr int kSamplesPerElement = 24;
constexpr double kPerMinute = 60.0;  // the planner works in mm/s

SegmentProfile sampleSegment(const mtc::core::lookahead::LookAheadSegment& segment) {
    SegmentProfile out;
    const auto& plan = segment.plan;
    out.length = plan.totalLength;
    out.time = plan.totalTime;
    if (!segment.contour.empty()) out.sourceLine = segment.contour.front().ref.line;
    double offset = 0.0;
    for (const auto& profile : plan.profiles) {
        for (int i = 0; i <= kSamplesPerElement; ++i) {
            const double s = profile.length * i / kSamplesPerElement;
            out.curve.push_back({offset + s, profile.velocityAt(s) * kPerMinute});
        }
        out.caps.push_back({offset, profile.vMax * kPerMinute});
        out.caps.push_back({offset + profile.length, profile.vMax * kPerMinute});
        offset += profile.length;
    }
    for (const auto& block : plan.blocks)
        out.blockStarts.push_back(block.sStart);
    out.blocks = static_cast<int>(plan.blocks.size());
    return out;
}

}  // namespace

VelocityProfile profileFromAnalysis(const mtc::core::lookahead::LookAheadAnalysis& analysis) {
    VelocityProfile profile;
    for (const auto& segment : analysis.segments)
        if (!segment.failed && segment.plan.ok() && !segment.plan.profiles.empty())
            profile.segments.push_back(sampleSegment(segment));
    return profile;
}

}  // namespace mtc::hmi
