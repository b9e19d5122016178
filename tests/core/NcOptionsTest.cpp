// The NC options settings file and the operator's macro entry
// (docs/decisions/nc-options.md, NO-002..NO-004).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "cnc_core/compiler/GlobalMacroFile.h"
#include "cnc_core/compiler/NcOptions.h"

namespace fs = std::filesystem;
using namespace mtc::core;

namespace {

class OptionsDir {
  public:
    OptionsDir() {
        const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
        path_ = fs::temp_directory_path() /
                ("mtc-ncopt-" + std::to_string(::getpid()) + "-" + test->name());
        fs::create_directories(path_);
    }
    ~OptionsDir() { fs::remove_all(path_); }
    std::string path() const { return path_.string(); }

  private:
    fs::path path_;
};

NcOptions sampleOptions() {
    NcOptions options;
    options.compilerActive = true;
    setUserCompilerCommand(options.userCompilers, 1, "/opt/cnc/ellipse --metric");
    setUserCompilerCommand(options.userCompilers, 4, "checker");
    return options;
}

}  // namespace

TEST(NcOptionsFile, PresetIsCompilerOffAndNoUserCompilers) {
    const NcOptionsContents contents = parseNcOptionsFile("");
    EXPECT_FALSE(contents.options.compilerActive);
    EXPECT_TRUE(contents.options.userCompilers.empty());
    EXPECT_TRUE(contents.problems.empty());
}

TEST(NcOptionsFile, FormatThenParseGivesTheSameSettings) {
    const NcOptions options = sampleOptions();
    const NcOptionsContents back = parseNcOptionsFile(formatNcOptionsFile(options));
    EXPECT_TRUE(back.problems.empty());
    EXPECT_TRUE(back.options.compilerActive);
    EXPECT_EQ(userCompilerCommand(back.options.userCompilers, 1), "/opt/cnc/ellipse --metric");
    EXPECT_EQ(userCompilerCommand(back.options.userCompilers, 2), "");
    EXPECT_EQ(userCompilerCommand(back.options.userCompilers, 4), "checker");
}

TEST(NcOptionsFile, BadLinesAreRefusedWithTheirLineNumberPresetsKept) {
    const NcOptionsContents contents = parseNcOptionsFile(
        "; comment\n"
        "compiler_active = yes\n"       // 2: taken (keys and YES/NO in any case)
        "COMPILER_ACTIVE = NO\n"        // 3: twice
        "USER_COMPILER_5 = x\n"         // 4: unknown slot
        "just text\n"                   // 5: no '='
        "USER_COMPILER_2 = a\tb\n"      // 6: control character
        "USER_COMPILER_3 =   cc  \r\n"  // 7: taken, trimmed
    );
    EXPECT_TRUE(contents.options.compilerActive);
    EXPECT_EQ(userCompilerCommand(contents.options.userCompilers, 2), "");
    EXPECT_EQ(userCompilerCommand(contents.options.userCompilers, 3), "cc");
    ASSERT_EQ(contents.problems.size(), 4u);
    EXPECT_EQ(contents.problems[0].line, 3);
    EXPECT_NE(contents.problems[0].message.find("twice"), std::string::npos);
    EXPECT_EQ(contents.problems[1].line, 4);
    EXPECT_EQ(contents.problems[2].line, 5);
    EXPECT_EQ(contents.problems[3].line, 6);
    EXPECT_EQ(contents.problems[3].file, kNcOptionsFileName);
}

TEST(NcOptionsFile, CompilerActiveMustBeYesOrNo) {
    const NcOptionsContents contents = parseNcOptionsFile("COMPILER_ACTIVE = 1\n");
    EXPECT_FALSE(contents.options.compilerActive);
    ASSERT_EQ(contents.problems.size(), 1u);
    EXPECT_EQ(contents.problems[0].line, 1);
}

TEST(NcOptionsFile, UserCompilerCommandChecks) {
    EXPECT_EQ(checkUserCompilerCommand(""), "");
    EXPECT_EQ(checkUserCompilerCommand("CHECK.EXE -v"), "");
    EXPECT_NE(checkUserCompilerCommand(std::string(kMaxUserCompilerCommandLength + 1, 'x')), "");
    EXPECT_EQ(checkUserCompilerCommand(std::string(kMaxUserCompilerCommandLength, 'x')), "");
    EXPECT_NE(checkUserCompilerCommand("a\nb"), "");
    EXPECT_NE(checkUserCompilerCommand(" lead"), "");
    UserCompilerSlots slots;
    EXPECT_FALSE(setUserCompilerCommand(slots, 0, "x"));
    EXPECT_FALSE(setUserCompilerCommand(slots, 5, "x"));
    EXPECT_TRUE(slots.empty());
    EXPECT_EQ(userCompilerCommand(slots, 9), "");
}

TEST(NcOptionsFile, WriteAndReadBothFilesOfTheProgramDirectory) {
    OptionsDir dir;
    const NcOptionsContents none = readNcOptions(dir.path());
    EXPECT_FALSE(none.options.compilerActive);
    EXPECT_TRUE(none.problems.empty());
    std::string error;
    ASSERT_TRUE(writeNcOptionsFile(dir.path(), sampleOptions(), error)) << error;
    ASSERT_TRUE(writeGlobalMacroFile(dir.path(), {{"QUICK", "G1 F9000"}}, error)) << error;
    {
        std::ofstream(fs::path(dir.path()) / kGlobalMacroFileName, std::ios::app)
            << "DEFINE LA_ON AS G1\n";
    }
    const NcOptionsContents back = readNcOptions(dir.path());
    EXPECT_TRUE(back.options.compilerActive);
    EXPECT_EQ(userCompilerCommand(back.options.userCompilers, 4), "checker");
    ASSERT_EQ(back.options.globalMacros.size(), 1u);
    EXPECT_EQ(back.options.globalMacros[0].name, "QUICK");
    ASSERT_EQ(back.problems.size(), 1u);  // LA_ON is a keyword
    EXPECT_EQ(back.problems[0].file, kGlobalMacroFileName);
    EXPECT_EQ(back.problems[0].line, 3);
}

TEST(NcOptionsFile, WriteIntoAMissingDirectoryFailsWithAReason) {
    std::string error;
    EXPECT_FALSE(writeNcOptionsFile("/nonexistent-mtc-dir/x", sampleOptions(), error));
    EXPECT_FALSE(error.empty());
}

TEST(NcOptionsFile, FuzzedTextNeverCrashesAndKeepsOnlyValidSettings) {
    std::mt19937 random(2026);
    const std::string pieces[] = {"COMPILER_ACTIVE",
                                  "USER_COMPILER_",
                                  "1",
                                  "4",
                                  "7",
                                  "=",
                                  " = ",
                                  "YES",
                                  "no",
                                  "\n",
                                  "\r",
                                  ";",
                                  "\t",
                                  " ",
                                  "cmd",
                                  "\0",
                                  "=="};
    for (int round = 0; round < 4000; ++round) {
        std::string text;
        const int count = static_cast<int>(random() % 50);
        for (int i = 0; i < count; ++i) {
            if (random() % 6 == 0)
                text += static_cast<char>(random() % 256);
            else
                text += pieces[random() % std::size(pieces)];
        }
        const NcOptionsContents contents = parseNcOptionsFile(text);
        for (int slot = 1; slot <= kUserCompilerSlotCount; ++slot)
            EXPECT_EQ(
                checkUserCompilerCommand(userCompilerCommand(contents.options.userCompilers, slot)),
                "")
                << text;
        for (const NcOptionsProblem& problem : contents.problems) {
            EXPECT_GE(problem.line, 1);
            EXPECT_FALSE(problem.message.empty());
        }
        // what was taken survives a round trip
        const NcOptionsContents back = parseNcOptionsFile(formatNcOptionsFile(contents.options));
        EXPECT_TRUE(back.problems.empty()) << text;
        EXPECT_EQ(back.options.compilerActive, contents.options.compilerActive);
        for (int slot = 1; slot <= kUserCompilerSlotCount; ++slot)
            EXPECT_EQ(userCompilerCommand(back.options.userCompilers, slot),
                      userCompilerCommand(contents.options.userCompilers, slot));
    }
}

TEST(GlobalMacroEntry, ATypedDefinitionIsCheckedBesideTheOthers) {
    const std::vector<MacroDefinition> others = {{"QUICK", "G1 F9000"}, {"COOL_ON", "M8"}};
    MacroDefinition macro;
    std::string problem;
    ASSERT_TRUE(parseGlobalMacroEntry("DEFINE SLOW AS G1 F100", others, "", macro, problem))
        << problem;
    EXPECT_EQ(macro.name, "SLOW");
    EXPECT_EQ(macro.body, "G1 F100");
    EXPECT_FALSE(parseGlobalMacroEntry("SLOW = G1", others, "", macro, problem));
    EXPECT_NE(problem.find("DEFINE"), std::string::npos);
    EXPECT_FALSE(parseGlobalMacroEntry("", others, "", macro, problem));
    EXPECT_FALSE(parseGlobalMacroEntry("DEFINE LA_ON AS G1", others, "", macro, problem));
    EXPECT_FALSE(parseGlobalMacroEntry("DEFINE TWICE AS QUICK X1", others, "", macro, problem));
    EXPECT_NE(problem.find("nested"), std::string::npos);
    EXPECT_FALSE(parseGlobalMacroEntry("DEFINE QUICK AS G0", others, "", macro, problem));
    EXPECT_NE(problem.find("already"), std::string::npos);
    // changing QUICK itself is fine
    EXPECT_TRUE(parseGlobalMacroEntry("DEFINE QUICK AS G0", others, "QUICK", macro, problem))
        << problem;
    EXPECT_FALSE(parseGlobalMacroEntry("DEFINE LONG AS " + std::string(157, '1'), others, "", macro,
                                       problem));
    EXPECT_FALSE(
        parseGlobalMacroEntry("DEFINE A1 AS X1\nDEFINE A2 AS X2", others, "", macro, problem));
}
