#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "cnc_core/compiler/CompilerTypes.h"
#include "cnc_core/compiler/lookahead/LookAheadAnalysis.h"

/// The velocity profile of the enhanced look-ahead as data, for the plot of
/// the runtime program view (seed 001 ch. 6, Fig. 6-1) and for the CLI.
namespace mtc::core::lookahead {

/// One block or sub-block of a segment as written into the object program.
struct ProfileRow {
    std::string block;       ///< enhanced block number, "N0053:0001" ("" without N)
    int sourceLine = 0;      ///< 1-based line of the source block
    bool generated = false;  ///< TRC corner arc, approach/retract or lead line
    double sStart = 0.0;     ///< mm from the segment start
    double sEnd = 0.0;
    double vStart = 0.0;  ///< profile velocity, mm/min
    double vEnd = 0.0;
    double vMax = 0.0;    ///< the element's cap, mm/min
    double feed = 0.0;    ///< programmed F of the (sub-)block, mm/min
    double tStart = 0.0;  ///< s from the segment start
    double time = 0.0;    ///< s
};

/// One point of the sampled curve v(s).
struct ProfilePoint {
    double s = 0.0;     ///< mm
    double t = 0.0;     ///< s
    double v = 0.0;     ///< mm/min
    double vMax = 0.0;  ///< mm/min
};

/// The profile of one LA_ON ... LA_OFF segment.
struct VelocityProfile {
    int onLine = 0;   ///< source line of LA_ON
    int offLine = 0;  ///< source line of LA_OFF
    std::vector<ProfileRow> rows;
    std::vector<ProfilePoint> curve;  ///< `samplesPerElement` points per element + the end
    double length = 0.0;              ///< mm
    double time = 0.0;                ///< s
};

/// The profile of a planned segment.
VelocityProfile profileOf(const LookAheadSegment& segment, int samplesPerElement = 8);

/// Compiles `source` with the standard passes and returns the velocity
/// profile of every segment that planned without error (errors: compile the
/// program for the .ERR file).
std::vector<VelocityProfile> velocityProfiles(std::string_view source,
                                              const CompilerOptions& options,
                                              const LookAheadDefaults& defaults = {},
                                              int samplesPerElement = 8);

/// The rows as CSV ("block;line;generated;s_start_mm;s_end_mm;v_start_mm_min;
/// v_end_mm_min;v_max_mm_min;f_mm_min;t_start_s;time_s"), one header line.
std::string formatProfileCsv(const VelocityProfile& profile);

}  // namespace mtc::core::lookahead
