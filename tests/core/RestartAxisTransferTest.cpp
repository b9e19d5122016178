// GAX / FAX during the computing process (seed 000, 5.4 "Axis transfer"): a
// FAX waits until another process requests the axis with GAX, a GAX waits
// until another process relinquishes it with FAX; the other process may be
// in NC program restart too. docs/decisions/restart.md R-021.
#include <gtest/gtest.h>

#include "RestartStation.h"
#include "cnc_core/machine/AxisTransfer.h"

namespace {

using namespace mtc::test;
using mtc::core::AxisTransfer;
using mtc::core::AxisTransferKind;
using mtc::core::ComputingStatus;

TEST(AxisTransfer, GetAndFreeOfTwoProcessesMeet) {
    AxisTransfer cell;
    const auto get = cell.post(0, AxisTransferKind::Get, "X1");
    EXPECT_FALSE(cell.done(get));
    const auto own = cell.post(0, AxisTransferKind::Free, "X1");
    EXPECT_FALSE(cell.done(own)) << "a process does not hand an axis to itself";
    const auto other = cell.post(1, AxisTransferKind::Free, "Z2");
    EXPECT_FALSE(cell.done(other)) << "another axis";
    const auto free = cell.post(1, AxisTransferKind::Free, "X1");
    EXPECT_TRUE(cell.done(free));
    EXPECT_TRUE(cell.done(get));
    EXPECT_FALSE(cell.done(own));
    ASSERT_EQ(cell.open().size(), 2u);
    cell.cancel(0);
    EXPECT_TRUE(cell.done(own)) << "withdrawn";
    ASSERT_EQ(cell.open().size(), 1u);
    EXPECT_EQ(cell.open()[0].axis, "Z2");
}

TEST(AxisTransfer, ArgumentsNameTheAxes) {
    AxisTransferKind kind{};
    std::vector<std::string> axes;
    ASSERT_TRUE(mtc::core::parseAxisTransfer("FAX", "(x1, Z2 )", kind, axes));
    EXPECT_EQ(kind, AxisTransferKind::Free);
    EXPECT_EQ(axes, (std::vector<std::string>{"X1", "Z2"}));
    ASSERT_TRUE(mtc::core::parseAxisTransfer("GAX", "X1 AXD (X:S-0-0104)=7000", kind, axes));
    EXPECT_EQ(kind, AxisTransferKind::Get);
    EXPECT_EQ(axes, (std::vector<std::string>{"X1"}));
    ASSERT_TRUE(mtc::core::parseAxisTransfer("GAX", " (Z2) FAX(X1)", kind, axes));
    EXPECT_EQ(axes, (std::vector<std::string>{"Z2"})) << "the rest of the block is not an axis";
    EXPECT_FALSE(mtc::core::parseAxisTransfer("GAX", "()", kind, axes)) << "no axis";
    EXPECT_FALSE(mtc::core::parseAxisTransfer("AXD", "(X1)", kind, axes));
}

/// Mill (process 0) and lathe (process 1), both with ADJUST/REPOS, on one
/// axis transfer handshake.
struct TwoStations {
    TwoStations() : mill(0), lathe(1) {
        mill.sequence.setAxisTransfer(&transfer);
        lathe.sequence.setAxisTransfer(&transfer);
        mill.cell.add(kLibrary, 99);
        lathe.cell.add(kLibrary, 99);
    }
    static ComputingStatus status(const RestartStation& s) {
        return s.sequence.computing().progress().status;
    }
    static double variable(const RestartStation& s, int index) {
        return s.sequence.computing().state().variables.values[static_cast<std::size_t>(index)];
    }
    AxisTransfer transfer;
    RestartStation mill;
    RestartStation lathe;
};

TEST(RestartAxisTransfer, FaxWaitsUntilAnotherRestartRequestsTheAxis) {
    TwoStations cell;
    cell.mill.cell.add("N0001 @1=1\nN0002 @1=2 FAX(X1)\nN0003 @1=3\nN0004 @2=1\nN0005 M30\n", 2);
    cell.lathe.cell.add("N0001 @1=5\nN0002 GAX(X1)\nN0003 @1=6\nN0004 @2=1\nN0005 M30\n", 2);
    ASSERT_TRUE(cell.mill.accept(cell.mill.cell.selection(2, 2, 4)));
    for (int i = 0; i < 3; ++i)
        EXPECT_EQ(cell.mill.sequence.advance(100'000), RestartPhase::Computing);
    EXPECT_EQ(TwoStations::status(cell.mill), ComputingStatus::Waiting);
    EXPECT_EQ(cell.mill.sequence.waitingFor(), "FAX X1");
    EXPECT_EQ(TwoStations::variable(cell.mill, 1), 2.0) << "the FAX block itself is done";
    EXPECT_EQ(cell.mill.sequence.computing().progress().blocksInterpreted, 2u);
    EXPECT_FALSE(cell.mill.sequence.held()) << "waiting is not a hold";
    EXPECT_EQ(cell.mill.signal("SACTIV"), 1);

    ASSERT_TRUE(cell.lathe.accept(cell.lathe.cell.selection(2, 2, 4)));
    EXPECT_EQ(cell.lathe.runUntilWaiting(), RestartPhase::TargetReached)
        << "the GAX met the waiting FAX at once";
    EXPECT_EQ(TwoStations::variable(cell.lathe, 1), 6.0);
    EXPECT_EQ(cell.mill.runUntilWaiting(), RestartPhase::TargetReached);
    EXPECT_EQ(TwoStations::variable(cell.mill, 1), 3.0);
    EXPECT_EQ(cell.mill.sequence.waitingFor(), "");
    EXPECT_TRUE(cell.transfer.open().empty());
}

TEST(RestartAxisTransfer, GaxWaitsUntilAnotherProcessRelinquishesTheAxis) {
    TwoStations cell;
    cell.mill.cell.add("N0001 GAX(Z2)\nN0002 @1=1\nN0003 @2=1\nN0004 M30\n", 2);
    cell.lathe.cell.add("N0001 @1=1\nN0002 FAX(Z2)\nN0003 @2=1\nN0004 M30\n", 2);
    ASSERT_TRUE(cell.mill.accept(cell.mill.cell.selection(2, 2, 3)));
    cell.mill.sequence.advance(100'000);
    EXPECT_EQ(TwoStations::status(cell.mill), ComputingStatus::Waiting);
    EXPECT_EQ(cell.mill.sequence.waitingFor(), "GAX Z2");
    ASSERT_TRUE(cell.lathe.accept(cell.lathe.cell.selection(2, 2, 3)));
    EXPECT_EQ(cell.lathe.runUntilWaiting(), RestartPhase::TargetReached);
    EXPECT_EQ(cell.mill.runUntilWaiting(), RestartPhase::TargetReached);
}

TEST(RestartAxisTransfer, StopHoldsAndControlResetWithdrawsTheRequest) {
    TwoStations cell;
    cell.mill.cell.add("N0001 GAX(X1)\nN0002 @1=1\nN0003 @2=1\nN0004 M30\n", 2);
    cell.lathe.cell.add("N0001 GAX(X1)\nN0002 @2=1\nN0003 M30\n", 2);
    ASSERT_TRUE(cell.mill.accept(cell.mill.cell.selection(2, 2, 3)));
    cell.mill.sequence.advance(100'000);
    ASSERT_EQ(TwoStations::status(cell.mill), ComputingStatus::Waiting);
    cell.mill.control.press(ControlKey::Stop);
    EXPECT_TRUE(cell.mill.sequence.held());
    cell.mill.control.press(ControlKey::Start);
    cell.mill.sequence.advance(100'000);
    EXPECT_EQ(TwoStations::status(cell.mill), ComputingStatus::Waiting) << "still no partner";
    ASSERT_TRUE(cell.lathe.accept(cell.lathe.cell.selection(2, 2, 2)));
    cell.lathe.sequence.advance(100'000);
    EXPECT_EQ(TwoStations::status(cell.lathe), ComputingStatus::Waiting) << "two GAX never meet";
    cell.mill.control.press(ControlKey::ControlReset);
    cell.mill.expectAllRestartSignalsOff();
    ASSERT_EQ(cell.transfer.open().size(), 1u) << "only the lathe's GAX is left";
    EXPECT_EQ(cell.transfer.open()[0].process, 1);
    cell.lathe.control.press(ControlKey::ControlReset);
    EXPECT_TRUE(cell.transfer.open().empty());
}

TEST(RestartAxisTransfer, AbortFromAnotherThreadEndsTheWait) {
    TwoStations cell;
    cell.mill.cell.add("N0001 FAX(X1)\nN0002 @2=1\nN0003 M30\n", 2);
    ASSERT_TRUE(cell.mill.accept(cell.mill.cell.selection(2, 2, 2)));
    cell.mill.sequence.advance(100'000);
    ASSERT_EQ(TwoStations::status(cell.mill), ComputingStatus::Waiting);
    cell.mill.sequence.requestAbort();
    EXPECT_EQ(cell.mill.sequence.advance(100'000), RestartPhase::Aborted);
    cell.mill.expectAllRestartSignalsOff();
    EXPECT_TRUE(cell.transfer.open().empty());
}

}  // namespace
