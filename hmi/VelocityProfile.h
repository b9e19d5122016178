#pragma once

#include <vector>

namespace mtc::core::lookahead {
struct LookAheadAnalysis;
}

namespace mtc::hmi {

/// A point of a velocity curve: path position (mm from the start of the
/// segment) and path velocity (mm/min).
struct ProfilePoint {
    double s = 0.0;
    double v = 0.0;
};

/// The velocity profile of one LA_ON ... LA_OFF segment as the runtime view
/// plots it (seed 001 ch. 6, Fig. 6-1): the planned velocity over the path,
/// each element's velocity cap, and where each (sub-)block starts.
struct SegmentProfile {
    int sourceLine = 0;               ///< 1-based source line of the first motion
    double length = 0.0;              ///< mm
    double time = 0.0;                ///< s
    std::vector<ProfilePoint> curve;  ///< planned velocity, sampled along the path
    std::vector<ProfilePoint> caps;   ///< pairs (start, end) of each element's cap
    std::vector<double> blockStarts;  ///< s of every emitted (sub-)block
    int blocks = 0;                   ///< emitted (sub-)blocks
};

/// Every planned segment of one compile (failed segments are left out).
struct VelocityProfile {
    std::vector<SegmentProfile> segments;
    bool empty() const { return segments.empty(); }
};

/// Samples the plans of `analysis` (what the look-ahead pass captured).
VelocityProfile profileFromAnalysis(const mtc::core::lookahead::LookAheadAnalysis& analysis);

}  // namespace mtc::hmi
