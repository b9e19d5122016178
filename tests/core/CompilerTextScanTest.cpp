// The caseless keyword pre-check that lets passes skip programs without
// their keywords (issue 6 speed target).
#include <gtest/gtest.h>

#include "cnc_core/compiler/Compiler.h"
#include "cnc_core/compiler/CompilerText.h"

namespace mtc::core {
namespace {

TEST(CompilerTextScan, FindsNeedlesWithoutCase) {
    EXPECT_TRUE(containsAnyCaseless("X10 la_on", {"LA_"}));
    EXPECT_TRUE(containsAnyCaseless("CONT (1)", {"START", "CONT"}));
    EXPECT_TRUE(containsAnyCaseless("g1 ccw", {"CW"}));
    EXPECT_FALSE(containsAnyCaseless("X10 Y20 F1200 M8", {"CONT", "LA_", "TRC"}));
    EXPECT_FALSE(containsAnyCaseless("", {"CW"}));
    EXPECT_FALSE(containsAnyCaseless("CO", {"CONT"}));
}

TEST(CompilerTextScan, LookAheadWordStillReportedAfterPreCheck) {
    // LA_OFF alone must reach the look-ahead pass (the pre-check sees "LA_").
    CompilerOptions options;
    options.compilerActive = true;
    const CompileResult result = Compiler().compile("N0001 G1 X10 F100\nN0002 LA_OFF\n", options);
    ASSERT_EQ(result.status, CompileStatus::Error);
    bool found = false;
    for (const CompilerError& e : result.errors)
        found = found || e.code == "LA_OFF_WITHOUT_ON";
    EXPECT_TRUE(found);
}

TEST(CompilerTextScan, GneKeywordStillReportedAfterPreCheck) {
    // END_CONT without CONT must reach the GNE pass (the pre-check sees "CONT").
    CompilerOptions options;
    options.compilerActive = true;
    const CompileResult result = Compiler().compile("N0001 G1 X10 F100\nN0002 END_CONT\n", options);
    ASSERT_EQ(result.status, CompileStatus::Error);
    bool found = false;
    for (const CompilerError& e : result.errors)
        found = found || e.code == "GNE_END_CONT_ALONE";
    EXPECT_TRUE(found);
}

TEST(CompilerTextScan, ProgramWithoutKeywordsCompilesUnchanged) {
    CompilerOptions options;
    options.compilerActive = true;
    const CompileResult result = Compiler().compile("N0001 G1 X10 Y5 F100\nN0002 X20\n", options);
    ASSERT_EQ(result.status, CompileStatus::Compiled);
    EXPECT_EQ(result.objectText,
              "N0001:0000 G1 X10 Y5 F100\nN0002:0000 X20\nN0003:0000 PROGRAMMENDE\n");
}

}  // namespace
}  // namespace mtc::core
