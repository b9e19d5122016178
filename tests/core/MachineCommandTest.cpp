// Typed machine commands (issue 16 §1): the interpreter reads a command
// word once into a MachineCommand; receivers use its keyword and action.
#include <gtest/gtest.h>

#include <string>

#include "cnc_core/interp/MachineCommand.h"
#include "cnc_core/language/Keywords.h"

using namespace mtc::core;

namespace {

TEST(MachineCommand, EveryCommandKeywordOfTheParserHasItsTypedKeyword) {
    for (int k = 0; k <= static_cast<int>(CommandKeyword::BRJ); ++k) {
        const auto keyword = static_cast<CommandKeyword>(k);
        EXPECT_EQ(lookupKeyword(keywordName(keyword)).keywordClass, KeywordClass::Command)
            << keywordName(keyword);
        EXPECT_EQ(commandKeyword(keywordName(keyword)), keyword) << keywordName(keyword);
    }
    // The other way round: every name of two or three letters the parser
    // takes for a command has a typed keyword.
    std::string name;
    for (char a = 'A'; a <= 'Z'; ++a)
        for (char b = 'A'; b <= 'Z'; ++b)
            for (char c = '@'; c <= 'Z'; ++c) {  // '@': two letters
                name = std::string{a, b};
                if (c != '@') name += c;
                if (lookupKeyword(name).keywordClass == KeywordClass::Command) {
                    EXPECT_TRUE(commandKeyword(name).has_value()) << name;
                }
            }
    EXPECT_FALSE(commandKeyword("CF").has_value()) << "a compiler keyword";
}

TEST(MachineCommand, ToolTransferCarriesTheSpindle) {
    auto tch = readMachineCommand("TCH(3, 2)", "(3, 2)");
    ASSERT_TRUE(tch);
    EXPECT_EQ(tch->keyword, CommandKeyword::TCH);
    ASSERT_TRUE(std::holds_alternative<ToolTransferCommand>(tch->action));
    EXPECT_EQ(std::get<ToolTransferCommand>(tch->action).spindle, 2);
    EXPECT_FALSE(performedWhileComputing(*tch));
    const auto noSpindle = readMachineCommand("TSM(1)", "(1)");
    ASSERT_TRUE(noSpindle);
    EXPECT_EQ(std::get<ToolTransferCommand>(noSpindle->action).spindle, 1) << "SPI defaults to 1";
    const auto tooLarge =
        readMachineCommand("TMS(1,99999999999999999999)", "(1,99999999999999999999)");
    ASSERT_TRUE(tooLarge);
    EXPECT_EQ(std::get<ToolTransferCommand>(tooLarge->action).spindle, 1) << "out of 1..4";
}

TEST(MachineCommand, AxisTransferCarriesTheAxes) {
    const auto gax = readMachineCommand("GAX(x1, Z2 )", "(x1, Z2 )");
    ASSERT_TRUE(gax);
    const auto& transfer = std::get<AxisTransferCommand>(gax->action);
    EXPECT_EQ(transfer.kind, AxisTransferKind::Get);
    EXPECT_EQ(transfer.axes, (std::vector<std::string>{"X1", "Z2"}));
    EXPECT_TRUE(performedWhileComputing(*gax));
    const auto none = readMachineCommand("FAX()", "()");
    ASSERT_TRUE(none) << "still a command: the interpreter refuses it with its block";
    EXPECT_EQ(std::get<AxisTransferCommand>(none->action).kind, AxisTransferKind::Free);
    EXPECT_TRUE(std::get<AxisTransferCommand>(none->action).axes.empty());
}

TEST(MachineCommand, FamiliesDecideWhatTheComputingProcessPerforms) {
    for (const char* held : {"MTP", "MRY", "MRV", "TSE", "TPE", "PMP", "NMP", "TCH"}) {
        const auto command = readMachineCommand(held, "");
        ASSERT_TRUE(command) << held;
        EXPECT_FALSE(performedWhileComputing(*command)) << held;
    }
    for (const char* passed : {"AXD", "ACC", "TLD", "DP", "WES", "POK", "BRJ"}) {
        const auto command = readMachineCommand(passed, "");
        ASSERT_TRUE(command) << passed;
        EXPECT_TRUE(std::holds_alternative<SpsCommand>(command->action)) << passed;
        EXPECT_TRUE(performedWhileComputing(*command)) << passed;
    }
}

TEST(MachineCommand, TextIsTheKeywordAndTheProgrammedArguments) {
    auto axd = readMachineCommand("AXD (X:S-0-0104)=7000", "(X:S-0-0104)=7000");
    ASSERT_TRUE(axd);
    EXPECT_EQ(commandText(*axd), "AXD ((X:S-0-0104)=7000)");
    EXPECT_EQ(commandText(*readMachineCommand("MTP", "")), "MTP ()");
    EXPECT_FALSE(readMachineCommand("XYZ(1)", "(1)")) << "not a command keyword";
}

}  // namespace
