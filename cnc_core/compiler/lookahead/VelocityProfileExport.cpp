#include "cnc_core/compiler/lookahead/VelocityProfileExport.h"

#include <algorithm>
#include <cstdio>
#include <memory>

#include "cnc_core/compiler/Compiler.h"
#include "cnc_core/compiler/CompilerText.h"
#include "cnc_core/compiler/lookahead/LookAheadPass.h"
#include "cnc_core/text/Numbers.h"

namespace mtc::core::lookahead {
namespace {

void sampleCurve(const LookAheadSegment& segment, int samples, VelocityProfile& profile) {
    double s0 = 0.0, t0 = 0.0;
    samples = std::max(1, samples);
    for (const ElementProfile& p : segment.plan.profiles) {
        for (int m = 0; m < samples; ++m) {
            const double s = p.length * m / samples;
            profile.curve.push_back(
                {s0 + s, t0 + p.timeTo(s), p.velocityAt(s) * 60.0, p.vMax * 60.0});
        }
        s0 += p.length;
        t0 += p.timeTo(p.length);
    }
    const double vMax = segment.plan.profiles.empty() ? 0.0 : segment.plan.profiles.back().vMax;
    profile.curve.push_back({s0, t0, 0.0, vMax * 60.0});
}

}  // namespace

VelocityProfile profileOf(const LookAheadSegment& segment, int samplesPerElement) {
    VelocityProfile profile;
    profile.onLine = segment.onLine;
    profile.offLine = segment.offLine;
    int lastBlock = -1, sub = 0;
    double t = 0.0;
    for (const PlannedBlock& part : segment.plan.blocks) {
        const PathElement& e = segment.polygon[static_cast<std::size_t>(part.element)];
        sub = e.ref.blockIndex == lastBlock ? sub + 1 : 0;
        lastBlock = e.ref.blockIndex;
        ProfileRow row;
        if (e.ref.number >= 0)
            row.block = formatBlockNumber(e.ref.number) + ":" + formatFourDigits(sub);
        row.sourceLine = e.ref.line;
        row.generated = e.generated != 0;
        row.sStart = part.sStart;
        row.sEnd = part.sEnd;
        row.vStart = part.vStart;
        row.vEnd = part.vEnd;
        row.vMax = part.vMax;
        row.feed = part.feed;
        row.tStart = t;
        row.time = part.time;
        t += part.time;
        profile.rows.push_back(std::move(row));
    }
    profile.length = segment.plan.totalLength;
    profile.time = segment.plan.totalTime;
    sampleCurve(segment, samplesPerElement, profile);
    return profile;
}

std::vector<VelocityProfile> velocityProfiles(std::string_view source,
                                              const CompilerOptions& options,
                                              const LookAheadDefaults& defaults,
                                              int samplesPerElement) {
    auto capture = std::make_shared<LookAheadAnalysis>();
    CompilerPassList passes;
    for (const auto& pass : standardCompilerPasses())
        if (pass->name() != "look-ahead") passes.push_back(pass);
    passes.push_back(std::make_shared<LookAheadPass>(defaults, capture));
    CompilerOptions active = options;
    active.compilerActive = true;
    Compiler(passes).compile(source, active);
    std::vector<VelocityProfile> profiles;
    for (const LookAheadSegment& segment : capture->segments)
        if (!segment.failed && segment.plan.ok() && !segment.plan.blocks.empty())
            profiles.push_back(profileOf(segment, samplesPerElement));
    return profiles;
}

std::string formatProfileCsv(const VelocityProfile& profile) {
    std::string text =
        "block;line;generated;s_start_mm;s_end_mm;v_start_mm_min;v_end_mm_min;v_max_mm_min;"
        "f_mm_min;t_start_s;time_s\n";
    for (const ProfileRow& r : profile.rows) {
        text += r.block + ";" + std::to_string(r.sourceLine) + ";" + (r.generated ? "1" : "0");
        for (double v : {r.sStart, r.sEnd})
            text += ";" + formatFixed(v, 4);
        for (double v : {r.vStart, r.vEnd, r.vMax, r.feed})
            text += ";" + formatFixed(v, 1);
        for (double v : {r.tStart, r.time})
            text += ";" + formatFixed(v, 6);
        text += "\n";
    }
    return text;
}

}  // namespace mtc::core::lookahead
