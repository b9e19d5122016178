// The shortcuts of the usual block (docs/decisions/interpreter.md I-022: the
// G0..G3-only and F-only words without the general functions, the move's
// frame fields kept while the frame stays) must give exactly the run of the
// general path (InterpreterOptions::shortcuts off): every field of every
// output, the diagnostics and the final state.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "InterpTestSupport.h"

using namespace mtc::core;
using namespace mtc::test;
namespace fs = std::filesystem;

namespace {

/// Every field of every output as text ("%.17g": no rounding hides a difference).
class FullSink : public MachineSink {
  public:
    void motion(const Motion& m) override {
        text += "motion " + place(m.where) + " " + std::to_string(static_cast<int>(m.type)) + " n" +
                std::to_string(m.axisCount) + " b" + std::to_string(m.blockIndex);
        values("start", m.start);
        values("end", m.end);
        text += " plane " + std::to_string(m.planeAxis1) + "," + std::to_string(m.planeAxis2);
        numbers({m.center1, m.center2, m.feed, m.effectiveRadius});
        text += " full" + std::to_string(m.fullCircle) + " t" + std::to_string(m.transformation) +
                " ta" + std::to_string(m.transformAxis1) + "," + std::to_string(m.transformAxis2) +
                " comp" + std::to_string(m.compensated) + " ins" + std::to_string(m.inserted);
        values("programmed", m.programmedEnd);
        values("offset", m.toolOffset);
        text += " stop" + std::to_string(m.exactStop) + " blend" + std::to_string(m.blendCorners) +
                " G" + std::to_string(m.zeroOffset);
        values("zero", m.zeroOffsetValues);
        text +=
            " radial" + std::to_string(m.radialAxis) + " dia" + std::to_string(m.diameter) + "\n";
    }
    void auxiliary(const AuxOutput& a) override {
        text += "aux " + place(a.where) + " " + a.type + std::to_string(a.spindle);
        numbers({a.value});
        text += "\n";
    }
    void dwell(const SourceLocation& where, double seconds) override {
        text += "dwell " + place(where);
        numbers({seconds});
        text += "\n";
    }
    void command(const MachineCommand& c) override {
        text +=
            "command " + place(c.where) + " " + std::to_string(static_cast<int>(c.keyword)) + "\n";
    }
    std::string text;

  private:
    static std::string place(const SourceLocation& w) {
        return "P" + std::to_string(w.program) + " " + w.block + " L" + std::to_string(w.line) +
               " C" + std::to_string(w.column);
    }
    void numbers(std::initializer_list<double> list) {
        for (double v : list) {
            char buffer[40];
            std::snprintf(buffer, sizeof buffer, " %.17g", v);
            text += buffer;
        }
    }
    void values(const char* name, const std::array<double, kMaxAxes>& v) {
        text += std::string(" ") + name;
        for (double x : v) {
            char buffer[40];
            std::snprintf(buffer, sizeof buffer, " %.17g", x);
            text += buffer;
        }
    }
};

/// Every field of the modal state: the usual block's commit copies only what
/// such a block changes (I-028), the general path copies all.
std::string modalText(const ModalState& m) {
    char buffer[40];
    const auto number = [&](double v) {
        std::snprintf(buffer, sizeof buffer, " %.17g", v);
        return std::string(buffer);
    };
    std::string text = "modal g";
    for (auto g : m.g)
        text += " " + std::to_string(g);
    text += " plane " + std::to_string(m.plane.plane());
    for (int a = 0; a < kMaxAxes; ++a)
        text += " " + std::to_string(static_cast<int>(m.plane.definitionOf(a)));
    text += " t" + std::to_string(m.transformation.kind()) + "," +
            std::to_string(m.transformation.planeAxis(0)) + "," +
            std::to_string(m.transformation.planeAxis(1)) +
            number(m.transformation.effectiveRadius());
    for (int a = 0; a < kMaxAxes; ++a)
        text += number(m.work[static_cast<std::size_t>(a)]) +
                number(m.machine[static_cast<std::size_t>(a)]);
    for (int j = 0; j < kSpindleSlots; ++j)
        text += number(m.spindleSpeed[static_cast<std::size_t>(j)]) +
                number(m.spindleLimit[static_cast<std::size_t>(j)]) + " r" +
                std::to_string(m.rotaryAxisMode[static_cast<std::size_t>(j)]);
    for (int s : m.toolSpindle)
        text += " ts" + std::to_string(s);
    text += " " + std::to_string(m.tool) + " " + std::to_string(m.edge) + " " +
            std::to_string(m.correction) + " " + std::to_string(m.referenceSpindle) + " " +
            std::to_string(m.adaptiveFeed) + number(m.lastEffectiveRadius) + number(m.feed) +
            number(m.time) + "\n";
    return text;
}

/// Runs `source` as program 1 of `process` of the demo cell in check mode
/// (errors skipped, M00 continued): every output, the diagnostics and the
/// final state. `between` is called before each block (an operator change).
template <typename Between>
std::string runOf(const std::string& source, int process, bool shortcuts, Between between) {
    const MachineConfig& cell = demoCell();
    const ProcessConfig& config = *cell.process(process);
    DiagnosticList ignored;
    auto offsets = std::make_shared<ZeroOffsetTable>(ZeroOffsetTable::build(config, ignored));
    ProgramStore store;
    store.put(process, 1, parse(source, 1));
    FullSink sink;
    InterpreterServices services;
    services.zeroOffsets = offsets;
    Interpreter interpreter(config, store, sink, services);
    interpreter.options().continueAfterError = true;
    interpreter.options().shortcuts = shortcuts;
    EXPECT_TRUE(interpreter.select(1));
    std::string text;
    for (int block = 0; block < 10000; ++block) {
        between(block, *offsets);
        const RunResult result = interpreter.step();
        text += diagnosticsText(result.diagnostics) + modalText(interpreter.state().modal);
        if (result.status != RunStatus::Running && result.status != RunStatus::Stopped) break;
    }
    return sink.text + text + stateText(interpreter);
}

std::string runOf(const std::string& source, int process, bool shortcuts) {
    return runOf(source, process, shortcuts, [](int, ZeroOffsetTable&) {});
}

/// Frame changes between moves: zero offsets, plane, exact stop, G7,
/// inch, incremental, radius compensation, errors in between.
const char* const kMillProgram =
    "N0010 G54 G1 X10 Y5 Z2 F1000\n"
    "N0020 G2 X20 Y15 I20 J5\n"
    "N0030 G55 G1 X30 Y20\n"
    "N0040 G9 G1 X31\n"
    "N0050 G7 X32 F1500\n"
    "N0060 G53 G0 X0 Y0\n"
    "N0070 G18 G1 X5 Z5 F800\n"
    "N0080 G3 X10 Z10 I5 K10\n"
    "N0090 G17 G70 G1 X1 Y1 F10\n"
    "N0100 G71 G91 X1 Y1 F500\n"
    "N0110 G90 G54 X12 Y12\n"
    "N0120 G1 X13 Y13 F-5\n"
    "N0130 G1 X14 F600 S1000 M3\n"
    "N0140 G41 D1 T1 G1 X20 Y20\n"
    "N0150 G1 X30 Y20\n"
    "N0160 G2 X40 Y10 I30 J10\n"
    "N0170 G40 G1 X50 Y0\n"
    "N0180 G8 G6 G1 X0 Y0 F0\n"
    "N0190 G4 F0.5\n"
    "N0200 G1 G56 X1 Y1 F100\n"
    "N0210 M30\n";

TEST(InterpShortcuts, MillFrameChangesGiveTheGeneralRun) {
    const std::string fast = runOf(kMillProgram, 0, true);
    EXPECT_NE(fast.find("motion P1 N0200"), std::string::npos) << fast;
    EXPECT_NE(fast.find(" G55 "), std::string::npos) << fast;
    EXPECT_EQ(fast, runOf(kMillProgram, 0, false));
}

TEST(InterpShortcuts, ZeroOffsetTableChangedBetweenBlocksIsSeen) {
    const std::string source =
        "N0010 G54 G1 X10 Y5 F1000\nN0020 G1 X11\nN0030 G1 X12\nN0040 G53 X13\nN0050 G54 "
        "X14\nN0060 M30\n";
    auto change = [](int block, ZeroOffsetTable& table) {
        if (block == 2) table.set(54, AxisDefinition::X, -7.5);
        if (block == 4) table.set(54, AxisDefinition::Y, 3.25);
    };
    const std::string fast = runOf(source, 0, true, change);
    EXPECT_NE(fast.find(" -7.5 "), std::string::npos) << fast;
    EXPECT_EQ(fast, runOf(source, 0, false, change));
}

/// Every kind of word that makes a block special (BlockInput::special,
/// I-023), each followed by two usual blocks: the first is decoded after a
/// full clear, the second after the partial one; a field a special word
/// left behind would repeat its output or its check in them.
const char* const kSpecialWordsProgram =
    "N0010 G54 G1 X10 Y5 F1000\n"
    "N0020 G1 X11 M3 S500\n"
    "N0030 G1 X12\n"
    "N0040 G2 X22 Y15 I17 J10\n"
    "N0050 T1 E1 D1\n"
    "N0060 G1 X23 Y16\n"
    "N0070 G1 X24\n"
    "N0080 Q17 M108\n"
    "N0090 G1 X25 F900\n"
    "N0100 G1 X26\n"
    "N0110 G4 F0.25\n"
    "N0120 G1 X27\n"
    "N0130 G1 X28\n"
    "N0140 @1=@1+1 G1 X29\n"
    "N0150 G1 X30\n"
    "N0160 G1 X@1\n"
    "N0170 G1 X31\n"
    "N0180 G92 S2000\n"
    "N0190 G1 X32\n"
    "N0200 G1 X33\n"
    "N0210 G1 X34 S2=100\n"
    "N0220 G1 X35\n"
    "N0230 G1 X36 M00\n"
    "N0240 G1 X37\n"
    "N0250 G1 X38 MTD(1,0,0,1)=1\n"
    "N0260 G1 X39\n"
    "N0270 G90 G1 X40 Y20 F700\n"
    "N0280 G91 X1\n"
    "N0290 G90 G17 X41\n"
    "N0300 G1 X42 Y21 W5\n"
    "N0310 G1 X43\n"
    "N0320 G74 X0\n"
    "N0330 G1 X44\n"
    "N0340 BST\n";

TEST(InterpShortcuts, SpecialWordsBetweenUsualBlocksGiveTheGeneralRun) {
    const std::string fast = runOf(kSpecialWordsProgram, 0, true);
    EXPECT_NE(fast.find("motion P1 N0330"), std::string::npos) << fast;
    EXPECT_NE(fast.find("aux P1 N0020"), std::string::npos) << fast;
    EXPECT_EQ(fast.find("aux P1 N0030"), std::string::npos) << fast;
    EXPECT_EQ(fast, runOf(kSpecialWordsProgram, 0, false));
    const std::string lathe = runOf(kSpecialWordsProgram, 1, true);
    EXPECT_EQ(lathe, runOf(kSpecialWordsProgram, 1, false));
}

/// The lathe's spindle S1 moved as its rotary axis C in usual blocks (the
/// rotary axis mode changes without a special word), between spindle words.
TEST(InterpShortcuts, SpindleMovedAsAnAxisGivesTheGeneralRun) {
    const std::string program = std::string("N0010 G1 X10 Z5 F500\nN0020 G1 C90\n") +
                                "N0030 G1 X12 C180\nN0040 M3 S500\nN0050 G1 X14\n" +
                                "N0060 G1 C45 F200\nN0070 G0 Z20 C0\nN0080 M30\n";
    const std::string fast = runOf(program, 1, true);
    EXPECT_NE(fast.find(" r1"), std::string::npos) << fast;  // S1 in rotary axis mode
    EXPECT_EQ(fast, runOf(program, 1, false));
}

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

/// Every golden interpreter program (one program of the process its header
/// names; calls to its other programs are errors here, the same both ways).
TEST(InterpShortcuts, GoldenProgramsGiveTheGeneralRun) {
    int programs = 0;
    std::error_code ec;
    const fs::path dir = fs::path(MTC_TEST_DATA_DIR) / "interp";
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
        if (entry.path().extension() != ".nc") continue;
        const std::string source = readFile(entry.path());
        const int process = source.find("; process: 1") != std::string::npos ? 1 : 0;
        EXPECT_EQ(runOf(source, process, true), runOf(source, process, false))
            << entry.path().filename();
        ++programs;
    }
    EXPECT_GE(programs, 10);
}

}  // namespace
