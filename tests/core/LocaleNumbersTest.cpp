// Numbers whatever the desk's locale (issue 20 §2, D-013): the process is
// switched to de_DE.UTF-8 (decimal comma, as the panel's QApplication does
// on a German desk) and machine data, tool data, configuration values and a
// program's values still read and write with '.' and round-trip exactly.
#include <gtest/gtest.h>

#include <clocale>
#include <cstdio>
#include <string>

#include "InterpTestSupport.h"
#include "cnc_core/machine/ConfigText.h"
#include "cnc_core/machine_data/MachineDataFile.h"
#include "cnc_core/machine_data/MachineDataStore.h"
#include "cnc_core/machine_data/MachineDataType.h"
#include "cnc_core/text/Numbers.h"
#include "cnc_core/tooldata/DataFileText.h"
#include "cnc_core/tooldata/SetupData.h"

namespace {

using namespace mtc::core;

/// The whole process in the German locale for one test, restored after it.
class GermanLocale : public ::testing::Test {
  protected:
    void SetUp() override {
        saved_ = std::setlocale(LC_ALL, nullptr);
        if (!std::setlocale(LC_ALL, "de_DE.UTF-8"))
            GTEST_SKIP() << "locale de_DE.UTF-8 is not installed (scripts/setup.sh installs it)";
        char text[16];
        std::snprintf(text, sizeof text, "%.1f", 0.5);
        ASSERT_STREQ(text, "0,5") << "the C library must write a decimal comma in this test";
    }
    void TearDown() override { std::setlocale(LC_ALL, saved_.c_str()); }

  private:
    std::string saved_;
};

struct RecordingSink : MachineSink {
    std::vector<Motion> motions;
    void motion(const Motion& m) override { motions.push_back(m); }
    void auxiliary(const AuxOutput&) override {}
    void dwell(const SourceLocation&, double) override {}
    void command(const MachineCommand&) override {}
};

TEST_F(GermanLocale, NumberTextIsTheCLocales) {
    EXPECT_EQ(formatGeneral(0.5, 10), "0.5");
    EXPECT_EQ(formatGeneral(1e6), "1e+06");
    EXPECT_EQ(formatGeneral(-1234.5678, 6), "-1234.57");
    EXPECT_EQ(formatFixed(2.5, 4), "2.5000");
    EXPECT_EQ(formatFixed(-0.04, 1), "-0.0");
    EXPECT_EQ(formatRoundTrip(0.1), "0.1");
    double value = 0;
    EXPECT_EQ(readNumberPrefix(std::string_view("12.75"), value), 5u);
    EXPECT_EQ(value, 12.75);
    EXPECT_EQ(readNumberPrefix(std::string_view("  -3.5e2,1"), value), 8u);
    EXPECT_EQ(value, -350.0);
    EXPECT_EQ(readNumberPrefix(std::string_view("+.5"), value), 3u);
    EXPECT_EQ(value, 0.5);
    EXPECT_EQ(readNumberPrefix(std::string_view("1e999"), value), 5u);
    EXPECT_EQ(value, HUGE_VAL);
    EXPECT_EQ(readNumberPrefix(std::string_view("x1"), value), 0u);
    EXPECT_EQ(leadingNumber("5,5"), 5.0) << "a decimal comma is never a decimal point";
}

TEST_F(GermanLocale, MachineDataFileRoundTripsExactly) {
    MachineDataStore original(mtc::test::demoCell());
    ASSERT_EQ(original.write({180, 1, 0, 2}, 612.25, MachineDataWriter::Sps),
              MachineDataStatus::Ok);
    ASSERT_EQ(original.write({30, 0, 0, 10}, 0.1, MachineDataWriter::Nc), MachineDataStatus::Ok);
    const std::string text = MachineDataFile::serialize(original);
    EXPECT_NE(text.find("\n1 180 0 2 612.25\n"), std::string::npos) << text;
    EXPECT_EQ(text.find(','), std::string::npos) << text;
    std::string cell, reason;
    std::vector<MachineDataStore::Entry> entries;
    ASSERT_TRUE(MachineDataFile::parse(text, cell, entries, reason)) << reason;
    MachineDataStore copy(mtc::test::demoCell());
    EXPECT_TRUE(copy.restore(entries).empty());
    double value = 0;
    ASSERT_EQ(copy.read({180, 1, 0, 2}, value), MachineDataStatus::Ok);
    EXPECT_EQ(value, 612.25);
    ASSERT_EQ(copy.read({30, 0, 0, 10}, value), MachineDataStatus::Ok);
    EXPECT_EQ(value, 0.1);
    EXPECT_EQ(MachineDataFile::serialize(copy), text);
}

TEST_F(GermanLocale, ToolAndOffsetFilesRoundTripExactly) {
    ToolLists lists;
    ToolEdge e;
    e.edge = 1;
    e.radius = 0.4;
    e.radiusWear = -0.012;
    e.length2 = -12.25;
    e.cornerAngle = 55.5;
    lists[0].setEdge(7, e, "fine");
    const std::string text = formatToolFile(lists);
    EXPECT_NE(text.find("radius=0.4"), std::string::npos) << text;
    EXPECT_EQ(text.find(','), std::string::npos) << text;
    ToolLists read;
    DiagnosticList diagnostics;
    ASSERT_TRUE(parseToolFile(text, "x.tools", read, diagnostics))
        << mtc::test::diagnosticsText(diagnostics);
    EXPECT_TRUE(read[0] == lists[0]);
    EXPECT_EQ(formatToolFile(read), text);

    ZeroOffsetTables tables;
    tables[0] = ZeroOffsetTable::build(*mtc::test::demoCell().process(0), diagnostics);
    tables[0].set(54, AxisDefinition::X, -140.5);
    const std::string offsets = formatOffsetFile(tables);
    EXPECT_NE(offsets.find("G54 X=-140.5 "), std::string::npos) << offsets;
    ZeroOffsetTables back;
    ASSERT_TRUE(parseOffsetFile(offsets, "o.offsets", back, diagnostics));
    EXPECT_EQ(back[0].value(54, AxisDefinition::X), -140.5);
}

TEST_F(GermanLocale, ConfigurationAndDisplayTextsUseThePoint) {
    EXPECT_EQ(formatConfigNumber(0.01), "0.01");
    EXPECT_EQ(formatMachineDataValue(MachineDataType::Real, 612.25), "612.25");
    EXPECT_EQ(formatDataNumber(-0.012), "-0.012");
    double value = 0;
    EXPECT_EQ(readDecimal("2.5", value), NumberProblem::None);
    EXPECT_EQ(value, 2.5);
    EXPECT_EQ(readDecimal("2,5", value), NumberProblem::NotANumber);
}

TEST_F(GermanLocale, ProgramValuesAreReadExactly) {
    mtc::test::Station station(mtc::test::demoCell(), 0);
    RecordingSink sink;
    station.interpreter = std::make_unique<Interpreter>(station.config, station.store, sink);
    station.add(
        "N0001 G1 G90 X12.345 Y-0.5 F1500.5\nN0002 @1=2.25\nN0003 X@1\n"
        "N0004 Y7.125\nN0005 M30\n",
        1);
    ASSERT_TRUE(station.interpreter->select(1, 0, nullptr));
    const RunResult result = station.interpreter->run(kDefaultBlockBudget);
    EXPECT_TRUE(result.diagnostics.empty()) << mtc::test::diagnosticsText(result.diagnostics);
    ASSERT_GE(sink.motions.size(), 3u);
    EXPECT_EQ(sink.motions[0].end[0], 12.345);
    EXPECT_EQ(sink.motions[0].end[1], -0.5);
    EXPECT_EQ(sink.motions[0].feed, 1500.5);
    EXPECT_EQ(sink.motions[1].end[0], 2.25);
    EXPECT_EQ(sink.motions.back().end[1], 7.125);
}

}  // namespace
