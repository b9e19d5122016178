// One writer at a time (issue 22 §4, docs/decisions/config-files.md CF-020,
// CF-021): two processes changing one machine data file in a loop lose
// nothing, whether each change is a locked read-modify-write (`md set`) or
// a long-lived copy saved again and again (the panel, `run --data`).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <iostream>

#include "InterpTestSupport.h"
#include "cnc_core/machine_data/SharedMachineDataFile.h"
#include "cnc_core/program/FileLock.h"
#include "tests/support/TempDir.h"

namespace {

using namespace mtc::core;
namespace fs = std::filesystem;

constexpr int kRounds = 100;

/// Page 60 element `element` (T number of a tool spindle: INT 0..9999999).
MachineDataAddress tSpindle(int element) {
    return {60, 0, 0, element};
}

double valueIn(const std::string& path, const MachineDataAddress& address) {
    MachineDataStore store(mtc::test::demoCell());
    SharedMachineDataFile file(path);
    EXPECT_TRUE(file.open(store).diagnostics.empty());
    double value = -1;
    store.read(address, value);
    return value;
}

/// `md set`-like: open locked, read the element, add one, save; kRounds times.
[[noreturn]] void incrementInRounds(const std::string& path, int element) {
    for (int round = 0; round < kRounds; ++round) {
        MachineDataStore store(mtc::test::demoCell());
        SharedMachineDataFile file(path);
        if (!file.open(store, true).diagnostics.items().empty()) ::_exit(2);
        double value = 0;
        store.read(tSpindle(element), value);
        store.update(tSpindle(element), value + 1);
        if (!file.save(store).ok) ::_exit(3);
    }
    ::_exit(0);
}

/// Panel-like: one copy opened once, one value changed and saved each round.
[[noreturn]] void setInRounds(const std::string& path, int element) {
    MachineDataStore store(mtc::test::demoCell());
    SharedMachineDataFile file(path);
    file.open(store);
    for (int round = 1; round <= kRounds; ++round) {
        store.update(tSpindle(element), round);
        if (!file.save(store).ok) ::_exit(3);
    }
    ::_exit(0);
}

void runTwo(void (*writer)(const std::string&, int), const std::string& path) {
    pid_t children[2];
    for (int k = 0; k < 2; ++k) {
        children[k] = ::fork();
        ASSERT_GE(children[k], 0);
        if (children[k] == 0) writer(path, 5 + k);
    }
    for (pid_t child : children) {
        int status = 0;
        ASSERT_EQ(::waitpid(child, &status, 0), child);
        ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
            << "a writer failed (exit " << WEXITSTATUS(status) << ")";
    }
}

TEST(MachineDataConcurrency, TwoLockedReadModifyWritersLoseNothing) {
    const mtc::test::TempDir dir(
        "mtc-mdlock");  // children leave by _exit: only the test removes it
    const std::string path = dir.file("cell.mdt");
    runTwo(incrementInRounds, path);
    EXPECT_EQ(valueIn(path, tSpindle(5)), kRounds);
    EXPECT_EQ(valueIn(path, tSpindle(6)), kRounds);
    std::cout << "[ measured ] 2 writers x " << kRounds
              << " locked increments: " << valueIn(path, tSpindle(5)) + valueIn(path, tSpindle(6))
              << " of " << 2 * kRounds << " kept\n";
}

TEST(MachineDataConcurrency, TwoLongLivedCopiesNeverWriteBackOldValues) {
    const mtc::test::TempDir dir(
        "mtc-mdlock");  // children leave by _exit: only the test removes it
    const std::string path = dir.file("cell.mdt");
    runTwo(setInRounds, path);
    EXPECT_EQ(valueIn(path, tSpindle(5)), kRounds) << "writer A's last value";
    EXPECT_EQ(valueIn(path, tSpindle(6)), kRounds) << "writer B's last value";
}

TEST(MachineDataConcurrency, RefreshTakesOverAnotherProgramsChange) {
    const mtc::test::TempDir dir(
        "mtc-mdlock");  // children leave by _exit: only the test removes it
    const std::string path = dir.file("cell.mdt");
    MachineDataStore panel(mtc::test::demoCell());
    SharedMachineDataFile panelFile(path);
    panelFile.open(panel);
    EXPECT_EQ(panelFile.refresh(panel).takenOver, 0u) << "nothing changed";
    {  // another program sets element 7
        MachineDataStore other(mtc::test::demoCell());
        SharedMachineDataFile otherFile(path);
        otherFile.open(other, true);
        other.update(tSpindle(7), 42);
        ASSERT_TRUE(otherFile.save(other).ok);
    }
    panel.update(tSpindle(8), 9);  // the panel's own change, not saved yet
    const MachineDataSync sync = panelFile.refresh(panel);
    EXPECT_EQ(sync.takenOver, 1u);
    double value = 0;
    panel.read(tSpindle(7), value);
    EXPECT_EQ(value, 42);
    panel.read(tSpindle(8), value);
    EXPECT_EQ(value, 9) << "the panel's own change stays";
    ASSERT_TRUE(panelFile.save(panel).ok);
    EXPECT_EQ(valueIn(path, tSpindle(7)), 42);
    EXPECT_EQ(valueIn(path, tSpindle(8)), 9);
}

TEST(MachineDataConcurrency, AHeldLockMakesTheOtherWriterWaitThenGiveUpWithAReason) {
    const mtc::test::TempDir dir(
        "mtc-mdlock");  // children leave by _exit: only the test removes it
    const std::string path = dir.file("cell.mdt");
    FileLock first(path);
    ASSERT_TRUE(first.locked()) << first.error();
    FileLock second(path, 0.05);
    EXPECT_FALSE(second.locked());
    EXPECT_NE(second.error().find("another program"), std::string::npos) << second.error();
    MachineDataStore store(mtc::test::demoCell());
    SharedMachineDataFile file(path, 0.05);
    const MachineDataLoadResult opened = file.open(store, true);
    ASSERT_FALSE(opened.diagnostics.items().empty());
    EXPECT_EQ(opened.diagnostics.items().front().code, "MD_FILE_LOCKED");
    EXPECT_FALSE(file.save(store).ok) << "nothing is saved without the lock";
}

}  // namespace
