#include <gtest/gtest.h>

#include "cnc_core/machine/MachineConfigReader.h"
#include "resources/EmbeddedResources.h"

using namespace mtc::core;

TEST(MachineConfig, DemoCellMatchesMachinesContract) {
    auto result = readMachineConfig(mtc::resources::find(mtc::resources::kDemoCellName));
    for (const auto& d : result.diagnostics.items())
        ADD_FAILURE() << formatDiagnostic(d);
    ASSERT_TRUE(result.ok());
    ASSERT_EQ(result.config.processes.size(), 2u);
    const ProcessConfig& mill = *result.config.process(0);
    EXPECT_EQ(mill.name, "Mill");
    EXPECT_EQ(mill.defaultPlane(), 17);
    EXPECT_EQ(mill.tools.size(), 24u);
    EXPECT_TRUE(mill.flag("B062"));
    EXPECT_EQ(mill.number("B063"), 10);
    ASSERT_NE(mill.mGroupOf(19), nullptr);
    EXPECT_EQ(mill.mGroupOf(19)->number, 2);
    EXPECT_EQ(mill.mGroupOf(41)->resetValue, 40);
    EXPECT_EQ(mill.mGroupOf(918)->number, 15);
    EXPECT_EQ(mill.mGroupOf(6), nullptr) << "M6 belongs to group 16";

    const ProcessConfig& lathe = *result.config.process(1);
    EXPECT_EQ(lathe.name, "Lathe");
    EXPECT_EQ(lathe.defaultPlane(), 18);
    EXPECT_TRUE(lathe.flag("B058"));
    const AxisConfig* s1 = lathe.axis("S1");
    ASSERT_NE(s1, nullptr);
    EXPECT_EQ(s1->rotaryAxisName, "C");
    EXPECT_EQ(s1->designation2, "Y1");
    EXPECT_EQ(s1->definitions, (std::vector<std::string>{"C", "Y"}));
    EXPECT_EQ(lathe.axis("X")->definitions, (std::vector<std::string>{"X", "Z"}));
    EXPECT_EQ(lathe.axis("Z2")->definitions, (std::vector<std::string>{"W"}));
    EXPECT_EQ(lathe.mGroupOf(205)->resetValue, 205);
    EXPECT_EQ(lathe.mGroupOf(305)->number, 4);
    EXPECT_EQ(lathe.mGroupOf(68), nullptr);
    ASSERT_EQ(lathe.userPages.size(), 1u);
    EXPECT_EQ(lathe.userPages[0].number, 180);
    EXPECT_EQ(lathe.userPages[0].elements.size(), 2u);
}

TEST(MachineConfig, BadInputGivesDiagnosticsWithLines) {
    auto result = readMachineConfig(
        "[cell]\nname = x\n[process 9]\n[process 0]\nfoo = bar\n"
        "[process 0 axis X]\nmax_velocity = -3\n[nonsense]\nkey\n");
    EXPECT_FALSE(result.ok());
    std::vector<int> lines;
    for (const auto& d : result.diagnostics.items())
        lines.push_back(d.where.line);
    // line 6: axis X has no definition (ProcessAxes::build, reported with
    // the line of its section after the whole file was read)
    EXPECT_EQ(lines, (std::vector<int>{3, 5, 7, 8, 9, 6}));
}

TEST(MachineConfig, EmptyTextIsAnError) {
    auto result = readMachineConfig("");
    EXPECT_FALSE(result.ok());
    EXPECT_EQ(result.diagnostics.items().front().code, "CFG_NO_PROCESS");
}

// Whole numbers out of int's range (and inf / nan) are refused before any
// conversion: casting them was undefined behaviour (caught by UBSan).
TEST(MachineConfig, IntegerValuesBeyondIntAreRefused) {
    for (const char* value :
         {"1e308", "-1e308", "inf", "-inf", "nan", "4294967296", "2147483648"}) {
        const std::string text = std::string("[process 0]\nname = P\ntool_places = ") + value +
                                 "\n[process " + value + "]\n";
        const auto result = readMachineConfig(text);
        std::vector<int> lines;
        for (const auto& d : result.diagnostics.items())
            lines.push_back(d.where.line);
        EXPECT_EQ(lines, (std::vector<int>{3, 4})) << value;
    }
}
