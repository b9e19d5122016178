// One rule for M groups and the page 61 buffer (seed 000, 3.1, 4.2, 5.4;
// restart.md R-025): spindle-index forms Mjnn go into the group of their
// spindle, the interpreter and the restart's buffer collector agree.
#include <gtest/gtest.h>

#include "RestartTestSupport.h"
#include "cnc_core/interp/AuxFunctionGroups.h"

namespace {

using namespace mtc::core;
using namespace mtc::test;

TEST(AuxFunctionGroups, SpindleOneFormsJoinTheGroupsOfTheirPlainForms) {
    const AuxFunctionGroups mill(*demoCell().process(0));
    EXPECT_EQ(mill.groupOf(3), 2);
    EXPECT_EQ(mill.groupOf(103), 2) << "M103 = M3 of spindle 1";
    EXPECT_EQ(mill.groupOf(104), 2);
    EXPECT_EQ(mill.groupOf(105), 2);
    EXPECT_EQ(mill.groupOf(119), 2) << "M119 = M19 of spindle 1";
    for (int m = 140; m <= 144; ++m)
        EXPECT_EQ(mill.groupOf(m), 3) << "gear S1: M" << m;
    EXPECT_EQ(mill.groupOf(108), 5) << "a configured M1xx keeps its own group (coolant)";
    EXPECT_EQ(mill.groupOf(203), 16) << "the mill has no spindle 2";
    EXPECT_EQ(mill.groupOf(62), 16);
    EXPECT_EQ(mill.groupOf(1234), 16);
}

TEST(AuxFunctionGroups, OtherSpindlesUseTheirConfiguredNumbers) {
    const AuxFunctionGroups lathe(*demoCell().process(1));
    EXPECT_EQ(lathe.groupOf(103), 2);
    EXPECT_EQ(lathe.groupOf(141), 6) << "gear S1 is group 6 on the lathe";
    EXPECT_EQ(lathe.groupOf(203), 3);
    EXPECT_EQ(lathe.groupOf(219), 3);
    EXPECT_EQ(lathe.groupOf(305), 4);
    EXPECT_EQ(lathe.groupOf(241), 16) << "S2 has no gear group";
}

TEST(AuxFunctionGroups, BufferKeepsGroup16WithoutM19FormsAndProgramControl) {
    const AuxFunctionGroups mill(*demoCell().process(0));
    EXPECT_TRUE(mill.storedInBuffer(62));
    EXPECT_TRUE(mill.storedInBuffer(241)) << "group 16 on the mill";
    for (int m : {19, 119, 219, 319})
        EXPECT_FALSE(mill.storedInBuffer(m)) << "M" << m << " (seed 000, 4.2)";
    for (int m : {0, 1, 2, 30, 103, 141, 108})
        EXPECT_FALSE(mill.storedInBuffer(m)) << "M" << m;
}

TEST(AuxFunctionGroups, InterpreterKeepsSpindleFormsInTheirGroups) {
    Station mill(demoCell(), 0);
    mill.add("N0001 S100 M103 M141\nN0002 M62\nN0003 M30\n", 1);
    ASSERT_TRUE(mill.interpreter->select(1));
    ASSERT_EQ(mill.interpreter->step().status, RunStatus::Running);
    ASSERT_EQ(mill.interpreter->step().status, RunStatus::Running);
    const InterpreterState& s = mill.interpreter->state();
    EXPECT_EQ(s.mGroups[2], 103);
    EXPECT_EQ(s.mGroups[3], 141);
    EXPECT_EQ(s.mGroups[16], 62);
}

TEST(AuxFunctionGroups, TwoFormsOfOneGroupInABlockConflict) {
    Station mill(demoCell(), 0);
    const RunResult r = mill.run("N0001 M3 M104\nN0002 M30\n");
    EXPECT_EQ(r.status, RunStatus::Error);
    EXPECT_EQ(errorCodes(r.diagnostics), std::vector<std::string>{"M_GROUP_CONFLICT"});
}

TEST(AuxFunctionGroups, ComputingProcessBuffersOnlyGroup16) {
    RestartCell mill(0);
    mill.add("N0001 S500 M103 M141 M62\nN0002 M105 M63\nN0003 M119\nN0004 @1=1\nN0005 M30\n", 1);
    ComputingProcess c(mill.config, mill.store, mill.sps, mill.services());
    DiagnosticList d;
    ASSERT_TRUE(c.begin(mill.selection(1, 1, 4), mill.live.state(), {}, 1000, d));
    ASSERT_EQ(c.runToEnd().status, ComputingStatus::TargetReached)
        << diagnosticsText(c.diagnostics());
    EXPECT_EQ(c.state().mGroups[2], 119);
    EXPECT_EQ(c.state().mGroups[3], 141);
    ASSERT_EQ(c.collector().m16().size(), 2);
    EXPECT_EQ(mill.page(61, 1, 1), 62);
    EXPECT_EQ(mill.page(61, 1, 2), 63);
    EXPECT_EQ(mill.page(61, 1, 3), 0);
}

}  // namespace
