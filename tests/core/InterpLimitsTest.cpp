// Programmed numbers at their extremes in the interpreter (issue 15 §1):
// a dwell outside its range is refused (I-017a), arithmetic that leaves the
// doubles is an error, a counter loop ends at the block budget; each case
// runs in microseconds.
#include <gtest/gtest.h>

#include "InterpTestSupport.h"

namespace {

using namespace mtc::core;
using namespace mtc::test;

TEST(InterpLimits, DwellOutsideItsRangeIsRefused) {
    const std::vector<std::pair<const char*, const char*>> cases = {
        {"F100000", "DWELL_TIME_RANGE"},
        {"F=99999999999*99999999999", "DWELL_TIME_RANGE"},
        {"F=-1", "VALUE_RANGE"},
        {"F=0/0", "DIVISION_BY_ZERO"}};
    for (const auto& [time, code] : cases) {
        Station s(demoCell(), 0);
        const RunResult r = s.run(std::string("N0001 G4 ") + time + "\nN0002 M30\n");
        EXPECT_EQ(r.status, RunStatus::Error) << time;
        EXPECT_EQ(errorCodes(r.diagnostics), std::vector<std::string>{code}) << time;
        EXPECT_EQ(s.interpreter->state().modal.time, 0.0) << "no time passed";
    }
    Station s(demoCell(), 0);
    const RunResult r = s.run("N0001 G4 F99999.999\nN0002 M30\n");
    EXPECT_NE(r.status, RunStatus::Error) << diagnosticsText(r.diagnostics);
    EXPECT_DOUBLE_EQ(s.interpreter->state().modal.time, 99999.999);
}

TEST(InterpLimits, ArithmeticBeyondTheDoublesIsAnError) {
    Station s(demoCell(), 0);
    const RunResult r = s.run(
        "N0001 @1=99999999999999\n"
        "N0002 @2=@1*@1*@1*@1*@1*@1*@1*@1*@1*@1*@1*@1*@1*@1*@1*@1*@1*@1*@1*@1*@1*@1*@1\n"
        "N0003 M30\n");
    EXPECT_EQ(r.status, RunStatus::Error);
    EXPECT_EQ(errorCodes(r.diagnostics), std::vector<std::string>{"ARITHMETIC_OVERFLOW"});
}

TEST(InterpLimits, ACounterLoopEndsAtTheBlockBudget) {
    Station s(demoCell(), 0);
    const RunResult r = s.run("N0001 @1=0\nN0002 .L @1=@1+1 BRA .L\n", 1, 50000);
    EXPECT_EQ(r.status, RunStatus::BudgetExceeded);
    EXPECT_LE(r.blocksInterpreted, 50000u);
}

}  // namespace
