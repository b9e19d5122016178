// The decoder reads a word held in the 8-byte form (WordList::readNumber)
// without building a Word; every other word goes the whole way. Both ways
// must give the same run (docs/decisions/interpreter.md I-021).
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "InterpTestSupport.h"

using namespace mtc::core;
using namespace mtc::test;

namespace {

/// Words of numbers of every kind the fast path takes, and mistakes in them.
const char* const kProgram =
    "N0010 G90 G54 G1 X12.5 Y-3.25 F1000 S1200 T1 M3\n"
    "N0020 G3 X22.5 Y6.75 I12.5 J6.75 Q17\n"
    "N0030 G2 X32.5 Y-3.25 I32.5 J-3.25 F1500 M108 M62\n"
    "N0040 G0 X0 Y0 E1 D1\n"
    "N0050 G91 X0.001 Y-0.001 G90\n"
    "N0060 G4 F0.5\n"
    "N0070 G1 X1 X2\n"
    "N0080 G1 G0 X3\n"
    "N0090 G1 Q5 I1 I2 X4\n"
    "N0100 M1000\n"
    "N0110 G99 X1\n"
    "N0120 W7 X1\n"
    "N0130 G1 X10 F-1\n"
    "N0140 M30\n";

/// `program` with every word moved past column 255: no word fits the
/// 8-byte form any more.
ProgramPtr movedRight(const ProgramPtr& program) {
    auto moved = std::make_shared<Program>(*program);
    for (std::size_t i = 0; i < moved->words.size(); ++i) {
        Word w = moved->words[i];
        w.column = static_cast<std::uint16_t>(w.column + 300);
        moved->words.set(i, w);
    }
    return moved;
}

/// How many words of `program` the 8-byte form holds.
std::size_t packedWords(const Program& program) {
    std::size_t count = 0;
    NumberWord w;
    for (std::size_t i = 0; i < program.words.size(); ++i)
        if (program.words.readNumber(i, w)) ++count;
    return count;
}

/// Runs `program` in check mode (every block, errors skipped) on process 0
/// of the demo cell: the transcript, the error codes and the final state.
std::string runOf(const ProgramPtr& program) {
    Station station(demoCell(), 0);
    station.interpreter->options().continueAfterError = true;
    station.store.put(0, 1, program);
    EXPECT_TRUE(station.interpreter->select(1));
    const RunResult result = station.interpreter->run();
    std::string text = station.sink->text + "\n";
    for (const std::string& code : errorCodes(result.diagnostics))
        text += code + "\n";
    return text + stateText(*station.interpreter);
}

TEST(InterpDecode, EightByteWordsDecodeAsWholeWords) {
    const ProgramPtr plain = parse(kProgram, 1);
    const ProgramPtr moved = movedRight(plain);
    EXPECT_EQ(packedWords(*plain), plain->words.size());
    EXPECT_EQ(packedWords(*moved), 0u);
    const std::string fast = runOf(plain);
    EXPECT_NE(fast.find("motion P1 N0040"), std::string::npos);
    EXPECT_NE(fast.find("WORD_TWICE"), std::string::npos);  // the mistakes are reported
    EXPECT_EQ(fast, runOf(moved));
}

}  // namespace
