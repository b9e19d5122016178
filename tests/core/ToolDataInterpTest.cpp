// The interpreter reads the shared tool list and zero offsets (issue 16 §4,
// docs/decisions/tool-data.md TOOL-005): T is checked against the tool list,
// G54..G59 come from the table, and a change is seen by the next block.
#include <gtest/gtest.h>

#include "InterpTestSupport.h"
#include "cnc_core/tooldata/SetupData.h"

namespace {

using namespace mtc::core;
using namespace mtc::test;

struct SharedData {
    SharedData() : data(SetupData::fromConfig(demoCell(), diagnostics)) {
        InterpreterServices services;
        services.tools = data.tools(0);
        services.zeroOffsets = data.offsets(0);
        interpreter = std::make_unique<Interpreter>(*demoCell().process(0), store, sink, services);
    }
    DiagnosticList diagnostics;
    SetupData data;
    ProgramStore store;
    RecordingSink sink;
    std::unique_ptr<Interpreter> interpreter;
};

TEST(ToolDataInterp, AChangedOffsetIsSeenByTheNextBlock) {
    SharedData s;
    s.store.put(0, 1, parse("N0001 G54 G0 X10 Y0 Z0\nN0002 G0 X20\nN0003 M30\n", 1));
    ASSERT_TRUE(s.interpreter->select(1));
    ASSERT_EQ(s.interpreter->step().status, RunStatus::Running);
    EXPECT_EQ(s.sink.motions.back().end[0], -140.0);
    s.data.offsets(0)->set(54, AxisDefinition::X, 100.0);  // the operator changes G54
    ASSERT_EQ(s.interpreter->step().status, RunStatus::Running);
    EXPECT_EQ(s.sink.motions.back().end[0], 120.0);
    EXPECT_EQ(s.interpreter->zeroOffsets().value(54, AxisDefinition::X), 100.0);
}

TEST(ToolDataInterp, TIsCheckedAgainstTheSharedToolList) {
    SharedData s;
    ToolEdge edge;
    edge.radius = 4.0;
    s.data.tools(0)->setEdge(77, edge, "extra");
    s.data.tools(0)->removeTool(3);
    s.store.put(0, 1, parse("N0001 T77\nN0002 T3\nN0003 M30\n", 1));
    ASSERT_TRUE(s.interpreter->select(1));
    const RunResult result = s.interpreter->run();
    EXPECT_EQ(errorCodes(result.diagnostics), std::vector<std::string>{"TOOL_UNKNOWN"});
    EXPECT_EQ(result.diagnostics.items().front().where.block, "N0002");
    EXPECT_EQ(s.interpreter->tools().edge(77, 1)->radius, 4.0);
}

}  // namespace
