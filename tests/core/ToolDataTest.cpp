// Tool lists and zero offsets as core data (issue 16 §4): the content the
// machine configuration gives, the file formats (round trip, strict
// refusals naming file, line, key, value and range; a cut-off file),
// atomic saves beside the machine data.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "InterpTestSupport.h"
#include "cnc_core/tooldata/SetupData.h"

namespace {

using namespace mtc::core;
using namespace mtc::test;
namespace fs = std::filesystem;

std::string firstMessage(const DiagnosticList& diagnostics) {
    return diagnostics.empty() ? std::string() : diagnostics.items().front().message;
}

TEST(ToolData, TheConfigurationGivesEdgeOneOfEveryTool) {
    const ToolList mill = ToolList::fromConfig(*demoCell().process(0));
    ASSERT_EQ(mill.tools().size(), 24u);
    const ToolEdge* t1 = mill.edge(1, 1);
    ASSERT_NE(t1, nullptr);
    EXPECT_EQ(t1->radius, 3.5);
    EXPECT_EQ(t1->length3, 82.5) << "a milling tool's length is on the perpendicular axis (G17)";
    EXPECT_EQ(mill.find(1)->name, "mill1");
    const ToolList lathe = ToolList::fromConfig(*demoCell().process(1));
    EXPECT_EQ(lathe.edge(1, 0)->orientation, 3);
    EXPECT_EQ(lathe.edge(1, 1)->length2, 61.5) << "a turning tool: radial, along X (L2 of G18)";
    EXPECT_EQ(lathe.edge(1, 1)->length1, 0.0);
    EXPECT_EQ(lathe.edge(9, 1)->length3, 73.5) << "the driven tool: along its own axis (L3)";
    EXPECT_EQ(lathe.edge(9, 2), nullptr);
}

TEST(ToolData, ToolFileRoundTripsEveryValue) {
    ToolLists lists;
    ToolEdge e;
    e.edge = 2;
    e.radius = 0.4;
    e.radiusWear = -0.012;
    e.length1 = 61.5;
    e.length2 = -12.25;
    e.length3Wear = 0.003;
    e.orientation = 3;
    e.cornerAngle = 55;
    e.settingAngle = 93;
    lists[1].setEdge(1234567, e, "turn.fine-2");
    e.edge = 1;
    lists[1].setEdge(1234567, e);
    lists[0];  // a process with an empty list keeps its section
    const std::string text = formatToolFile(lists);
    ToolLists read;
    DiagnosticList diagnostics;
    ASSERT_TRUE(parseToolFile(text, "x.tools", read, diagnostics)) << diagnosticsText(diagnostics);
    EXPECT_TRUE(read[1] == lists[1]);
    ASSERT_EQ(read.count(0), 1u);
    EXPECT_TRUE(read[0].empty());
    EXPECT_EQ(formatToolFile(read), text);
}

struct Refusal {
    const char* record;
    const char* expected;  ///< part of the message
};

TEST(ToolData, EveryBadValueIsRefusedWithFileLineKeyValueAndRange) {
    const Refusal cases[] = {
        {"T1 E1 radius=abc",
         ":4: key 'radius' = 'abc': not a decimal number (allowed 0 .. 999.99999 mm)"},
        {"T1 E1 radius=nan", "'nan': not a decimal number"},
        {"T1 E1 radius=inf", "'inf': not a decimal number"},
        {"T1 E1 radius=0x10", "'0x10': not a decimal number"},
        {"T1 E1 radius=5,5", "'5,5': not a decimal number"},
        {"T1 E1 radius=-1", "'-1': out of range (allowed 0 .. 999.99999 mm)"},
        {"T1 E1 radius=1e308", "out of range"},
        {"T1 E1 l3=10000", "key 'l3' = '10000': out of range (allowed -9999.9999 .. 9999.9999 mm)"},
        {"T1 E1 orientation=10", "key 'orientation' = '10': out of range (allowed 0 .. 9)"},
        {"T1 E1 orientation=2.5", "not a whole number"},
        {"T1 E1 corner_angle=181", "allowed 0 .. 180 degrees"},
        {"T1 E1 colour=red", "key 'colour' = 'red': unknown key"},
        {"T1 E1 radius=1 radius=2", "key given twice"},
        {"T1 E10 radius=1", "key 'E' = '10': out of range (allowed 1 .. 9)"},
        {"T0 E1 radius=1", "key 'T' = '0': out of range (allowed 1 .. 9999999)"},
        {"T1 radius=1", "expected E<number>"},
        {"T1 E1 name=a/b", "key 'name' = 'a/b'"},
        {"T1 E1 radius", "expected key=value"},
    };
    for (const Refusal& c : cases) {
        const std::string text = std::string("# tools\nformat = mtc200-tools 1\n[process 0]\n") +
                                 c.record + "\nend = 1\n";
        ToolLists lists;
        lists[5];  // must stay untouched
        DiagnosticList diagnostics;
        EXPECT_FALSE(parseToolFile(text, "/tmp/x.tools", lists, diagnostics)) << c.record;
        EXPECT_NE(firstMessage(diagnostics).find(c.expected), std::string::npos)
            << c.record << " -> " << firstMessage(diagnostics);
        EXPECT_NE(firstMessage(diagnostics).find("/tmp/x.tools:4"), std::string::npos);
        EXPECT_EQ(diagnostics.items().front().where.line, 4);
        EXPECT_EQ(lists.size(), 1u) << "nothing changes on a refusal";
    }
}

TEST(ToolData, FrameProblemsAreRefused) {
    const std::pair<const char*, const char*> cases[] = {
        {"", "empty file"},
        {"[process 0]\nend = 0\n", "must start with 'format = mtc200-tools 1'"},
        {"format = mtc200-tools 2\n", "must start with"},
        {"format = mtc200-tools 1\n[process 0]\nT1 E1 radius=1\n", "no 'end = N' line"},
        {"format = mtc200-tools 1\n[process 0]\nT1 E1 radius=1\nT2 E1 radius=1\nend = 1\n",
         "the file holds 2 records"},
        {"format = mtc200-tools 1\n[process 0]\nT1 E1 radius=1\nT1 E1 radius=2\nend = 2\n",
         "T1 E1 is given twice"},
        {"format = mtc200-tools 1\nT1 E1\nend = 1\n", "before any '[process N]'"},
        {"format = mtc200-tools 1\n[process 7]\nend = 0\n", "key 'process' = '7'"},
        {"format = mtc200-tools 1\n[process 0]\n[process 0]\nend = 0\n", "section given twice"},
        {"format = mtc200-tools 1\n[process 0]\nend = 0\nT1 E1\n", "nothing may follow"},
        {"format = mtc200-tools 1\n[process 0]\nT1 E1 name=a\nT1 E2 name=b\nend = 2\n",
         "is named 'a' on another edge"},
    };
    for (const auto& [text, expected] : cases) {
        ToolLists lists;
        DiagnosticList diagnostics;
        EXPECT_FALSE(parseToolFile(text, "t.tools", lists, diagnostics)) << text;
        EXPECT_NE(firstMessage(diagnostics).find(expected), std::string::npos)
            << text << " -> " << firstMessage(diagnostics);
    }
}

TEST(ToolData, EveryCutOfAValidFileIsRefusedOrReadsTheSame) {
    ToolLists lists;
    lists[0] = ToolList::fromConfig(*demoCell().process(0));
    const std::string text = formatToolFile(lists);
    for (std::size_t cut = 0; cut < text.size(); ++cut) {
        ToolLists read;
        DiagnosticList diagnostics;
        if (parseToolFile(text.substr(0, cut), "t.tools", read, diagnostics)) {
            EXPECT_TRUE(read[0] == lists[0]) << "a cut at " << cut << " read as a different list";
        }
    }
}

TEST(ToolData, OffsetFileRoundTripsAndRefusesBadColumns) {
    DiagnosticList diagnostics;
    ZeroOffsetTables tables;
    tables[0] = ZeroOffsetTable::build(*demoCell().process(0), diagnostics);
    const std::string text = formatOffsetFile(tables);
    EXPECT_NE(text.find("G54 X=-150 Y=-80 Z=-120\n"), std::string::npos) << text;
    ZeroOffsetTables read;
    ASSERT_TRUE(parseOffsetFile(text, "o.offsets", read, diagnostics));
    EXPECT_EQ(read[0].value(55, AxisDefinition::X), 50.0);
    EXPECT_EQ(formatOffsetFile(read), text);
    const std::pair<const char*, const char*> bad[] = {
        {"G53 X=1", "key 'code' = 'G53': allowed G54 .. G59"},
        {"G54 Q=1", "key 'Q' = '1': not an axis definition"},
        {"G54 X=1e308", "key 'X' = '1e308': out of range (allowed -99999.9999 .. 99999.9999"},
        {"G54 X=1 X=2", "column given twice"},
        {"G54 X=nan", "not a decimal number"},
    };
    for (const auto& [record, expected] : bad) {
        const std::string file =
            std::string("format = mtc200-offsets 1\n[process 0]\n") + record + "\nend = 1\n";
        DiagnosticList problems;
        EXPECT_FALSE(parseOffsetFile(file, "o.offsets", read, problems)) << record;
        EXPECT_NE(firstMessage(problems).find(expected), std::string::npos)
            << record << " -> " << firstMessage(problems);
        EXPECT_NE(firstMessage(problems).find("o.offsets:3"), std::string::npos);
    }
}

class SetupDataFilesTest : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("mtc-tooldata-" + std::to_string(::getpid()) + "-" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

TEST_F(SetupDataFilesTest, FilesLiveBesideTheMachineDataAndChangesSurviveALoad) {
    const SetupDataFiles files = setupDataFilesBeside((dir_ / "cell.v2.mdt").string());
    EXPECT_EQ(files.tools, (dir_ / "cell.v2.tools").string());
    EXPECT_EQ(files.offsets, (dir_ / "cell.v2.offsets").string());
    EXPECT_TRUE(setupDataFilesBeside("").tools.empty());

    DiagnosticList diagnostics;
    SetupData data = SetupData::fromConfig(demoCell(), diagnostics);
    ASSERT_TRUE(data.load(files, diagnostics)) << "missing files keep the configuration's data";
    ToolEdge edge = *data.tools(0)->edge(3, 1);
    edge.radiusWear = -0.05;
    data.tools(0)->setEdge(3, edge);
    data.offsets(1)->set(56, AxisDefinition::Z, 12.5);
    ASSERT_TRUE(data.saveTools(files.tools, diagnostics)) << diagnosticsText(diagnostics);
    ASSERT_TRUE(data.saveOffsets(files.offsets, diagnostics));

    SetupData again = SetupData::fromConfig(demoCell(), diagnostics);
    ASSERT_TRUE(again.load(files, diagnostics)) << diagnosticsText(diagnostics);
    EXPECT_EQ(again.tools(0)->edge(3, 1)->totalRadius(), 6.5 - 0.05);
    EXPECT_EQ(again.offsets(1)->value(56, AxisDefinition::Z), 12.5);
    EXPECT_EQ(again.offsets(0)->value(54, AxisDefinition::X), -150.0);
    for (const auto& entry : fs::directory_iterator(dir_))
        EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << "no temporary left";
}

TEST_F(SetupDataFilesTest, ARefusedFileChangesNothing) {
    const SetupDataFiles files = setupDataFilesBeside((dir_ / "cell.mdt").string());
    std::ofstream(files.tools) << "format = mtc200-tools 1\n[process 3]\nT1 E1 radius=1\nend = 1\n";
    DiagnosticList diagnostics;
    SetupData data = SetupData::fromConfig(demoCell(), diagnostics);
    EXPECT_FALSE(data.load(files, diagnostics));
    EXPECT_NE(diagnosticsText(diagnostics).find("process 3 is not in the machine configuration"),
              std::string::npos);
    EXPECT_EQ(data.tools(0)->tools().size(), 24u);
}

}  // namespace
