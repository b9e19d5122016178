// Batching of the machine's work (docs/decisions/motion.md MOT-022): a
// station whose interpreter runs a batch of blocks ahead of the look-ahead
// gives exactly the run of one without: the same times, positions,
// auxiliary functions, adaptive feed control figures and trend clock.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "InterpTestSupport.h"
#include "cnc_core/afc/AdaptiveFeedControl.h"
#include "cnc_core/cell/Cell.h"

namespace mtc::test {
namespace {

using core::ControlKey;

std::string block(int& number, const std::string& text) {
    char label[16];
    std::snprintf(label, sizeof label, "N%04d ", number++);
    return label + text + "\n";
}

/// Inside the demo mill's stock (X -150..-50, Y -80..-20, Z -132..-120).
/// 300 collinear steps of 0.05 mm at F30000: the axes never reach the feed,
/// every move's exit is planned from the end of its look-ahead window, so a
/// window longer than without the batch shows in the time. Then plain moves
/// with corners, a dwell, a stall torque recording over one torque sample
/// (its noise is that of the millisecond) and a G26 move: the
/// trend clock both read is set by the moves before them.
std::string batchProgram() {
    int n = 1;
    std::string p =
        block(n, "S1=3000 M3") + block(n, "G0 G90 X-145 Y-50 Z-110") + block(n, "G1 Z-125 F600");
    char move[64];
    for (int i = 1; i <= 300; ++i) {
        std::snprintf(move, sizeof move, "G1 X%.2f F30000", -145.0 + 0.05 * i);
        p += block(n, move);
    }
    p += block(n, "G2 X-125 Y-50 I-127.5 J-50 F1200") + block(n, "G4 F0.3");
    for (int i = 0; i < 60; ++i) {  // zigzag: a corner at rest after every move
        std::snprintf(move, sizeof move, "G1 X%.1f Y%d F%d", -125.0 + 0.5 * i,
                      i % 2 == 0 ? -49 : -50, 900 + 10 * i);
        p += block(n, move);
    }
    p += block(n, "AXD(S1:P-7-3651)=1") + block(n, "@122=AXD(S1:P-7-3652)") + block(n, "M108") +
         block(n, "G1 X-120 Y-50 F900");
    for (int i = 0; i < 60; ++i) {
        std::snprintf(move, sizeof move, "G1 X%.1f Y%d F%d", -120.0 + 0.5 * i,
                      i % 2 == 0 ? -49 : -50, 700 + 10 * i);
        p += block(n, move);
    }
    return p + block(n, "G1 G26 X-60 Y-50 F1500") + block(n, "G25") +
           block(n, "G1 X-145 Y-30 F2000") + block(n, "M30");
}

/// Everything a run leaves behind that the interpreter's side or the
/// machine's progress could change.
struct BatchOutcome {
    double seconds = 0.0;
    double afcClock = 0.0;
    double stallTorque = 0.0;  ///< @122, read right after the recording
    std::vector<double> positions;
    std::vector<int> aux;
    std::map<int, double> page30;
    std::vector<int> signals;
    std::size_t trendSamples = 0;
};

BatchOutcome runWithBatch(std::size_t batch, bool keepTrend, const std::string& source) {
    core::Cell cell(demoCell());
    core::ProgramPtr program = cell.addProgram(0, 1, "batch.nc", source);
    EXPECT_FALSE(program->diagnostics.hasErrors()) << diagnosticsText(program->diagnostics);
    core::Station& mill = cell.station(0);
    mill.keepAfcTrend(keepTrend);
    mill.keepBlockStates(false);
    mill.batchMachineWork(batch);
    EXPECT_TRUE(mill.selectProgram(1));
    EXPECT_TRUE(mill.press(ControlKey::Start));
    for (int i = 0; i < 1'000'000 && mill.busy(); ++i)
        mill.advance(1e9);
    EXPECT_TRUE(mill.control().alarm().empty()) << mill.control().alarm();
    EXPECT_EQ(mill.runStatus(), core::RunStatus::Ended);
    BatchOutcome out;
    out.seconds = mill.machine().seconds();
    out.afcClock = mill.adaptiveFeed().clock();
    out.stallTorque = mill.interpreter().state().variables.values[122];
    for (int axis = 0; axis < 3; ++axis)
        out.positions.push_back(mill.machine().position(axis));
    for (const core::AuxOutput& aux : mill.machine().recentAux())
        out.aux.push_back(static_cast<int>(aux.value));
    for (int element : {5, 7, 8, 11, 12, 14})
        cell.machineData().read({30, 0, 0, element}, out.page30[element]);
    out.signals = {mill.control().signalTable().get("P00SEXCTH"),
                   mill.control().signalTable().get("P00STHMIS")};
    out.trendSamples = mill.afcTrend().size();
    return out;
}

/// Bit for bit: a batch changes no figure at all.
void expectIdentical(const BatchOutcome& a, const BatchOutcome& b, std::size_t batch) {
    SCOPED_TRACE("batch " + std::to_string(batch));
    EXPECT_EQ(a.seconds, b.seconds);
    EXPECT_EQ(a.afcClock, b.afcClock);
    EXPECT_EQ(a.stallTorque, b.stallTorque);
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.aux, b.aux);
    EXPECT_EQ(a.page30, b.page30);
    EXPECT_EQ(a.signals, b.signals);
    EXPECT_EQ(a.trendSamples, b.trendSamples);
}

TEST(StationBatch, ABatchGivesTheRunWithoutOneBitForBit) {
    const std::string source = batchProgram();
    for (bool keepTrend : {false, true}) {
        SCOPED_TRACE(keepTrend ? "with trend" : "without trend");
        const BatchOutcome plain = runWithBatch(0, keepTrend, source);
        EXPECT_GT(plain.page30.at(12), 0.0) << "G26 reduced the feed";
        EXPECT_NE(plain.stallTorque, 0.0) << "the stall torque was recorded";
        for (std::size_t batch : {1u, 8u, 40u, 500u})
            expectIdentical(runWithBatch(batch, keepTrend, source), plain, batch);
    }
}

}  // namespace
}  // namespace mtc::test
