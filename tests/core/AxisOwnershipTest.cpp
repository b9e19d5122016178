// Axis ownership of normal program runs (docs/decisions/restart.md R-022):
// GAX requests an axis and waits until its holder frees it with FAX, a move
// needs the axes it moves, Control reset withdraws the request; a restart
// computing process takes part in the same handshake.
#include <gtest/gtest.h>

#include "InterpTestSupport.h"
#include "RestartStation.h"
#include "cnc_core/machine/AxisTransfer.h"

namespace {

using namespace mtc::test;
using mtc::core::AxisTransfer;
using mtc::core::AxisTransferKind;
using mtc::core::ComputingStatus;
using mtc::core::Interpreter;
using mtc::core::InterpreterServices;
using mtc::core::RunStatus;

/// One process of the demo cell in a normal run on the cell's ownership table.
struct OwnerStation {
    OwnerStation(AxisTransfer& transfer, int process)
        : config(*demoCell().process(process)), sink(std::vector<std::string>{}) {
        InterpreterServices services;
        services.axisTransfer = &transfer;
        interpreter = std::make_unique<Interpreter>(config, store, sink, services);
        std::vector<std::string> names;
        for (int a = 0; a < interpreter->axes().count(); ++a)
            names.push_back(interpreter->axisName(a));
        sink.setNames(names);
    }
    void select(const std::string& source) {
        store.put(config.index, 1, parse(source, 1));
        ASSERT_TRUE(interpreter->select(1));
    }
    /// One block; returns its status (Stopped without a block while waiting).
    RunStatus step() {
        last = interpreter->step();
        return last.status;
    }
    double x() const { return interpreter->state().modal.machine[0]; }

    const mtc::core::ProcessConfig& config;
    mtc::core::ProgramStore store;
    TranscriptSink sink;
    std::unique_ptr<Interpreter> interpreter;
    mtc::core::RunResult last;
};

TEST(AxisOwnership, TableGrantsReleasesAndQueues) {
    AxisTransfer cell;
    EXPECT_EQ(cell.holder("X"), AxisTransfer::kAtHome);
    EXPECT_EQ(cell.request(0, "X"), 0u) << "never transferred: granted at once";
    EXPECT_EQ(cell.holder("X"), 0);
    const auto wait = cell.request(1, "X");
    EXPECT_FALSE(cell.done(wait)) << "process 0 holds X";
    EXPECT_FALSE(cell.release(1, "X")) << "process 1 does not hold X";
    const auto before = cell.revision();
    EXPECT_TRUE(cell.release(0, "X"));
    EXPECT_TRUE(cell.done(wait)) << "the FAX hands X to the waiting GAX";
    EXPECT_EQ(cell.holder("X"), 1);
    EXPECT_GT(cell.revision(), before);
    EXPECT_TRUE(cell.open().empty());

    EXPECT_TRUE(cell.release(1, "X"));
    EXPECT_EQ(cell.holder("X"), AxisTransfer::kNobody);
    EXPECT_TRUE(cell.release(1, "X")) << "a repeated FAX of the releaser";
    cell.cancel(1);
    ASSERT_EQ(cell.open().size(), 1u) << "Control reset keeps a released axis released";
    EXPECT_EQ(cell.request(1, "X"), 0u) << "taken back: nobody else took it";
    EXPECT_EQ(cell.holder("X"), 1);
    EXPECT_TRUE(cell.open().empty());
}

TEST(AxisOwnership, TwoNormalRunsHandAnAxisBackAndForth) {
    AxisTransfer transfer;
    OwnerStation mill(transfer, 0);
    OwnerStation lathe(transfer, 1);
    mill.select(
        "N0001 GAX(X)\nN0002 G0 X10\nN0003 FAX(X)\nN0004 GAX(X)\nN0005 G0 X20\nN0006 M30\n");
    lathe.select("N0001 GAX(X)\nN0002 G0 X30\nN0003 FAX(X)\nN0004 M30\n");
    EXPECT_EQ(mill.step(), RunStatus::Running);  // GAX: X was at home
    EXPECT_EQ(mill.step(), RunStatus::Running);
    EXPECT_EQ(mill.x(), 10.0);
    EXPECT_EQ(mill.step(), RunStatus::Running);  // FAX
    EXPECT_EQ(transfer.holder("X"), AxisTransfer::kNobody);

    EXPECT_EQ(lathe.step(), RunStatus::Running) << "the lathe's GAX takes the free axis";
    EXPECT_EQ(transfer.holder("X"), 1);
    EXPECT_EQ(mill.step(), RunStatus::Stopped) << "the mill's GAX waits for the lathe's FAX";
    EXPECT_EQ(mill.interpreter->waitingForAxis(), "X");
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(mill.step(), RunStatus::Stopped);
        EXPECT_EQ(mill.last.blocksInterpreted, 0u) << "waiting executes no block";
    }
    EXPECT_EQ(lathe.step(), RunStatus::Running);  // G0 X30
    EXPECT_EQ(lathe.step(), RunStatus::Running);  // FAX: the mill's GAX is met
    EXPECT_EQ(transfer.holder("X"), 0);
    EXPECT_EQ(mill.interpreter->waitingForAxis(), "");
    EXPECT_EQ(mill.step(), RunStatus::Running);
    EXPECT_EQ(mill.x(), 20.0);
    EXPECT_EQ(mill.step(), RunStatus::Ended);
    EXPECT_EQ(lathe.step(), RunStatus::Ended);
    EXPECT_TRUE(transfer.open().empty());
    EXPECT_NE(mill.sink.text.find("command P1 N0004 L4 GAX"), std::string::npos)
        << mill.sink.text << "GAX still reaches the machine as a command";
}

TEST(AxisOwnership, MotionWithoutTheAxisIsARuntimeErrorOfTheBlock) {
    AxisTransfer transfer;
    OwnerStation mill(transfer, 0);
    OwnerStation lathe(transfer, 1);
    mill.select("N0001 GAX(X)\nN0002 M30\n");
    EXPECT_EQ(mill.step(), RunStatus::Running);
    lathe.select("N0010 G0 Z5\n\nN0020 G0 X5 Z6\nN0030 M30\n");
    EXPECT_EQ(lathe.step(), RunStatus::Running) << "Z is the lathe's own";
    EXPECT_EQ(lathe.step(), RunStatus::Error);
    ASSERT_EQ(errorCodes(lathe.last.diagnostics), std::vector<std::string>{"AXIS_NOT_HELD"});
    const auto& error = lathe.last.diagnostics.items()[0];
    EXPECT_EQ(error.where.block, "N0020");
    EXPECT_EQ(error.where.line, 3);
    EXPECT_NE(error.message.find("process 0 holds it"), std::string::npos) << error.message;
    EXPECT_EQ(lathe.x(), 0.0) << "the rejected block changed nothing";

    // The mill itself after FAX: released, nobody took it.
    OwnerStation alone(transfer, 0);
    alone.select("N0001 FAX(Y)\nN0002 G1 Y5 F100\nN0003 M30\n");
    EXPECT_EQ(alone.step(), RunStatus::Running);
    EXPECT_EQ(alone.step(), RunStatus::Error);
    ASSERT_FALSE(alone.last.diagnostics.items().empty());
    EXPECT_NE(alone.last.diagnostics.items()[0].message.find("released with FAX"),
              std::string::npos);
}

TEST(AxisOwnership, TransferOfAnUnknownOrForeignAxisIsRefused) {
    AxisTransfer transfer;
    OwnerStation mill(transfer, 0);
    mill.select("N0001 GAX(Z2)\nN0002 M30\n");
    EXPECT_EQ(mill.step(), RunStatus::Error);
    EXPECT_EQ(errorCodes(mill.last.diagnostics), std::vector<std::string>{"AXIS_TRANSFER"});
    EXPECT_EQ(transfer.holder("Z2"), AxisTransfer::kAtHome) << "nothing changed";

    OwnerStation lathe(transfer, 1);
    lathe.select("N0001 GAX(x1)\nN0002 M30\n");
    EXPECT_EQ(lathe.step(), RunStatus::Running) << "designation 2 names the same axis";
    EXPECT_EQ(transfer.holder("X"), 1);
    mill.select("N0001 FAX(X)\nN0002 M30\n");
    EXPECT_EQ(mill.step(), RunStatus::Error);
    EXPECT_EQ(errorCodes(mill.last.diagnostics), std::vector<std::string>{"AXIS_NOT_HELD"});
    EXPECT_EQ(transfer.holder("X"), 1);
}

TEST(AxisOwnership, ControlResetWithdrawsTheRequest) {
    AxisTransfer transfer;
    OwnerStation mill(transfer, 0);
    OwnerStation lathe(transfer, 1);
    lathe.select("N0001 GAX(X)\nN0002 FAX(X)\nN0003 M30\n");
    EXPECT_EQ(lathe.step(), RunStatus::Running);
    mill.select("N0001 GAX(X)\nN0002 G0 X1\nN0003 M30\n");
    EXPECT_EQ(mill.step(), RunStatus::Stopped);
    ASSERT_EQ(mill.interpreter->waitingForAxis(), "X");
    mill.interpreter->controlReset();
    EXPECT_EQ(mill.interpreter->waitingForAxis(), "");
    EXPECT_TRUE(transfer.open().empty()) << "the GAX is withdrawn";
    EXPECT_EQ(lathe.step(), RunStatus::Running);  // FAX: nobody waits any more
    EXPECT_EQ(transfer.holder("X"), AxisTransfer::kNobody);
    // After the reset the mill starts again and takes the released axis.
    EXPECT_EQ(mill.step(), RunStatus::Running);
    EXPECT_EQ(transfer.holder("X"), 0);
    EXPECT_EQ(mill.step(), RunStatus::Running);
    EXPECT_EQ(mill.x(), 1.0);
}

TEST(AxisOwnership, SingleProcessGaxIsGrantedAtOnce) {
    AxisTransfer alone;  // the CLI's run: no other process in the cell
    OwnerStation mill(alone, 0);
    mill.select("N0001 FAX(X)\nN0002 GAX(X)\nN0003 G0 X7\nN0004 GAX(Y)\nN0005 G0 Y3\nN0006 M30\n");
    const auto result = mill.interpreter->run();
    EXPECT_EQ(result.status, RunStatus::Ended) << diagnosticsText(result.diagnostics);
    EXPECT_EQ(mill.x(), 7.0) << "the moves after the GAX ran";
    EXPECT_EQ(alone.holder("X"), 0);
    EXPECT_EQ(alone.holder("Y"), 0);
}

/// The lathe in NC program restart and the mill in a normal run.
struct RestartAndRun {
    RestartAndRun() : lathe(1), mill(transfer, 0) {
        lathe.sequence.setAxisTransfer(&transfer);
        lathe.cell.add(kLibrary, 99);
    }
    AxisTransfer transfer;
    RestartStation lathe;
    OwnerStation mill;
};

TEST(AxisOwnership, NormalRunGaxMeetsTheFaxOfARestartComputingProcess) {
    RestartAndRun cell;
    cell.lathe.cell.add("N0001 @1=1\nN0002 FAX(X)\nN0003 @1=3\nN0004 @2=1\nN0005 M30\n", 2);
    ASSERT_TRUE(cell.lathe.accept(cell.lathe.cell.selection(2, 2, 4)));
    cell.lathe.sequence.advance(100'000);
    ASSERT_EQ(cell.lathe.sequence.computing().progress().status, ComputingStatus::Waiting);
    cell.mill.select("N0001 GAX(X)\nN0002 G0 X4\nN0003 M30\n");
    EXPECT_EQ(cell.mill.step(), RunStatus::Running) << "the restart's FAX hands X over";
    EXPECT_EQ(cell.transfer.holder("X"), 0);
    EXPECT_EQ(cell.lathe.runUntilWaiting(), RestartPhase::TargetReached);
    EXPECT_EQ(cell.mill.step(), RunStatus::Running);
    EXPECT_EQ(cell.mill.x(), 4.0);
}

TEST(AxisOwnership, RestartGaxWaitsForTheFaxOfANormalRun) {
    RestartAndRun cell;
    cell.mill.select("N0001 GAX(X)\nN0002 G0 X2\nN0003 FAX(X)\nN0004 M30\n");
    EXPECT_EQ(cell.mill.step(), RunStatus::Running);
    cell.lathe.cell.add("N0001 GAX(X)\nN0002 @1=1\nN0003 @2=1\nN0004 M30\n", 2);
    ASSERT_TRUE(cell.lathe.accept(cell.lathe.cell.selection(2, 2, 3)));
    cell.lathe.sequence.advance(100'000);
    EXPECT_EQ(cell.lathe.sequence.computing().progress().status, ComputingStatus::Waiting);
    EXPECT_EQ(cell.lathe.sequence.waitingFor(), "GAX X");
    EXPECT_EQ(cell.mill.step(), RunStatus::Running);
    EXPECT_EQ(cell.mill.step(), RunStatus::Running);  // FAX meets the restart's GAX
    EXPECT_EQ(cell.transfer.holder("X"), 1);
    EXPECT_EQ(cell.lathe.runUntilWaiting(), RestartPhase::TargetReached);
    EXPECT_TRUE(cell.transfer.open().empty());
}

}  // namespace
