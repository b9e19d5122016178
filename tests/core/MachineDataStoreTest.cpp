// The machine data store: page definitions (30, 60, 61, user pages), write
// protection per writer, password, data types and ranges, NC-internal
// updates, and MTD in NC programs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "InterpTestSupport.h"
#include "cnc_core/machine/MachineConfigReader.h"
#include "cnc_core/machine_data/MachineDataStore.h"
#include "cnc_core/machine_data/StandardPages.h"

namespace {

using namespace mtc::core;
using namespace mtc::test;

TEST(MachineDataPages, Page30HasTheFourteenElementsOfSeed002) {
    const MachineDataPage page = adaptiveFeedPage();
    ASSERT_EQ(page.elements.size(), 14u);
    const std::vector<int> statusElements = {1, 5, 7, 8, 11, 12};
    for (const MachineDataElement& e : page.elements) {
        const bool isStatus = std::count(statusElements.begin(), statusElements.end(), e.number);
        EXPECT_EQ(e.protectedNc, isStatus) << e.number;
        EXPECT_EQ(e.protectedSps, isStatus) << e.number;
        EXPECT_EQ(e.protectedGui, isStatus) << e.number;
        EXPECT_TRUE(e.password) << e.number;
        EXPECT_EQ(e.minimum, 0.0) << e.number;
    }
    EXPECT_EQ(page.element(1)->type, MachineDataType::Bool);
    EXPECT_EQ(page.element(2)->type, MachineDataType::Sint);
    EXPECT_EQ(page.element(2)->maximum, 12);
    EXPECT_EQ(page.element(3)->type, MachineDataType::Ampl);
    EXPECT_EQ(page.element(3)->defaultValue, 0.1);
    EXPECT_EQ(page.element(3)->unit, "1/s");
    EXPECT_EQ(page.element(4)->type, MachineDataType::Uint);
    EXPECT_EQ(page.element(4)->maximum, 65535);
    EXPECT_EQ(page.element(4)->defaultValue, 200);
    EXPECT_EQ(page.element(10)->maximum, 999.9);
    EXPECT_EQ(page.element(11)->maximum, 100.0);
    EXPECT_EQ(page.element(13)->maximum, 100.0);
    EXPECT_EQ(page.element(14)->designation, "Stall torque");
    EXPECT_EQ(page.element(15), nullptr);
}

TEST(MachineDataPages, Pages60And61FollowSeed000) {
    const MachineDataPage restart = restartPage();
    ASSERT_EQ(restart.elements.size(), 8u);
    EXPECT_EQ(restart.subs(), std::vector<int>{0});
    EXPECT_EQ(restart.element(4)->defaultValue, 30);
    EXPECT_EQ(restart.element(8)->maximum, 9999999);
    const MachineDataPage buffers = functionBufferPage();
    EXPECT_EQ(buffers.subs(), (std::vector<int>{1, 2}));
    EXPECT_EQ(buffers.elements.size(), 40u);
    EXPECT_EQ(buffers.subSlot(0), -1);
    EXPECT_EQ(buffers.element(7)->designation, "Aux. Function 7");
}

TEST(MachineDataStore, PagesPerProcess) {
    MachineDataStore data(demoCell());
    EXPECT_EQ(data.processes(), (std::vector<int>{0, 1}));
    EXPECT_EQ(data.pageNumbers(0), (std::vector<int>{30, 60, 61}));
    EXPECT_EQ(data.pageNumbers(1), (std::vector<int>{30, 60, 61, 180}));
    EXPECT_TRUE(data.pageNumbers(4).empty());
    ASSERT_NE(data.page(1, 180), nullptr);
    EXPECT_EQ(data.page(1, 180)->title, "parts transfer");
    EXPECT_EQ(data.page(0, 180), nullptr);
}

TEST(MachineDataStore, DefaultsAndTypes) {
    MachineDataStore data(demoCell());
    double v = -1;
    ASSERT_EQ(data.read({30, 1, 0, 3}, v), MachineDataStatus::Ok);
    EXPECT_EQ(v, 0.1);
    ASSERT_EQ(data.read({30, 1, 0, 4}, v), MachineDataStatus::Ok);
    EXPECT_EQ(v, 200);
    EXPECT_EQ(data.write({30, 0, 0, 2}, 2.5, MachineDataWriter::Nc), MachineDataStatus::WrongType);
    EXPECT_EQ(data.write({30, 0, 0, 10}, 47.26, MachineDataWriter::Sps), MachineDataStatus::Ok);
    ASSERT_EQ(data.read({30, 0, 0, 10}, v), MachineDataStatus::Ok);
    EXPECT_EQ(v, 47.3) << "PERC keeps one decimal";
    EXPECT_EQ(data.write({30, 0, 0, 3}, 0.125, MachineDataWriter::Nc), MachineDataStatus::Ok);
    ASSERT_EQ(data.read({30, 0, 0, 3}, v), MachineDataStatus::Ok);
    EXPECT_NEAR(v, 0.13, 1e-12) << "AMPL keeps two decimals";
    EXPECT_EQ(data.write({30, 0, 0, 13}, 100.04, MachineDataWriter::Nc), MachineDataStatus::Ok)
        << "rounds to 100.0, inside the range";
    EXPECT_EQ(data.write({30, 0, 0, 13}, 100.06, MachineDataWriter::Nc),
              MachineDataStatus::OutOfRange);
    EXPECT_EQ(data.write({30, 0, 0, 4}, 65536, MachineDataWriter::Nc),
              MachineDataStatus::OutOfRange);
    EXPECT_EQ(data.write({30, 0, 0, 2}, -1, MachineDataWriter::Nc), MachineDataStatus::OutOfRange);
    EXPECT_EQ(data.write({30, 0, 0, 6}, std::nan(""), MachineDataWriter::Nc),
              MachineDataStatus::OutOfRange);
    ASSERT_EQ(data.read({30, 0, 0, 13}, v), MachineDataStatus::Ok);
    EXPECT_EQ(v, 100.0) << "failed writes keep the old value";
}

TEST(MachineDataStore, WriteProtectionPerWriter) {
    MachineDataStore data(demoCell());
    for (MachineDataWriter writer :
         {MachineDataWriter::Nc, MachineDataWriter::Sps, MachineDataWriter::Gui}) {
        EXPECT_EQ(data.write({30, 0, 0, 1}, 1, writer, "MTC200"),
                  MachineDataStatus::WriteProtected);
        EXPECT_EQ(data.write({30, 0, 0, 11}, 5, writer, "MTC200"),
                  MachineDataStatus::WriteProtected);
    }
    EXPECT_EQ(data.write({30, 0, 0, 2}, 10, MachineDataWriter::Nc), MachineDataStatus::Ok);
    EXPECT_EQ(data.write({30, 0, 0, 14}, 3.5, MachineDataWriter::Sps), MachineDataStatus::Ok);
    EXPECT_EQ(data.update({30, 0, 0, 11}, 42.5), MachineDataStatus::Ok)
        << "the NC itself updates status elements";
    EXPECT_EQ(data.update({30, 0, 0, 11}, 120), MachineDataStatus::OutOfRange);
    double v = 0;
    ASSERT_EQ(data.read({30, 0, 0, 11}, v), MachineDataStatus::Ok);
    EXPECT_EQ(v, 42.5);
}

TEST(MachineDataStore, PasswordForTheOperator) {
    MachineDataStore data(demoCell());
    EXPECT_EQ(data.write({30, 0, 0, 10}, 60, MachineDataWriter::Gui),
              MachineDataStatus::PasswordRequired);
    EXPECT_EQ(data.write({30, 0, 0, 10}, 60, MachineDataWriter::Gui, "guess"),
              MachineDataStatus::WrongPassword);
    EXPECT_EQ(data.check({30, 0, 0, 10}, 60, MachineDataWriter::Gui, kDefaultMachineDataPassword),
              MachineDataStatus::Ok);
    double v = -1;
    ASSERT_EQ(data.read({30, 0, 0, 10}, v), MachineDataStatus::Ok);
    EXPECT_EQ(v, 0) << "check() and refused writes change nothing";
    EXPECT_EQ(data.write({30, 0, 0, 10}, 60, MachineDataWriter::Gui, kDefaultMachineDataPassword),
              MachineDataStatus::Ok);
    EXPECT_EQ(data.write({60, 0, 0, 5}, 12, MachineDataWriter::Gui), MachineDataStatus::Ok)
        << "page 60 needs no password";
    EXPECT_EQ(data.write({180, 1, 0, 1}, 1, MachineDataWriter::Gui), MachineDataStatus::Ok);
}

TEST(MachineDataStore, ConfiguredPasswordAndUserProtection) {
    const MachineConfig cell = cellFromText(R"(
[cell]
name = protected
md_password = s3cret
[process 2]
name = P2
[process 2 page 300]
title = clamping
element 1 = pressure | PERC | 0 | 150 | 80 | % | password
element 2 = clamped | BOOL | 0 | 1 | 0 | - | nc gui
element 3 = cycles | UINT | 0 | 65535 | 0
)");
    MachineDataStore data(cell);
    EXPECT_EQ(data.write({300, 2, 0, 1}, 90, MachineDataWriter::Gui, "MTC200"),
              MachineDataStatus::WrongPassword);
    EXPECT_EQ(data.write({300, 2, 0, 1}, 90, MachineDataWriter::Gui, "s3cret"),
              MachineDataStatus::Ok);
    EXPECT_EQ(data.write({300, 2, 0, 1}, 95, MachineDataWriter::Nc), MachineDataStatus::Ok);
    EXPECT_EQ(data.write({300, 2, 0, 2}, 1, MachineDataWriter::Nc),
              MachineDataStatus::WriteProtected);
    EXPECT_EQ(data.write({300, 2, 0, 2}, 1, MachineDataWriter::Gui, "s3cret"),
              MachineDataStatus::WriteProtected);
    EXPECT_EQ(data.write({300, 2, 0, 2}, 1, MachineDataWriter::Sps), MachineDataStatus::Ok);
    EXPECT_EQ(data.page(2, 300)->element(2)->unit, "");
    EXPECT_EQ(data.write({300, 2, 0, 3}, 7, MachineDataWriter::Gui), MachineDataStatus::Ok);
}

TEST(MachineDataStore, RevisionCountsChangesAndResetRestoresDefaults) {
    MachineDataStore data(demoCell());
    const auto start = data.revision();
    data.write({60, 1, 0, 5}, 7, MachineDataWriter::Nc);
    EXPECT_EQ(data.revision(), start + 1);
    data.write({60, 1, 0, 5}, 7, MachineDataWriter::Nc);
    EXPECT_EQ(data.revision(), start + 1) << "the same value is no change";
    data.write({60, 1, 0, 5}, 70000000, MachineDataWriter::Nc);
    EXPECT_EQ(data.revision(), start + 1) << "refused writes are no change";
    data.resetToDefaults();
    double v = -1;
    ASSERT_EQ(data.read({60, 1, 0, 5}, v), MachineDataStatus::Ok);
    EXPECT_EQ(v, 0);
    EXPECT_GT(data.revision(), start + 1);
}

TEST(MachineDataStore, EntriesAndRestore) {
    MachineDataStore data(demoCell());
    const std::vector<MachineDataStore::Entry> all = data.entries();
    EXPECT_EQ(all.size(), 2u * (14 + 8 + 80) + 2u);
    MachineDataStore copy(demoCell());
    data.write({61, 1, 2, 40}, 9501, MachineDataWriter::Nc);
    const auto rejected = copy.restore(
        {{{61, 1, 2, 40}, 9501}, {{30, 0, 0, 1}, 1}, {{30, 0, 0, 2}, 99}, {{77, 0, 0, 1}, 1}});
    ASSERT_EQ(rejected.size(), 2u) << "out of range and unknown page";
    EXPECT_EQ(rejected[0].address.element, 2);
    EXPECT_EQ(rejected[1].address.page, 77);
    double v = 0;
    ASSERT_EQ(copy.read({30, 0, 0, 1}, v), MachineDataStatus::Ok);
    EXPECT_EQ(v, 1) << "restore puts status elements back too";
    ASSERT_EQ(copy.read({61, 1, 2, 40}, v), MachineDataStatus::Ok);
    EXPECT_EQ(v, 9501);
}

TEST(MachineDataStoreConfig, BadUserElementsAreRefused) {
    for (const char* element :
         {"element 1 = a | WORD | 0 | 1 | 0", "element 1 = a | INT | 0 | 10 | 11",
          "element 1 = a | INT | 0 | 10 | 1 | mm | nc admin",
          "element 1 = a | INT | 0 | 10 | 1 | mm | nc | more"}) {
        const auto result = readMachineConfig(std::string("[process 0]\nname = P\n"
                                                          "[process 0 page 200]\n") +
                                              element + "\n");
        ASSERT_TRUE(result.diagnostics.hasErrors()) << element;
        EXPECT_EQ(result.diagnostics.items().front().code, "CFG_PAGE") << element;
    }
    const auto spaced = readMachineConfig("[cell]\nmd_password = two words\n[process 0]\n");
    EXPECT_TRUE(spaced.diagnostics.hasErrors());
}

TEST(MachineDataInterp, MtdWritesHonourProtectionAndRange) {
    Station mill(demoCell(), 0);
    RunResult r = mill.run(
        "N1 MTD(30,,,2)=10 MTD(30,,,10)=55.55\nN2 @1=MTD(30,,,3)\n"
        "N3 MTD(30,,,1)=1\nN4 M30\n");
    ASSERT_EQ(errorCodes(r.diagnostics), std::vector<std::string>{"MTD_WRITE_PROTECTED"});
    const Diagnostic& d = r.diagnostics.items().front();
    EXPECT_EQ(d.where.block, "N0003");
    EXPECT_EQ(d.where.line, 3);
    double v = 0;
    MachineDataProvider& md = mill.interpreter->machineData();
    ASSERT_EQ(md.read({30, 0, 0, 10}, v), MachineDataStatus::Ok);
    EXPECT_EQ(v, 55.6);
    EXPECT_EQ(mill.interpreter->state().variables.values[1], 0.1);
    ASSERT_EQ(md.read({30, 0, 0, 1}, v), MachineDataStatus::Ok);
    EXPECT_EQ(v, 0);
}

TEST(MachineDataInterp, OutOfRangeAndWrongTypeStopTheBlockAndKeepTheValue) {
    Station lathe(demoCell(), 1);
    RunResult r = lathe.run("N1 MTD(180,,,1)=2\nN2 MTD(180,,,1)=3\nN3 M30\n");
    ASSERT_EQ(errorCodes(r.diagnostics), std::vector<std::string>{"MTD_OUT_OF_RANGE"});
    EXPECT_EQ(r.diagnostics.items().front().where.block, "N0002");
    double v = 0;
    ASSERT_EQ(lathe.interpreter->machineData().read({180, 1, 0, 1}, v), MachineDataStatus::Ok);
    EXPECT_EQ(v, 2);
    Station other(demoCell(), 1);
    r = other.run("N1 MTD(30,,,4)=150.5\nN2 M30\n");
    ASSERT_EQ(errorCodes(r.diagnostics), std::vector<std::string>{"MTD_WRONG_TYPE"});
    EXPECT_EQ(r.diagnostics.items().front().where.line, 1);
}

}  // namespace
