#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "CompilerTestSupport.h"
#include "cnc_core/compiler/Compiler.h"
#include "cnc_core/compiler/GlobalMacroFile.h"

namespace fs = std::filesystem;
using namespace mtc::core;

namespace {

class MacroDir {
  public:
    MacroDir() {
        const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
        path_ = fs::temp_directory_path() /
                ("mtc-gmacro-" + std::to_string(::getpid()) + "-" + test->name());
        fs::create_directories(path_);
    }
    ~MacroDir() { fs::remove_all(path_); }
    std::string path() const { return path_.string(); }

  private:
    fs::path path_;
};

const std::vector<MacroDefinition> kTwo = {{"QUICK", "G1 F9000"}, {"COOL_ON", "M8"}};

}  // namespace

TEST(GlobalMacroCheck, AcceptsAWellFormedMacro) {
    EXPECT_EQ(checkGlobalMacro({"SLOW_FEED", "G1 F100"}, kTwo), "");
    EXPECT_EQ(checkGlobalMacro({"ABCDEFGHIJKLMNOPQRST", "M9"}, kTwo), "");  // 20 characters
    EXPECT_EQ(checkGlobalMacro({"X1", std::string(156, '1')}, {}), "");
}

TEST(GlobalMacroCheck, RefusesEachLimitOfChapterFour) {
    EXPECT_NE(checkGlobalMacro({"ABCDEFGHIJKLMNOPQRSTU", "M9"}, kTwo), "");  // 21 characters
    EXPECT_NE(checkGlobalMacro({"1ABC", "M9"}, kTwo), "");
    EXPECT_NE(checkGlobalMacro({"MY-MAC", "M9"}, kTwo), "");
    EXPECT_NE(checkGlobalMacro({"LA_ON", "M9"}, kTwo).find("keyword"), std::string::npos);
    EXPECT_NE(checkGlobalMacro({"BSR", "M9"}, kTwo).find("keyword"), std::string::npos);
    EXPECT_NE(checkGlobalMacro({"BIG", std::string(157, '1')}, {}).find("156"), std::string::npos);
    EXPECT_NE(checkGlobalMacro({"EMPTY", "  "}, kTwo), "");
    EXPECT_NE(checkGlobalMacro({"TAIL", "M3 ;comment"}, kTwo).find("follow"), std::string::npos);
    EXPECT_NE(checkGlobalMacro({"TWO", "M3\nM4"}, kTwo), "");
    EXPECT_NE(checkGlobalMacro({"DEF", "DEFINE A AS M3"}, kTwo), "");
}

TEST(GlobalMacroCheck, RefusesNestingInBothDirectionsAndDuplicates) {
    EXPECT_NE(checkGlobalMacro({"FAST", "QUICK X10"}, kTwo).find("nested"), std::string::npos);
    const std::vector<MacroDefinition> usesLater = {{"A_MAC", "LATER X1"}};
    EXPECT_NE(checkGlobalMacro({"LATER", "M3"}, usesLater).find("nested"), std::string::npos);
    EXPECT_NE(checkGlobalMacro({"SELF", "SELF X1"}, {}).find("nested"), std::string::npos);
    EXPECT_NE(checkGlobalMacro({"QUICK", "G1 F100"}, kTwo).find("already"), std::string::npos);
    // changing QUICK itself is fine
    EXPECT_EQ(checkGlobalMacro({"QUICK", "G1 F100"}, kTwo, "QUICK"), "");
}

TEST(GlobalMacroFile, FormatThenParseGivesTheSameMacros) {
    const MacroFileContents back = parseGlobalMacroFile(formatGlobalMacroFile(kTwo));
    EXPECT_TRUE(back.problems.empty());
    ASSERT_EQ(back.macros.size(), 2u);
    EXPECT_EQ(back.macros[0].name, "QUICK");
    EXPECT_EQ(back.macros[0].body, "G1 F9000");
    EXPECT_EQ(back.macros[1].name, "COOL_ON");
    EXPECT_EQ(back.macros[1].body, "M8");
}

TEST(GlobalMacroFile, BadLinesAreRefusedWithTheirLineNumberOthersKept) {
    const std::string text =
        "; header\r\n"
        "DEFINE GOOD AS M3 S100\r\n"
        "\n"
        "DEFINE ONLYNAME\n"
        "DEFINE NESTED AS GOOD X1\n"
        "DEFINE GOOD AS M4\n"
        "  DEFINE LAST   AS   G0 X0  \n";
    const MacroFileContents contents = parseGlobalMacroFile(text);
    ASSERT_EQ(contents.macros.size(), 2u);
    EXPECT_EQ(contents.macros[1].name, "LAST");
    EXPECT_EQ(contents.macros[1].body, "G0 X0");
    ASSERT_EQ(contents.problems.size(), 3u);
    EXPECT_EQ(contents.problems[0].line, 4);
    EXPECT_EQ(contents.problems[1].line, 5);
    EXPECT_EQ(contents.problems[2].line, 6);
}

TEST(GlobalMacroFile, WriteAndReadInTheProgramDirectory) {
    MacroDir dir;
    EXPECT_TRUE(readGlobalMacroFile(dir.path()).macros.empty());  // no file: no macros
    EXPECT_TRUE(readGlobalMacroFile(dir.path()).problems.empty());
    std::string error;
    ASSERT_TRUE(writeGlobalMacroFile(dir.path(), kTwo, error)) << error;
    const MacroFileContents back = readGlobalMacroFile(dir.path());
    ASSERT_EQ(back.macros.size(), 2u);
    EXPECT_EQ(back.macros[1].body, "M8");
    EXPECT_TRUE(fs::exists(fs::path(dir.path()) / kGlobalMacroFileName));
}

TEST(GlobalMacroFile, WriteIntoAMissingDirectoryFailsWithAReason) {
    std::string error;
    EXPECT_FALSE(writeGlobalMacroFile("/nonexistent-mtc-dir/x", kTwo, error));
    EXPECT_FALSE(error.empty());
}

TEST(GlobalMacroFile, FuzzedTextNeverCrashesAndKeepsOnlyValidMacros) {
    std::mt19937 random(4711);
    const std::string pieces[] = {"DEFINE ", "AS ", "QUICK ", "G1 ", "X10 ", ";",
                                  "\n",      "\r",  "LA_ON ", "M3",  "(",    ")",
                                  "@1",      ".L ", "  ",     "\t",  "\0"};
    for (int round = 0; round < 3000; ++round) {
        std::string text;
        const int count = static_cast<int>(random() % 40);
        for (int i = 0; i < count; ++i) {
            if (random() % 5 == 0)
                text += static_cast<char>(random() % 256);
            else
                text += pieces[random() % std::size(pieces)];
        }
        const MacroFileContents contents = parseGlobalMacroFile(text);
        for (std::size_t i = 0; i < contents.macros.size(); ++i) {
            std::vector<MacroDefinition> others = contents.macros;
            others.erase(others.begin() + static_cast<long>(i));
            EXPECT_EQ(checkGlobalMacro(contents.macros[i], others), "") << text;
        }
        // what was kept survives a round trip
        const MacroFileContents back = parseGlobalMacroFile(formatGlobalMacroFile(contents.macros));
        EXPECT_EQ(back.macros.size(), contents.macros.size()) << text;
    }
}

TEST(MdiLine, GlobalMacrosAreExpanded) {
    std::string expanded, problem;
    ASSERT_TRUE(expandMdiLine("QUICK X10 COOL_ON", kTwo, expanded, problem)) << problem;
    EXPECT_EQ(expanded, "G1 F9000 X10 M8");
    ASSERT_TRUE(expandMdiLine("G0 X5", kTwo, expanded, problem));
    EXPECT_EQ(expanded, "G0 X5");
}

TEST(MdiLine, DefinitionsAndOtherCompilerKeywordsAreRefused) {
    std::string expanded, problem;
    EXPECT_FALSE(expandMdiLine("DEFINE A AS M3", kTwo, expanded, problem));
    EXPECT_NE(problem.find("defined"), std::string::npos);
    EXPECT_FALSE(expandMdiLine("LA_ON", kTwo, expanded, problem));
    EXPECT_NE(problem.find("LA_ON"), std::string::npos);
    // a comment may name anything
    EXPECT_TRUE(expandMdiLine("G0 X1 ;LA_ON", kTwo, expanded, problem));
    // A free text in brackets is no keyword use (the macro pass's name scan).
    EXPECT_TRUE(expandMdiLine("G0 X1 (LA_ON LATER)", kTwo, expanded, problem)) << problem;
}

TEST(GlobalMacroFile, MacrosReadFromTheFileAreExpandedByTheCompiler) {
    const MacroFileContents contents = parseGlobalMacroFile("DEFINE FAST AS G1 F5000\n");
    ASSERT_EQ(contents.macros.size(), 1u);
    const CompileResult result = mtc::test::compileText("N0001 FAST X10\n", contents.macros);
    EXPECT_EQ(result.status, CompileStatus::Compiled);
    EXPECT_NE(result.objectText.find("G1 F5000 X10"), std::string::npos) << result.objectText;
}
