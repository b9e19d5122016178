// Manual data input (docs/decisions/mdi.md): an MDI entry continues the
// station's state (MDI-002), global macros are expanded and compiler
// keywords refused (seed 001 ch. 4 and 12, MDI-001), diagnostics name the
// line of the input, and Start in MDI mode runs the entry (MDI-005).
#include <gtest/gtest.h>

#include <map>
#include <random>

#include "InterpTestSupport.h"
#include "RestartStation.h"
#include "cnc_core/mdi/MdiEntry.h"
#include "cnc_core/mdi/MdiRun.h"

namespace {

using namespace mtc::core;
using namespace mtc::test;
using mtc::test::Station;  // the interpreter fixture, not core::Station

const std::vector<MacroDefinition> kMacros = {{"FAST", "G1 F4000"}, {"COOLANT", "M8"}};

/// Prepares `input` and runs it to its end on `station`'s interpreter.
RunResult runMdi(Station& station, const std::string& input,
                 const std::vector<MacroDefinition>& macros = kMacros) {
    const MdiEntry entry = prepareMdiEntry(input, macros);
    EXPECT_TRUE(entry.runnable()) << input;
    if (!entry.runnable()) return {};
    MdiRun run;
    EXPECT_TRUE(run.begin(*station.interpreter, entry.program));
    RunResult result = run.run();
    EXPECT_FALSE(run.active());
    return result;
}

double variable(const Station& s, int index) {
    return s.interpreter->state().variables.values[static_cast<size_t>(index)];
}

TEST(MdiEntryTest, GlobalMacrosAreExpandedLineByLine) {
    const MdiEntry entry = prepareMdiEntry("FAST X10\n\nCOOLANT ;coolant on\n", kMacros);
    ASSERT_TRUE(entry.runnable()) << (entry.diagnostics.empty()
                                          ? ""
                                          : entry.diagnostics.items()[0].message);
    ASSERT_EQ(entry.lines.size(), 3u);
    EXPECT_EQ(entry.expanded[0], "G1 F4000 X10");
    EXPECT_EQ(entry.expanded[1], "");
    EXPECT_EQ(entry.expanded[2], "M8 ;coolant on");
    EXPECT_EQ(entry.program->name, kMdiProgramName);
    EXPECT_EQ(entry.program->number, 0);
}

TEST(MdiEntryTest, DefineAndCompilerKeywordsAreRefusedWithTheirLine) {
    MdiEntry entry = prepareMdiEntry("G1 X5 F100\nDEFINE SLOW AS F10\n", kMacros);
    EXPECT_FALSE(entry.runnable());
    ASSERT_EQ(entry.diagnostics.size(), 1u);
    EXPECT_EQ(entry.diagnostics.items()[0].code, "MDI_KEYWORD_REFUSED");
    EXPECT_EQ(entry.diagnostics.items()[0].where.line, 2);
    EXPECT_NE(entry.diagnostics.items()[0].message.find("defined"), std::string::npos);

    entry = prepareMdiEntry("G1 X5 F100 RD3\nLA_ON\n", kMacros);
    EXPECT_FALSE(entry.runnable());
    ASSERT_EQ(entry.diagnostics.size(), 2u) << "every refused line is reported";
    std::map<int, std::string> byLine;
    for (const Diagnostic& d : entry.diagnostics.items()) {
        EXPECT_EQ(d.code, "MDI_KEYWORD_REFUSED");
        byLine[d.where.line] = d.message;
    }
    EXPECT_NE(byLine[1].find("keyword RD "), std::string::npos) << byLine[1];
    EXPECT_NE(byLine[2].find("LA_ON"), std::string::npos) << byLine[2];
}

TEST(MdiEntryTest, AMacroThatExpandsToAKeywordIsRefused) {
    const MdiEntry entry = prepareMdiEntry("G1 X5 ROUND", {{"ROUND", "RD5"}});
    EXPECT_FALSE(entry.runnable());
    ASSERT_FALSE(entry.diagnostics.empty());
    EXPECT_EQ(entry.diagnostics.items()[0].code, "MDI_KEYWORD_REFUSED");
}

// Fuzz finding mdi ba78da4: a header line made the parser read the entry as
// a program file, whose problems named no input line.
TEST(MdiEntryTest, AProgramFileHeaderLineIsRefusedWithItsLine) {
    const MdiEntry entry = prepareMdiEntry("G1 X5 F100\n%MAC2.5 @6=-3\nG1 X6\n", kMacros);
    EXPECT_FALSE(entry.runnable());
    ASSERT_FALSE(entry.diagnostics.items().empty());
    for (const Diagnostic& d : entry.diagnostics.items())
        EXPECT_GE(d.where.line, 1) << d.code << ": " << d.message;
    EXPECT_EQ(entry.diagnostics.items()[0].code, "MDI_HEADER_REFUSED");
    EXPECT_EQ(entry.diagnostics.items()[0].where.line, 2);
}

TEST(MdiEntryTest, AnEntryIsNeverReadAsAProgramFile) {
    // Fuzz finding mdi 633c4f6: a byte order mark before "%NPG" slipped past
    // the header refusal, and the parser read the entry as a .DAT file whose
    // missing PROGRAMMENDE it reported at line 0.
    const MdiEntry entry = prepareMdiEntry("\xEF\xBB\xBF%NPG\nS-0\n", kMacros);
    EXPECT_FALSE(entry.runnable());
    ASSERT_FALSE(entry.diagnostics.items().empty());
    for (const Diagnostic& d : entry.diagnostics.items()) {
        EXPECT_GE(d.where.line, 1) << d.code << ": " << d.message;
        EXPECT_NE(d.code.rfind("DAT_", 0), 0u) << d.code << ": no program file problems in MDI";
    }
    EXPECT_EQ(entry.diagnostics.items()[0].where.line, 1);
}

TEST(MdiEntryTest, ParseErrorsCarryTheInputLine) {
    const MdiEntry entry = prepareMdiEntry("G1 X5 F100\nG1 X=(3+\n", kMacros);
    EXPECT_FALSE(entry.runnable());
    ASSERT_TRUE(entry.diagnostics.hasErrors());
    const Diagnostic& d = entry.diagnostics.items()[0];
    EXPECT_EQ(d.where.line, 2);
    EXPECT_EQ(d.where.program, 0);
    ASSERT_FALSE(d.details.empty());
    EXPECT_EQ(d.details.back(), "MDI input line 2: G1 X=(3+");
    EXPECT_EQ(formatMdiDiagnostic(d).rfind("MDI line 2: error [", 0), 0u) << formatMdiDiagnostic(d);
}

TEST(MdiEntryTest, EmptyAndOversizedInputsAreRefused) {
    EXPECT_EQ(prepareMdiEntry("", kMacros).diagnostics.items().at(0).code, "MDI_EMPTY");
    EXPECT_EQ(prepareMdiEntry("  \n; only a comment\n", kMacros).diagnostics.items().at(0).code,
              "MDI_EMPTY");
    std::string many;
    for (std::size_t i = 0; i <= kMaxMdiLines; ++i)
        many += "G1 X1\n";
    EXPECT_EQ(prepareMdiEntry(many, kMacros).diagnostics.items().at(0).code, "MDI_TOO_LONG");
    const MdiEntry wide = prepareMdiEntry("G1 X1 ;" + std::string(kMaxMdiLineLength, 'a'), kMacros);
    EXPECT_EQ(wide.diagnostics.items().at(0).code, "MDI_TOO_LONG");
}

TEST(MdiRunTest, StateContinuesAcrossEntries) {
    Station mill(demoCell(), 0);
    runMdi(mill, "G1 G91 X10 F1000 M3 S500 @5=7");
    const InterpreterState& s = mill.interpreter->state();
    EXPECT_DOUBLE_EQ(s.modal.machine[0], 10.0);
    // The end of an entry is no program end: G1, G91, F, M3, S stay.
    EXPECT_EQ(s.modal.g[kGroupInterpolation], 1);
    EXPECT_EQ(s.modal.g[kGroupDimension], 91);
    EXPECT_DOUBLE_EQ(s.modal.feed, 1000.0);
    EXPECT_EQ(s.mGroups[2], 3);

    // The next entry moves incrementally with the modal feed of the first.
    runMdi(mill, "X5\nX=@5");
    EXPECT_DOUBLE_EQ(s.modal.machine[0], 22.0);
    EXPECT_EQ(s.modal.g[kGroupInterpolation], 1);
    EXPECT_DOUBLE_EQ(variable(mill, 5), 7.0);
    EXPECT_NE(mill.sink->text.find("motion - L2 linear X=22.0000"), std::string::npos)
        << mill.sink->text;
}

TEST(MdiRunTest, AnEntryContinuesFromAProgramAndHandsItBack) {
    Station mill(demoCell(), 0);
    ProgramPtr program = mill.add("N1 G0 G90 X40 Y20\nN2 @9=3\nN3 M30\n", 1);
    ASSERT_TRUE(mill.interpreter->select(1));
    ASSERT_EQ(mill.interpreter->run().status, RunStatus::Ended);
    runMdi(mill, "G1 Y25 F300");
    const InterpreterState& s = mill.interpreter->state();
    EXPECT_DOUBLE_EQ(s.modal.machine[0], 40.0);
    EXPECT_DOUBLE_EQ(s.modal.machine[1], 25.0);
    EXPECT_DOUBLE_EQ(variable(mill, 9), 3.0);
    EXPECT_EQ(s.selected, program) << "the automatic program is selected again";
    EXPECT_EQ(s.program, program);
    EXPECT_EQ(s.block, 0u);
}

TEST(MdiRunTest, AnM30InTheEntryResetsLikeAProgramEnd) {
    Station mill(demoCell(), 0);
    const RunResult r = runMdi(mill, "G1 G91 X3 F200\nM30");
    EXPECT_EQ(r.status, RunStatus::Ended);
    EXPECT_EQ(mill.interpreter->state().modal.g[kGroupDimension], 90);
    EXPECT_DOUBLE_EQ(mill.interpreter->state().modal.machine[0], 3.0);
}

TEST(MdiRunTest, ARuntimeErrorNamesTheInputLineAndKeepsTheStateBefore) {
    Station mill(demoCell(), 0);
    const MdiEntry entry = prepareMdiEntry("G1 X5 F500\nG1 X8 A10\nX20", kMacros);
    ASSERT_TRUE(entry.runnable());
    MdiRun run;
    ASSERT_TRUE(run.begin(*mill.interpreter, entry.program));
    const RunResult r = run.run();
    EXPECT_EQ(r.status, RunStatus::Error);
    EXPECT_FALSE(run.active()) << "an error ends the entry";
    ASSERT_EQ(errorCodes(r.diagnostics), std::vector<std::string>{"AXIS_UNKNOWN"});
    EXPECT_EQ(r.diagnostics.items()[0].where.line, 2);
    EXPECT_EQ(formatMdiDiagnostic(r.diagnostics.items()[0]).rfind("MDI line 2: error", 0), 0u);
    EXPECT_DOUBLE_EQ(mill.interpreter->state().modal.machine[0], 5.0);
}

TEST(MdiRunTest, StepsStopAtM00AndGoOn) {
    Station mill(demoCell(), 0);
    const MdiEntry entry = prepareMdiEntry("G1 X1 F100\nM0\nX2", kMacros);
    MdiRun run;
    ASSERT_TRUE(run.begin(*mill.interpreter, entry.program));
    EXPECT_EQ(run.run().status, RunStatus::Stopped);
    EXPECT_TRUE(run.active());
    EXPECT_EQ(run.run().status, RunStatus::Ended);
    EXPECT_DOUBLE_EQ(mill.interpreter->state().modal.machine[0], 2.0);
}

TEST(MdiRunTest, TheLastBlockEndsTheEntry) {
    Station mill(demoCell(), 0);
    const MdiEntry entry = prepareMdiEntry("G1 X1 F100\n\nX2 ;last", kMacros);
    MdiRun run;
    ASSERT_TRUE(run.begin(*mill.interpreter, entry.program));
    EXPECT_EQ(run.step().status, RunStatus::Running);
    EXPECT_TRUE(run.active());
    const RunResult last = run.step();
    EXPECT_EQ(last.status, RunStatus::Ended) << "no extra step (or single-block hold) after X2";
    EXPECT_EQ(last.blocksInterpreted, 1u);
    EXPECT_FALSE(run.active());
    EXPECT_DOUBLE_EQ(mill.interpreter->state().modal.machine[0], 2.0);
}

TEST(MdiRunTest, AnEndlessEntryIsBoundedByTheBudget) {
    Station mill(demoCell(), 0);
    const MdiEntry entry = prepareMdiEntry("N1 .LOOP @1=@1+1\nN2 BRA .LOOP", kMacros);
    ASSERT_TRUE(entry.runnable());
    MdiRun run;
    ASSERT_TRUE(run.begin(*mill.interpreter, entry.program));
    const RunResult r = run.run(1000);
    EXPECT_EQ(r.status, RunStatus::BudgetExceeded);
    EXPECT_FALSE(run.active());
}

TEST(MdiRefusalTest, OnlyInMdiModeAndWithoutAnActiveProgram) {
    ProcessControl control(0);
    EXPECT_NE(mdiRefusal(control).find("select MDI mode"), std::string::npos);
    ASSERT_TRUE(control.press(ControlKey::Mdi));
    EXPECT_EQ(control.mode(), OperatingMode::Mdi);
    EXPECT_EQ(mdiRefusal(control), "");
    control.setProgramActive(true);
    EXPECT_NE(mdiRefusal(control).find("program is active"), std::string::npos);
    EXPECT_FALSE(control.press(ControlKey::Automatic)) << "no mode change while the entry runs";
}

// The refusals in the station's language (docs/DECISIONS.md D-026): the
// German text drops the English mode name (the panel translates modes).
TEST(MdiRefusalTest, InTheStationsLanguage) {
    ProcessControl control(0);
    control.setLanguage(Language::German);
    EXPECT_EQ(mdiRefusal(control), "MDI abgelehnt: zuerst Betriebsart MDI anwählen");
    control.setLanguage(Language::English);
    EXPECT_EQ(mdiRefusal(control), "MDI refused: select MDI mode first (now " +
                                       std::string(modeName(control.mode())) + " mode)");
    ASSERT_TRUE(control.press(ControlKey::Mdi));
    control.setProgramActive(true);
    control.setLanguage(Language::German);
    EXPECT_EQ(mdiRefusal(control),
              "MDI abgelehnt: ein Programm ist aktiv (erst Steuerung rücksetzen)");
}

TEST(MdiRefusalTest, TheMdiKeyIsRefusedDuringAnNcProgramRestart) {
    RestartStation mill(0);
    mill.addDemoPrograms();
    ASSERT_EQ(mill.restartAtDemoTarget(), RestartPhase::TargetReached);
    EXPECT_FALSE(mill.control.press(ControlKey::Mdi));
    EXPECT_NE(mill.control.alarm().find("MDI refused"), std::string::npos) << mill.control.alarm();
    EXPECT_EQ(mill.control.mode(), OperatingMode::Automatic);
    EXPECT_EQ(mill.sequence.phase(), RestartPhase::TargetReached) << "the restart goes on";
}

struct MdiRunner : ProgramRunner {
    std::string start(int number) override {
        started.push_back("program " + std::to_string(number));
        return {};
    }
    std::string startMdi() override {
        started.push_back("MDI");
        return alarm;
    }
    std::string resume() override { return {}; }
    void hold() override {}
    void reset() override {}
    std::vector<std::string> started;
    std::string alarm;
};

TEST(MdiRefusalTest, StartRunsTheEntryOnlyInMdiMode) {
    ProcessControl control(0);
    MdiRunner runner;
    control.setRunner(&runner);
    ASSERT_TRUE(control.selectProgram(4));
    ASSERT_TRUE(control.press(ControlKey::Start));  // automatic: the selected program
    control.programFinished({});
    ASSERT_TRUE(control.press(ControlKey::Mdi));
    ASSERT_TRUE(control.press(ControlKey::Start));
    EXPECT_TRUE(control.programActive());
    control.programFinished({});
    runner.alarm = "MDI line 1: error [MDI_KEYWORD_REFUSED]: no";
    EXPECT_FALSE(control.press(ControlKey::Start));
    EXPECT_FALSE(control.programActive());
    EXPECT_EQ(control.alarm(), runner.alarm);
    EXPECT_EQ(runner.started, (std::vector<std::string>{"program 4", "MDI", "MDI"}));
    ASSERT_TRUE(control.press(ControlKey::Manual));
    EXPECT_FALSE(control.press(ControlKey::Start));
    EXPECT_EQ(runner.started.size(), 3u);
}

TEST(MdiFuzzTest, RandomLinesNeverCrash) {
    std::mt19937 random(20261121);
    const std::string alphabet = "GXYZFMSTN@=.()+-*/;_ \n0123456789ABCDEFKLORUVW:[],\t\"%";
    const std::vector<std::string> words = {"DEFINE", "AS", "FAST", "RD",  "CF",   "LA_ON",
                                            "JMP",    ".L", "BSR",  "RTS", "MTD(", "G1 X"};
    Station mill(demoCell(), 0);
    int ran = 0;
    for (int round = 0; round < 5000; ++round) {
        std::string input;
        const int length = static_cast<int>(random() % 80);
        for (int i = 0; i < length; ++i) {
            if (random() % 6 == 0)
                input += words[random() % words.size()];
            else
                input += alphabet[random() % alphabet.size()];
        }
        const MdiEntry entry = prepareMdiEntry(input, kMacros);
        EXPECT_EQ(entry.runnable(), entry.program != nullptr);
        for (const Diagnostic& d : entry.diagnostics.items())
            EXPECT_LE(d.where.line, static_cast<int>(entry.lines.size()) + 1) << input;
        if (!entry.runnable()) continue;
        MdiRun run;
        if (!run.begin(*mill.interpreter, entry.program)) continue;
        ++ran;
        const RunResult r = run.run(500);
        if (r.status == RunStatus::Stopped) run.abandon();
        EXPECT_FALSE(run.active());
    }
    EXPECT_GT(ran, 0) << "some random entries are runnable";
}

}  // namespace
