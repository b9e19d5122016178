// Loading the machine data file removes the temporary files of saves that
// were killed before their rename (older than a minute), and says so; young
// ones (a save running elsewhere) and unrelated files stay.
#include <gtest/gtest.h>
#include <utime.h>

#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>

#include "InterpTestSupport.h"
#include "cnc_core/machine_data/MachineDataFile.h"
#include "cnc_core/machine_data/MachineDataStore.h"

namespace {

using namespace mtc::core;
namespace fs = std::filesystem;

void touch(const fs::path& path, std::time_t modified) {
    std::ofstream(path) << "MTC200-MACHINE-DATA 1\ncell half";
    utimbuf times{modified, modified};
    ASSERT_EQ(::utime(path.c_str(), &times), 0);
}

TEST(MachineDataFile, StaleTemporariesOfKilledSavesAreRemovedOnLoad) {
    const fs::path dir =
        fs::temp_directory_path() /
        ("mtc-stale-" + std::to_string(::getpid()) + "-" +
         std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()));
    fs::create_directories(dir);
    const std::string path = (dir / "cell.mdt").string();
    const std::time_t now = std::time(nullptr);
    touch(dir / "cell.mdt.tmpAb12Cd", now - 3600);   // killed an hour ago
    touch(dir / "cell.mdt.tmpYoung1", now);          // a save running right now
    touch(dir / "cell.mdt.tmpfoo", now - 3600);      // not a temporary of ours
    touch(dir / "other.mdt.tmpAb12Cd", now - 3600);  // another cell's file
    MachineDataStore store(mtc::test::demoCell());
    const MachineDataLoadResult result = MachineDataFile(path).load(store);
    ASSERT_EQ(result.diagnostics.items().size(), 1u);
    EXPECT_EQ(result.diagnostics.items()[0].code, "MD_STALE_TEMPORARY");
    EXPECT_NE(result.diagnostics.items()[0].message.find("cell.mdt.tmpAb12Cd"), std::string::npos);
    EXPECT_FALSE(fs::exists(dir / "cell.mdt.tmpAb12Cd"));
    EXPECT_TRUE(fs::exists(dir / "cell.mdt.tmpYoung1"));
    EXPECT_TRUE(fs::exists(dir / "cell.mdt.tmpfoo"));
    EXPECT_TRUE(fs::exists(dir / "other.mdt.tmpAb12Cd"));
    EXPECT_FALSE(result.fileFound);  // the data file itself was never there
    fs::remove_all(dir);
}

}  // namespace
