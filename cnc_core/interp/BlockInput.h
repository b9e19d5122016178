#pragma once

#include <array>
#include <cstdint>

#include "cnc_core/interp/InterpreterState.h"
#include "cnc_core/machine/MachineDataProvider.h"

namespace mtc::core {

/// One block after its words were read and their expressions evaluated,
/// before anything is committed. Fixed-size arrays only: decoding a block
/// never allocates. Reset with clear() before each block.
struct BlockInput {
    static constexpr int kMaxAux = 8;      ///< M or Q words per block
    static constexpr int kMaxWrites = 16;  ///< variable assignments per block
    static constexpr int kMaxMtdWrites = 4;
    static constexpr int kMaxCommands = 4;

    struct VariableWrite {
        int process = -1;  ///< -1 = own process
        int index = 0;
        double value = 0.0;
    };
    struct MtdWrite {
        MachineDataAddress address;
        double value = 0.0;
        std::uint16_t column = 0;
    };
    struct AuxWord {
        int value = 0;
        std::uint16_t column = 0;
    };

    GGroupValues g{};         ///< programmed G per group, -1 = none
    std::uint32_t gMask = 0;  ///< bit n: a G of group n is programmed
    std::array<std::uint16_t, kGroupSlots> gColumn{};
    bool dwell = false;       ///< G4
    bool speedLimit = false;  ///< G92
    std::uint16_t dwellColumn = 0;
    /// G74 / G75 / G77 programmed in the block (the G number), 0 = none.
    std::uint8_t axisFunction = 0;
    std::uint16_t axisFunctionColumn = 0;

    /// G25 / G26 programmed (the G number), 0 = none.
    std::uint8_t adaptiveFeed = 0;
    std::uint16_t adaptiveFeedColumn = 0;
    bool idleMeasurement = false;  ///< ITM in the block
    std::uint16_t idleColumn = 0;
    /// AXD(axis:P-7-3651)=period: stall torque recording of `stallAxis`.
    bool stallRecording = false;
    std::array<char, 4> stallAxis{};  ///< "X", "S1", ... (NUL-terminated)
    double stallPeriodMs = 0.0;
    std::uint16_t stallColumn = 0;
    std::uint16_t axisMask = 0;  ///< bit i: machine axis i programmed
    std::array<double, kMaxAxes> axisValue{};
    std::array<std::uint16_t, kMaxAxes> axisColumn{};
    /// Axis words in program order (repeats included, so that G20 can report
    /// an axis written twice); axisValue/axisColumn hold the last occurrence.
    static constexpr int kMaxAxisWords = 16;
    std::array<std::uint8_t, kMaxAxisWords> axisOrder{};
    std::array<double, kMaxAxisWords> orderValue{};
    std::array<std::uint16_t, kMaxAxisWords> orderColumn{};
    int axisCount = 0;
    std::uint16_t repeatedAxisColumn = 0;  ///< column of the first repeated axis word, 0 = none

    std::uint8_t centerMask = 0;  ///< bit 0 I, 1 J, 2 K
    std::array<double, 3> center{};
    std::uint16_t centerColumn = 0;

    bool hasFeed = false, hasTool = false, hasEdge = false, hasCorrection = false;
    bool hasRadius = false;
    double feed = 0.0, radius = 0.0;
    int tool = 0, edge = 0, correction = 0;
    std::uint16_t toolColumn = 0, radiusColumn = 0, feedColumn = 0;

    std::uint8_t spindleMask = 0;  ///< bit j: S for spindle j (1..3) programmed
    std::array<double, kSpindleSlots> spindle{};
    std::uint16_t spindleColumn = 0;  ///< column of the first S word

    std::array<AuxWord, kMaxAux> m{};
    int mCount = 0;
    std::array<AuxWord, kMaxAux> q{};
    int qCount = 0;

    std::array<VariableWrite, kMaxWrites> writes{};
    int writeCount = 0;
    std::array<MtdWrite, kMaxMtdWrites> mtdWrites{};
    int mtdCount = 0;
    bool conditionSet = false;
    double condition = 0.0;

    std::int64_t jumpWord = -1;  ///< index (Program::words) of the jump/branch/call word
    double jumpProgram = 0.0;    ///< JSR/JMP/JEV: evaluated program number
    std::array<std::uint32_t, kMaxCommands> commands{};  ///< word indices of commands
    int commandCount = 0;

    /// False: the block holds only modal G words, axis words, I/J/K and F
    /// (the usual block); what the decoder wrote is then g, gMask, gColumn
    /// and the axis, centre and feed fields. Set by every other word (and
    /// every word in its whole form), so that the flags and counters of all
    /// the other fields are as clear() left them (I-023).
    bool special = true;

    /// Forgets the previous block (cheap: only flags and counters).
    void clear() {
        g.fill(-1);
        gMask = 0;
        dwell = speedLimit = false;
        axisFunction = 0;
        adaptiveFeed = 0;
        idleMeasurement = stallRecording = false;
        axisMask = 0;
        axisCount = 0;
        repeatedAxisColumn = 0;
        centerMask = 0;
        hasFeed = hasTool = hasEdge = hasCorrection = hasRadius = false;
        spindleMask = 0;
        mCount = qCount = writeCount = mtdCount = commandCount = 0;
        conditionSet = false;
        jumpWord = -1;
        special = false;
    }
    /// clear() after a block that was not special: only what such a block
    /// writes (InterpreterOptions::shortcuts; the general path calls clear()).
    void clearUsual() {
        g.fill(-1);
        gMask = 0;
        axisMask = 0;
        axisCount = 0;
        repeatedAxisColumn = 0;
        centerMask = 0;
        hasFeed = false;
    }
};

}  // namespace mtc::core
