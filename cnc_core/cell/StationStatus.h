#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cnc_core/interp/InterpreterState.h"
#include "cnc_core/language/Program.h"
#include "cnc_core/machine/ProcessControl.h"

namespace mtc::core {

class Station;

/// One axis of the position display (every axis except a plain spindle).
struct AxisStatus {
    int index = 0;         ///< machine axis index (what Station::jogBy() takes)
    std::string name;      ///< as the program addresses it now ("X", "Z2", "C", "Y1" under G32)
    bool rotary = false;   ///< degrees instead of mm
    double work = 0.0;     ///< actual position in workpiece coordinates (programmed units)
    double machine = 0.0;  ///< actual position in machine coordinates (mm, degrees)
    double toGo = 0.0;     ///< distance to go in the current move (machine units)
};

/// Direction of a spindle from its last M function (Mj03/Mj04/Mj05/Mj19).
enum class SpindleTurn { Unknown, Clockwise, CounterClockwise, Stopped, Oriented };

/// "CW (M3)", "CCW (M4)", "stopped (M5)", "oriented (M19)", "-".
const char* spindleTurnName(SpindleTurn turn);

/// One spindle S1..S3 of the process.
struct SpindleStatus {
    int index = 0;            ///< 1..3
    std::string name;         ///< configuration name ("S1")
    double programmed = 0.0;  ///< last S, rpm
    double actual = 0.0;      ///< rpm the spindle turns at
    SpindleTurn turn = SpindleTurn::Unknown;
    bool rotaryAxisMode = false;  ///< S1 as rotary axis C (position display instead)
};

/// One active G function and its group.
struct GFunctionStatus {
    int group = 0;
    int code = 0;            ///< G number
    const char* topic = "";  ///< "interpolation", "plane", ...
};

/// One block of the program listing around the running block.
struct BlockLineStatus {
    std::string id;    ///< "N0012", "N0053:0001" or ""
    std::string text;  ///< the block's source text (one line, trimmed)
    bool current = false;
};

/// What the program of the station is doing, as the base screen says it.
enum class ProgramState {
    NoProgram,       ///< none selected
    Ready,           ///< selected, not active (Start runs it)
    Running,         ///< active, not held
    FeedHold,        ///< Stop: feed hold, Start continues
    ProgrammedStop,  ///< held at M00 / M01
    SingleBlock,     ///< held after a block in single-block mode
    WaitingForAxis,  ///< GAX: another process holds the axis
    WaitingForSps,   ///< NC program restart selected: waits for the SPS's start (PxxCBPSTR)
    Restart,         ///< the NC program restart computes, adjusts or repositions
    Error,           ///< the last run ended with an error (the alarm says which)
};

/// "running", "feed hold", ... (lower case; the screen capitalises).
const char* programStateName(ProgramState state);
/// One or two words for the status header: "running", "feed hold",
/// "M00 stop", "single block", "waiting", "restart", "error", "".
const char* programStateWord(ProgramState state);

/// What the program of `station` is doing now.
ProgramState programStateOf(const Station& station);

/// The interpreter's modal state as of the block the machine executes (the
/// interpreter may be the look-ahead ahead of the axes), its state now when
/// the machine stands or the block is not known.
const ModalState& shownModalState(const Station& station);

/// The lamp of machine control key `key` on the panel: lit while what the
/// key selects is in force (its mode, single block, feed hold, a running
/// program, an NC program restart, multi-block retrace possible). Control
/// reset is a momentary key without lamp.
bool keyLamp(const Station& station, ControlKey key);

/// Everything the base screen ("position") shows of a station, read from
/// the station at one instant. Plain data; describeStation() builds it.
struct StationStatus {
    std::vector<AxisStatus> axes;
    std::vector<SpindleStatus> spindles;
    double programmedFeed = 0.0;  ///< F (mm/min, or mm/rev under G95)
    bool feedPerRevolution = false;
    double actualFeed = 0.0;  ///< path feed of the axes now, mm/min
    double feedOverride = 100.0;
    double rapidOverride = 100.0;
    std::vector<GFunctionStatus> gFunctions;  ///< ascending group number
    int tool = 0;                             ///< T (0 = none)
    int edge = 0;                             ///< E (0 = the first edge)
    bool edgeKnown = false;                   ///< the tool list has T/E
    double edgeRadius = 0.0;                  ///< R (geometry + wear), mm
    double edgeLength[3] = {0.0, 0.0, 0.0};   ///< L1..L3 (geometry + wear), mm
    int edgeOrientation = 0;                  ///< cutting edge position 0..9
    int zeroOffset = 53;                      ///< G53..G59 in force
    std::vector<double> zeroOffsetValues;     ///< per entry of `axes` (mm, degrees)
    int program = 0;                          ///< program of the running block (0 = none)
    int callLevel = 0;                        ///< 0 = main program, 1.. = subroutine levels
    bool inLibrary = false;                   ///< the block is in program 99 (subroutine library)
    std::vector<BlockLineStatus> blocks;      ///< before, the current one, after
    ProgramState state = ProgramState::NoProgram;
};

/// Reads the status of `station` now: actual positions of the machine (in
/// workpiece coordinates through the zero offset and axis allocation in
/// force), the interpreter's modal state, and the block the machine
/// executes with `around` blocks before and after it.
StationStatus describeStation(const Station& station, int around = 2);

/// Index of the block that starts on or before 1-based source `line` of
/// `program` (binary search; 0 for an empty program).
std::uint32_t blockIndexAtLine(const Program& program, int line);

}  // namespace mtc::core
