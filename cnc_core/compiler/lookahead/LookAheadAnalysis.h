#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "cnc_core/compiler/CompilerPass.h"
#include "cnc_core/compiler/lookahead/CompileTimeValue.h"
#include "cnc_core/compiler/lookahead/RadiusCorrection.h"
#include "cnc_core/compiler/lookahead/VelocityPlanner.h"

namespace mtc::core::lookahead {

/// Presets of the look-ahead variables ("NC options", seed 001 ch. 6) and
/// the controller access of ACD_COMP. Process parameters B070..B073 of the
/// compiled process override the presets (docs/decisions/lookahead.md LA-010).
struct LookAheadDefaults {
    double metbMs = 5.0;              ///< METB preset, 3..30 ms
    double vfbt = 1.0;                ///< VFBT preset, 1..10
    int bbtrc = 3;                    ///< BBTRC preset, 1..10
    double blockCycleMs = 2.0;        ///< NC block cycle time (VFBT transition formula)
    NcVariableReader readNcVariable;  ///< ACD_COMP; empty = no controller (reads 0, warns)
};

/// A block of a segment that keeps words besides its motion (SE, RE, Q, S).
struct SegmentMotion {
    std::size_t block = 0;          ///< sequence index
    std::string motionCode;         ///< "G1", "G2", "G3"
    std::vector<std::string> kept;  ///< raw words written into the first part
    std::string comment;            ///< the block's ';' comment, with the ';'
};

/// One LA_ON ... LA_OFF segment of the program as planned.
struct LookAheadSegment {
    std::size_t onBlock = 0;             ///< sequence index of LA_ON
    std::size_t offBlock = 0;            ///< sequence index of LA_OFF
    int onLine = 0;                      ///< source line of LA_ON
    int offLine = 0;                     ///< source line of LA_OFF
    AxisLimits limits;                   ///< axis table and machine limits
    std::vector<char> centerLetter;      ///< per axis: 'I', 'J', 'K' or ' ' (no centre word)
    std::vector<PathElement> contour;    ///< programmed polygon (ref.blockIndex = sequence index)
    std::vector<PathElement> polygon;    ///< after TRC (= contour without TRC)
    std::vector<SegmentMotion> motions;  ///< per motion block, in order
    LookAheadParameters parameters;
    bool radiusCorrection = false;
    RadiusCorrectionSettings correction;
    LookAheadPlan plan;
    int motionAfter = 1;     ///< modal G0..G3 of the source at LA_OFF (written there)
    double feedAfter = 0.0;  ///< modal path F of the source at LA_OFF (0 = none)
    bool failed = false;     ///< an error was reported: nothing is emitted
};

/// Every segment of a block sequence.
struct LookAheadAnalysis {
    std::vector<LookAheadSegment> segments;
    /// New texts of blocks that lose look-ahead words (METB=, TRC=, LA_ON,
    /// F<axis>=, ACC_EFF=, ...): sequence index and text.
    std::vector<std::pair<std::size_t, std::string>> rewrites;
};

/// Reads the look-ahead variables and segments of `blocks`, checks every
/// rule of seed 001 ch. 6 (errors through `context`) and plans each segment.
LookAheadAnalysis analyzeLookAhead(const BlockSequence& blocks, CompileContext& context,
                                   const LookAheadDefaults& defaults);

/// Rewrites `blocks`: look-ahead words removed, every motion block of a
/// segment replaced by its planned parts (first part in the block itself,
/// the others as intermediate blocks), the source's G and F restored in the
/// LA_OFF block.
void emitLookAhead(BlockSequence& blocks, const LookAheadAnalysis& analysis);

/// The axis table and limits of `process` (nullptr: X Y Z with the
/// AxisConfig defaults); spindles are left out.
AxisLimits axisLimitsOf(const ProcessConfig* process);

}  // namespace mtc::core::lookahead
