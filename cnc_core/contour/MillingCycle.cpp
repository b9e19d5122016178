// CYCLE_40: contour cut milling with tool radius compensation (G17).

#include "cnc_core/contour/CycleSupport.h"
#include "cnc_core/contour/PathOffset.h"

namespace mtc::core::gne {

bool millingContourCut(const CycleInput& in, BlockWriter& out, std::string& problem) {
    const Geometry& g = *in.geometry;
    const int sideParam = static_cast<int>(in.value(kMillSide));
    if (g.strokes && sideParam != 0)
        return problem = "text is engraved on its strokes: SIDE must be 0", false;
    const double radius = in.value(kMillToolRadius);
    const double safeZ = in.value(kMillSafeZ), cutZ = in.value(kMillCutZ);
    if (cutZ >= safeZ) return problem = "ZC must lie below the safety plane ZS", false;
    const double plunge =
        in.value(kMillPlungeFeed) > 0 ? in.value(kMillPlungeFeed) : in.value(kMillFeed);
    const int side = sideParam == 1 ? 1 : sideParam == 2 ? -1 : 0;
    out.raw("G0 Z" + BlockWriter::number(safeZ));
    for (const std::vector<Segment>& path : g.paths) {
        std::vector<Segment> toolPath = path;
        if (side != 0 && !offsetPath(path, side, radius, g.closed, toolPath, problem)) return false;
        if (toolPath.empty()) continue;
        out.rapid(toolPath.front().start);
        out.raw("G1 Z" + BlockWriter::number(cutZ) + " F" + BlockWriter::number(plunge));
        out.setFeed(in.value(kMillFeed));
        for (const Segment& s : toolPath)
            out.segment(s);
        out.raw("G0 Z" + BlockWriter::number(safeZ));
    }
    return true;
}

}  // namespace mtc::core::gne
