// User compiler commands run without a shell (docs/DECISIONS.md D-010):
// split into words like the shell splits them, shell operators refused,
// started directly, stopped after a time limit.
#include <gtest/gtest.h>

#include <filesystem>

#include "cnc_core/compiler/CommandLine.h"
#include "cnc_core/compiler/NcOptions.h"

namespace {

using namespace mtc::core;

std::vector<std::string> split(const std::string& command) {
    std::vector<std::string> words;
    std::string problem;
    EXPECT_TRUE(splitCommandLine(command, words, problem)) << command << ": " << problem;
    return words;
}

std::string refusal(const std::string& command) {
    std::vector<std::string> words;
    std::string problem;
    EXPECT_FALSE(splitCommandLine(command, words, problem)) << command;
    return problem;
}

TEST(CommandLine, WordsAreSplitLikeTheShellSplitsThem) {
    EXPECT_EQ(split("/opt/cnc/ellipse --metric"),
              (std::vector<std::string>{"/opt/cnc/ellipse", "--metric"}));
    EXPECT_EQ(split("sh -c 'sed s/A/B/ \"$0\" > \"$1\"'"),
              (std::vector<std::string>{"sh", "-c", "sed s/A/B/ \"$0\" > \"$1\""}));
    EXPECT_EQ(split("tool \"two words\" a\\ b \"q\\\"uote\""),
              (std::vector<std::string>{"tool", "two words", "a b", "q\"uote"}));
    EXPECT_EQ(split("a''b"), (std::vector<std::string>{"ab"}));
}

TEST(CommandLine, ShellOperatorsAreRefusedNotInterpreted) {
    for (const char* command : {"checker; rm -rf ~", "a | b", "a && b", "a > out", "a < in",
                                "$(evil)", "`evil`", "a $HOME", "a *.DAT", "a ~/x", "a (b)",
                                "a \"$HOME\"", "a 'open", "a \"open", "a \\", ""})
        EXPECT_FALSE(refusal(command).empty()) << command;
    EXPECT_NE(refusal("checker; rm -rf ~").find("without a shell"), std::string::npos);
    EXPECT_FALSE(checkUserCompilerCommand("checker; rm -rf ~").empty())
        << "the NC options refuse it when it is entered or read";
    EXPECT_TRUE(checkUserCompilerCommand("sh -c 'exit 0'").empty());
}

TEST(CommandLine, ACommandRunsDirectlyAndIsStoppedWhenItHangs) {
    const std::string marker = std::filesystem::temp_directory_path() /
                               ("mtc-cmdline-" + std::to_string(::getpid()));
    std::filesystem::remove(marker);
    // Without a shell, ';' and '>' are plain arguments of echo: nothing else runs.
    CommandOutcome echo = runCommand({"echo", "x;", "touch", marker}, 10);
    EXPECT_TRUE(echo.problem.empty()) << echo.problem;
    EXPECT_EQ(echo.exitStatus, 0);
    EXPECT_FALSE(std::filesystem::exists(marker));
    EXPECT_EQ(runCommand({"false"}, 10).exitStatus, 1);
    const CommandOutcome missing = runCommand({"/no/such/compiler"}, 10);
    EXPECT_FALSE(missing.problem.empty());
    const CommandOutcome hang = runCommand({"sleep", "30"}, 0.2);
    EXPECT_TRUE(hang.timedOut);
    EXPECT_NE(hang.problem.find("did not finish"), std::string::npos) << hang.problem;
}

}  // namespace
