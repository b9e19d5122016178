// Adaptive feed control and the machine configuration (seed 002, 4.2): the
// process parameters B062..B069 are refused by the configuration reader with
// line, key, value and range; an AdaptiveFeedControl built on a configuration
// made in code with bad values reports them instead of crashing.
#include <gtest/gtest.h>

#include <algorithm>
#include <string_view>

#include "InterpTestSupport.h"
#include "cnc_core/afc/AdaptiveFeedControl.h"
#include "cnc_core/afc/AfcParameterRanges.h"
#include "cnc_core/machine/ConfigSchema.h"
#include "cnc_core/machine/MachineConfigReader.h"
#include "cnc_core/machine_data/MachineDataStore.h"

namespace {

using namespace mtc::core;
using namespace mtc::test;

/// A one-process configuration whose process section ends with `parameters`
/// (line 4 is the first parameter line). The ranges and the message form are
/// the configuration reader's rule table (docs/decisions/config-files.md CF-001).
std::string cellWith(const std::string& parameters) {
    return "[cell]\nname = afc\n[process 0]\n" + parameters +
           "[process 0 axis X]\ndefinition = X\n[process 0 spindle S1]\nindex = 1\n";
}

TEST(AfcConfig, ReaderRefusesOutOfRangeAndNonNumericParameters) {
    const MachineConfigReadResult result =
        readMachineConfig(cellWith("B062 = maybe\nB063 = 13\nB064 = 80\nB065 = 600\nB066 = lots\n"
                                   "B067 = 100.5\nB068 = 0\nB069 = 1.5\n"));
    ASSERT_EQ(result.diagnostics.items().size(), 7u) << diagnosticsText(result.diagnostics);
    std::vector<int> lines;
    for (const Diagnostic& d : result.diagnostics.items()) {
        EXPECT_EQ(d.code, "CFG_VALUE");
        lines.push_back(d.where.line);
    }
    EXPECT_EQ(lines, (std::vector<int>{4, 5, 7, 8, 9, 10, 11}));
    const auto message = [&](std::size_t i) { return result.diagnostics.items()[i].message; };
    EXPECT_NE(message(0).find("B062 = 'maybe'"), std::string::npos) << message(0);
    EXPECT_NE(message(0).find("allowed: yes | no"), std::string::npos);
    EXPECT_NE(message(1).find("allowed: 0 … 12 (whole)"), std::string::npos) << message(1);
    EXPECT_NE(message(2).find("B065 = '600'"), std::string::npos) << message(2);
    EXPECT_NE(message(2).find("allowed: 0 … 500 %"), std::string::npos) << message(2);
    EXPECT_NE(message(3).find("B066 = 'lots'"), std::string::npos);
    EXPECT_NE(message(5).find("allowed: 0.01 … 100 1/s"), std::string::npos) << message(5);
    EXPECT_NE(message(6).find("allowed: 2 … 60000 ms (whole)"), std::string::npos) << message(6);
}

TEST(AfcConfig, ReaderAcceptsTheRangeLimits) {
    const MachineConfigReadResult result =
        readMachineConfig(cellWith("B062 = Yes\nB063 = 0\nB064 = 500\nB065 = 0\nB066 = 0.0\n"
                                   "B067 = 100\nB068 = 0.01\nB069 = 60000\n"));
    EXPECT_TRUE(result.ok()) << diagnosticsText(result.diagnostics);
}

TEST(AfcConfig, BadParametersOfAConfigurationMadeInCodeAreReportedNotACrash) {
    // Regression: the diagnostics list was written before it was constructed
    // (member initialisation order), a SIGSEGV for any bad B063..B069.
    const MachineConfig cell = demoCell();
    ProcessConfig process = *cell.process(0);
    process.parameters["B063"] = "S1";
    process.parameters["B065"] = "600";
    process.parameters["B069"] = "1.5";
    MachineDataStore data(cell);
    const AdaptiveFeedControl afc(process, data);
    EXPECT_EQ(errorCodes(afc.parameterDiagnostics()), std::vector<std::string>(3, "AFC_PARAMETER"));
    EXPECT_EQ(afc.effectiveSettings().minimumTorque, 10.0) << "the default is used";
    EXPECT_EQ(afc.effectiveSettings().measuringPeriodMs, 200.0);
}

TEST(AfcConfig, B062OnlyYesOrNo) {
    bool value = false;
    EXPECT_TRUE(parseYesNo("YES", value));
    EXPECT_TRUE(value);
    EXPECT_TRUE(parseYesNo("0", value));
    EXPECT_FALSE(value);
    EXPECT_FALSE(parseYesNo("maybe", value));
    double parsed = -1;
    EXPECT_FALSE(readAfcParameterValue("B062", "maybe", parsed));
    EXPECT_EQ(parsed, -1.0);
    EXPECT_TRUE(readAfcParameterValue("B062", "no", parsed));
    EXPECT_EQ(parsed, 0.0);
    EXPECT_FALSE(readAfcParameterValue("B064", "nan", parsed));
    EXPECT_FALSE(readAfcParameterValue("B064", "1e999", parsed));
    EXPECT_TRUE(readAfcParameterValue("B004", "anything", parsed)) << "not an AFC parameter";
}

}  // namespace

namespace mtc::test {
namespace {

// One table of the AFC parameter ranges (issue 22 §1): the configuration's
// schema holds exactly the AFC reader's ranges, once each, right after B062.
TEST(AfcParameterRanges, TheConfigurationSchemaUsesTheSameTable) {
    const auto& rules = core::configRules();
    for (const core::AfcParameterRange* r = core::afcParameterRangesBegin();
         r != core::afcParameterRangesEnd(); ++r) {
        int found = 0;
        for (const core::ConfigRule& rule : rules)
            if (rule.section == core::ConfigSection::Process && rule.key == r->key) {
                ++found;
                EXPECT_EQ(rule.minimum, r->minimum) << r->key;
                EXPECT_EQ(rule.maximum, r->maximum) << r->key;
                EXPECT_EQ(rule.type == core::ConfigValueType::Whole, r->whole) << r->key;
                EXPECT_EQ(rule.unit, std::string_view(r->unit)) << r->key;
            }
        EXPECT_EQ(found, 1) << r->key;
    }
    EXPECT_EQ(core::afcParameterRangesEnd() - core::afcParameterRangesBegin(), 7);
    const auto b062 = std::find_if(rules.begin(), rules.end(),
                                   [](const core::ConfigRule& rule) { return rule.key == "B062"; });
    ASSERT_NE(b062, rules.end());
    ASSERT_NE(b062 + 1, rules.end());
    EXPECT_EQ((b062 + 1)->key, "B063");
}

}  // namespace
}  // namespace mtc::test
