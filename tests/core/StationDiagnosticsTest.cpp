// The station's diagnostics stay data from where they arise to whoever
// reads them (issue 16: the error window no longer parses alarm texts), and
// the station owns manual data input (its input, history and message).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "InterpTestSupport.h"
#include "cnc_core/cell/Cell.h"
#include "cnc_core/cell/DiagnosticLog.h"

namespace mtc::test {
namespace {

using core::ControlKey;
using core::DiagnosticSource;
using core::LoggedDiagnostic;

std::vector<LoggedDiagnostic> recordsAfter(const core::Station& station, std::uint64_t after) {
    std::vector<LoggedDiagnostic> records;
    station.diagnostics().forEachAfter(after,
                                       [&](const LoggedDiagnostic& r) { records.push_back(r); });
    return records;
}

void runToRest(core::Cell& cell, core::Station& station) {
    for (int i = 0; i < 10'000 && station.busy(); ++i)
        cell.advance(0.1);
    ASSERT_FALSE(station.busy());
}

TEST(DiagnosticLog, KeepsTheNewestRecordsWithSerialsNeverReused) {
    core::DiagnosticLog log;
    core::Diagnostic d;
    for (int i = 0; i < static_cast<int>(core::DiagnosticLog::kCapacity) + 5; ++i) {
        d.message = "m" + std::to_string(i + 1);
        log.add(DiagnosticSource::Run, d);
    }
    EXPECT_EQ(log.size(), core::DiagnosticLog::kCapacity);
    EXPECT_EQ(log.lastSerial(), core::DiagnosticLog::kCapacity + 5);
    std::vector<std::uint64_t> serials;
    log.forEachAfter(log.lastSerial() - 2,
                     [&](const LoggedDiagnostic& r) { serials.push_back(r.serial); });
    EXPECT_EQ(serials, (std::vector<std::uint64_t>{log.lastSerial() - 1, log.lastSerial()}));
    std::uint64_t oldest = 0;
    log.forEachAfter(0, [&](const LoggedDiagnostic& r) {
        if (oldest == 0) oldest = r.serial;
    });
    EXPECT_EQ(oldest, 6u) << "the five oldest records went first";
}

TEST(StationDiagnostics, ARuntimeErrorIsLoggedWithItsPlaceAsData) {
    core::Cell cell(demoCell());
    // A message text that looks like a place ("line 7: ") must not matter:
    // nobody parses it any more.
    cell.addProgram(0, 4, "t.nc", "N0001 G1 G90 X10 F600\nN0002 T999\nN0003 M30\n");
    core::Station& mill = cell.station(0);
    ASSERT_TRUE(mill.selectProgram(4));
    const std::uint64_t before = mill.diagnostics().lastSerial();
    ASSERT_TRUE(mill.press(ControlKey::Start));
    runToRest(cell, mill);
    const auto records = recordsAfter(mill, before);
    ASSERT_EQ(records.size(), 1u);
    EXPECT_EQ(records[0].source, DiagnosticSource::Run);
    EXPECT_EQ(records[0].diagnostic.severity, core::Severity::Error);
    EXPECT_EQ(records[0].diagnostic.where.program, 4);
    EXPECT_EQ(records[0].diagnostic.where.block, "N0002");
    EXPECT_EQ(records[0].diagnostic.where.line, 2);
    EXPECT_FALSE(records[0].diagnostic.code.empty());
    EXPECT_NE(mill.control().alarm().find(records[0].diagnostic.message), std::string::npos)
        << "the alarm line shows the logged error: " << mill.control().alarm();
}

TEST(StationDiagnostics, TheStationRunsItsOwnMdiInput) {
    core::Cell cell(demoCell());
    core::Station& mill = cell.station(0);
    ASSERT_TRUE(mill.press(ControlKey::Mdi));
    mill.setMdiInput("G1 G90 X5 F600\nG1 X8 A10");
    const std::uint64_t before = mill.diagnostics().lastSerial();
    ASSERT_TRUE(mill.press(ControlKey::Start));
    runToRest(cell, mill);
    EXPECT_DOUBLE_EQ(mill.machine().position(0), 5.0) << "line 1 ran, line 2 refused";
    const auto records = recordsAfter(mill, before);
    ASSERT_EQ(records.size(), 1u);
    const core::Diagnostic& d = records[0].diagnostic;
    EXPECT_EQ(records[0].source, DiagnosticSource::Mdi);
    EXPECT_EQ(d.code, "AXIS_UNKNOWN");
    EXPECT_EQ(d.where.line, 2);
    ASSERT_FALSE(d.details.empty());
    EXPECT_EQ(d.details.back(), "MDI input line 2: G1 X8 A10");
    ASSERT_EQ(mill.mdi().history().size(), 1u);
    EXPECT_EQ(mill.mdi().history()[0].outcome, "error line 2: " + d.message);
    EXPECT_EQ(mill.mdi().input(), "G1 G90 X5 F600\nG1 X8 A10") << "a failed entry stays";
    EXPECT_TRUE(mill.mdi().messageIsError());
    EXPECT_EQ(mill.mdi().message().rfind("MDI line 2: error [AXIS_UNKNOWN]", 0), 0u)
        << mill.mdi().message();

    // Corrected and run again: it ends, the input is cleared (MDI-004).
    mill.setMdiInput("G1 X8");
    ASSERT_TRUE(mill.press(ControlKey::Start));
    runToRest(cell, mill);
    EXPECT_DOUBLE_EQ(mill.machine().position(0), 8.0);
    EXPECT_EQ(mill.mdi().history().back().outcome, "done");
    EXPECT_EQ(mill.mdi().input(), "");
    EXPECT_FALSE(mill.mdi().messageIsError());
}

TEST(StationDiagnostics, ARefusedMdiCheckIsLoggedAndRunsNothing) {
    core::Cell cell(demoCell());
    core::Station& mill = cell.station(0);
    mill.setMdiInput("G1 X5 F100\nDEFINE SLOW AS F10");
    const std::uint64_t before = mill.diagnostics().lastSerial();
    EXPECT_FALSE(mill.checkMdi());
    const auto records = recordsAfter(mill, before);
    ASSERT_FALSE(records.empty());
    EXPECT_EQ(records[0].source, DiagnosticSource::Mdi);
    EXPECT_EQ(records[0].diagnostic.code, "MDI_KEYWORD_REFUSED");
    EXPECT_EQ(records[0].diagnostic.where.line, 2);
    EXPECT_TRUE(mill.mdi().history().empty());
    mill.setMdiInput("G1 X5 F100");
    EXPECT_TRUE(mill.checkMdi());
    EXPECT_EQ(mill.mdi().message(), "Input correct: G1 X5 F100");
}

TEST(StationDiagnostics, GlobalMacrosOfTheCellExpandInMdi) {
    core::Cell cell(demoCell());
    core::NcOptions options;
    options.globalMacros.push_back({"FAR", "X12"});
    cell.setNcOptions(options);
    core::Station& mill = cell.station(0);
    ASSERT_TRUE(mill.press(ControlKey::Mdi));
    mill.setMdiInput("G1 G90 FAR F600");
    ASSERT_TRUE(mill.press(ControlKey::Start)) << mill.control().alarm();
    runToRest(cell, mill);
    EXPECT_DOUBLE_EQ(mill.machine().position(0), 12.0);
}

}  // namespace
}  // namespace mtc::test
