// The interpreter's own machine data (InMemoryMachineData = MachineDataStore
// without persistence): user pages with ranges and defaults, pages 60 and 61,
// and the pages it does not know.
#include <gtest/gtest.h>

#include "InterpTestSupport.h"
#include "cnc_core/machine/InMemoryMachineData.h"

namespace {

using namespace mtc::core;
using namespace mtc::test;

TEST(InMemoryMachineData, UserPageRangesAndDefaults) {
    InMemoryMachineData data(demoCell());
    double v = -1;
    ASSERT_EQ(data.read({180, 1, 0, 1}, v), MachineDataStatus::Ok);
    EXPECT_EQ(v, 0) << "default of the configuration";
    EXPECT_EQ(data.check({180, 1, 0, 1}, 3, MachineDataWriter::Nc), MachineDataStatus::OutOfRange);
    EXPECT_EQ(data.write({180, 1, 0, 1}, 3, MachineDataWriter::Sps), MachineDataStatus::OutOfRange);
    EXPECT_EQ(data.write({180, 1, 0, 2}, 612.25, MachineDataWriter::Gui), MachineDataStatus::Ok);
    ASSERT_EQ(data.read({180, 1, 0, 2}, v), MachineDataStatus::Ok);
    EXPECT_EQ(v, 612.25);
    EXPECT_EQ(data.read({180, 0, 0, 1}, v), MachineDataStatus::UnknownPage)
        << "page 180 is the lathe's";
    EXPECT_EQ(data.read({180, 1, 1, 1}, v), MachineDataStatus::UnknownElement);
    EXPECT_EQ(data.read({180, 5, 0, 1}, v), MachineDataStatus::UnknownProcess);
}

TEST(InMemoryMachineData, Pages60And61) {
    InMemoryMachineData data(demoCell());
    double v = -1;
    ASSERT_EQ(data.read({60, 0, 0, 4}, v), MachineDataStatus::Ok);
    EXPECT_EQ(v, 30) << "transformation selection starts at 30";
    EXPECT_EQ(data.write({60, 0, 0, 4}, 33, MachineDataWriter::Nc), MachineDataStatus::OutOfRange);
    EXPECT_EQ(data.write({60, 0, 0, 1}, 2, MachineDataWriter::Nc), MachineDataStatus::OutOfRange);
    EXPECT_EQ(data.write({60, 0, 0, 5}, 1234567, MachineDataWriter::Nc), MachineDataStatus::Ok);
    EXPECT_EQ(data.read({60, 0, 0, 9}, v), MachineDataStatus::UnknownElement);
    EXPECT_EQ(data.write({61, 1, 2, 40}, 9501, MachineDataWriter::Nc), MachineDataStatus::Ok);
    ASSERT_EQ(data.read({61, 1, 2, 40}, v), MachineDataStatus::Ok);
    EXPECT_EQ(v, 9501);
    EXPECT_EQ(data.read({61, 1, 3, 1}, v), MachineDataStatus::UnknownElement);
    EXPECT_EQ(data.read({61, 1, 1, 41}, v), MachineDataStatus::UnknownElement);
    EXPECT_EQ(data.write({61, 1, 1, 1}, -2, MachineDataWriter::Nc), MachineDataStatus::OutOfRange);
}

TEST(InMemoryMachineData, PagesItDoesNotProvide) {
    InMemoryMachineData data(demoCell());
    double v = -1;
    EXPECT_EQ(data.read({30, 0, 0, 1}, v), MachineDataStatus::Ok) << "page 30 is the store's";
    EXPECT_EQ(v, 0);
    EXPECT_EQ(data.read({99, 0, 0, 1}, v), MachineDataStatus::UnknownPage);
    EXPECT_STREQ(machineDataStatusCode(MachineDataStatus::UnknownPage), "MTD_UNKNOWN_PAGE");
}

}  // namespace
