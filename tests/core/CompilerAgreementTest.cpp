// One rule for check and compile (issue 15 §4): a program that needs the
// compiler is checked by compiling it (GNE and look-ahead errors included),
// the source file's rules hold for compile too (lines of at most 71
// characters), macro names inside expression brackets are expanded, the
// compiler-off download check, warnings without an error file, and the
// enhanced numbers the GNE writes into a source program.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "CompilerTestSupport.h"
#include "cnc_core/compiler/CompilerFiles.h"
#include "cnc_core/compiler/ProgramCheck.h"
#include "cnc_core/language/CompilerWords.h"
#include "cnc_core/language/Parser.h"

using namespace mtc::core;
using namespace mtc::test;

namespace {

const char* kHeader =
    "iMTc/010001/01.00/0000000000/03.02.2025/07:30:00/N0010009.DAT/1\n"
    "%NPG:0:01:0:009\n"
    "!01.00\n"
    "*agreement\n"
    "%NPG\n";

/// Error codes of a list.
std::vector<std::string> errorCodesOf(const DiagnosticList& list) {
    std::vector<std::string> out;
    for (const Diagnostic& d : list.items())
        if (d.severity == Severity::Error) out.push_back(d.code);
    return out;
}

/// The check of `source` (a .DAT text when it has the header), the
/// program parsed knowing the names of the global macros as the CLI does.
DiagnosticList check(const std::string& source, const std::vector<MacroDefinition>& globals = {}) {
    ParseOptions parse{9, "N0010009.DAT", {}};
    for (const MacroDefinition& m : globals)
        parse.macroNames.push_back(m.name);
    const Program program = parseProgram(source, parse);
    CompilerOptions options;
    options.programNumber = 9;
    options.globalMacros = globals;
    return checkProgram(program, options);
}

TEST(CompilerAgreement, CheckFailsWhereTheGneFailsToCompile) {
    // a cycle naming a contour that does not exist: GNE_NO_GEOMETRY
    const std::string source =
        "N0001 WINDOW_01 (-40, 2, 30)\nN0002 CYCLE_10 (7, 1, 0.2)\nN0003 M30\n";
    const CompileResult compiled = compileText(source);
    ASSERT_EQ(compiled.status, CompileStatus::Error);
    ASSERT_FALSE(compiled.errors.empty());
    const std::vector<std::string> found = errorCodesOf(check(source));
    EXPECT_EQ(found, std::vector<std::string>{compiled.errors[0].code});
    EXPECT_EQ(found, std::vector<std::string>{"GNE_NO_GEOMETRY"});
}

TEST(CompilerAgreement, CheckFailsWhereTheLookAheadFailsToCompile) {
    const std::string source =
        "N0001 G0 G17 G90 X0 Y0\nN0002 LA_ON\nN0003 G1 X10 F1000\nN0004 G0 X20\n"
        "N0005 LA_OFF\nN0006 M30\n";
    const CompileResult compiled = compileText(source);
    ASSERT_EQ(compiled.status, CompileStatus::Error);
    EXPECT_EQ(errorCodesOf(check(source)), std::vector<std::string>{"LA_COMMAND_NOT_ALLOWED"});
}

TEST(CompilerAgreement, CompileRefusesLinesOverSeventyOneCharactersAsCheckDoes) {
    // the CF/RD pass rewrites the block (and would wrap it), but the source
    // line is too long: seed 001 ch. 10
    const std::string source = std::string(kHeader) + "N0001 G1 G17 G90 X0 Y0 F1000\n" +
                               "N0002 X10 CF1 ;" + std::string(60, 'a') + "\nN0003 Y10\n" +
                               "N0004 M30\nN0005 PROGRAMMENDE\n";
    const CompileResult compiled = Compiler().compile(source, [] {
        CompilerOptions o;
        o.compilerActive = true;
        o.programNumber = 9;
        return o;
    }());
    ASSERT_EQ(compiled.status, CompileStatus::Error);
    ASSERT_EQ(codes(compiled), std::vector<std::string>{"FILE_LINE_TOO_LONG"});
    EXPECT_EQ(compiled.errors[0].block, "N0002");
    EXPECT_EQ(compiled.errors[0].sourceLine, 7);
    const DiagnosticList checked = check(source);
    EXPECT_EQ(errorCodesOf(checked), std::vector<std::string>{"FILE_LINE_TOO_LONG"});
}

TEST(CompilerAgreement, CheckAndCompileAgreeOnEveryGoldenProgram) {
    const std::filesystem::path dir =
        std::filesystem::path(MTC_SOURCE_DIR) / "tests/golden/compiler";
    int programs = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (entry.path().extension() != ".DAT") continue;
        std::ifstream in(entry.path());
        std::stringstream text;
        text << in.rdbuf();
        const std::vector<MacroDefinition> globals = {{"QUICK", "G1 F12000"},
                                                      {"PARK", "G0 G53 Z0"}};  // as CompilerGolden
        const CompileResult compiled = compileText(text.str(), globals);
        const DiagnosticList checked = check(text.str(), globals);
        EXPECT_EQ(compiled.hasErrors(), checked.hasErrors()) << entry.path();
        ++programs;
    }
    EXPECT_GE(programs, 8);
}

TEST(CompilerAgreement, MacroNamesInsideExpressionBracketsAreExpanded) {
    const CompileResult r = compileText(
        "N0001 DEFINE WEAR AS TLD (, 2, @5, , 1, 13,)\n"
        "N0002 DEFINE NOMINAL AS MTD (60, 1, 0, 1)\n"
        "N0003 DEFINE ACTUAL AS MTD (60, 1, 0, 2)\n"
        "N0004 WEAR = (NOMINAL - ACTUAL) /2\n"
        "N0005 @7 = 3 * (NOMINAL + 1) (NOMINAL stays in the text)\n");
    ASSERT_EQ(r.status, CompileStatus::Compiled) << (r.errors.empty() ? "" : r.errors[0].message);
    // the object's blocks with their continuation lines joined
    std::string joined;
    for (std::size_t i = 0, start = 0; start < r.objectText.size(); ++i) {
        std::size_t end = r.objectText.find('\n', start);
        if (end == std::string::npos) end = r.objectText.size();
        const std::string line = r.objectText.substr(start, end - start);
        if (r.lineMap[i].kind == ObjectLineKind::Continuation)
            joined += " " + line.substr(line.find_first_not_of(' '));
        else
            joined += (joined.empty() ? "" : "\n") + line;
        start = end + 1;
    }
    EXPECT_NE(joined.find("N0004:0000 TLD (, 2, @5, , 1, 13,) = (MTD (60, 1, 0, 1) - MTD (60, 1, "
                          "0, 2)) /2\n"),
              std::string::npos)
        << joined;
    EXPECT_NE(joined.find("N0005:0000 @7 = 3 * (MTD (60, 1, 0, 1) + 1) (NOMINAL stays in the "
                          "text)\n"),
              std::string::npos)
        << joined;
    EXPECT_EQ(joined.find("NOMINAL -"), std::string::npos);
}

TEST(CompilerAgreement, WithTheCompilerOffAKeywordIsRefusedAtItsBlock) {
    const Program program =
        parseProgram("N0001 G1 X0 Y0 F100\nN0002 X10\nN0003 Y10 RD2\nN0004 X0\n", {4, "P4", {}});
    Diagnostic found;
    ASSERT_TRUE(findCompilerWord(program, found));
    EXPECT_EQ(found.code, "NEEDS_COMPILER");
    EXPECT_EQ(found.where.program, 4);
    EXPECT_EQ(found.where.block, "N0003");
    EXPECT_EQ(found.where.line, 3);
    EXPECT_EQ(found.where.column, 11);
    // one line naming the word, not its block: it becomes the panel's alarm
    EXPECT_EQ(found.message, "'RD2' needs the NC compiler, which is off: program refused");
    EXPECT_TRUE(found.details.empty());
    const Program plain = parseProgram("N0001 G1 X0 Y0 F100\nN0002 X10\n", {4, "P4", {}});
    EXPECT_FALSE(findCompilerWord(plain, found));
}

TEST(CompilerAgreement, WarningsOnlyWriteNoErrorFile) {
    namespace fs = std::filesystem;
    // a directory of its own: ctest runs the tests as parallel processes
    const fs::path dir =
        fs::temp_directory_path() / ("mtc_agreement-" + std::to_string(::getpid()) + "-warnings");
    fs::create_directories(dir);
    const std::string source = (dir / "N0010009.DAT").string();
    std::ofstream(dir / "N0010009.ERR") << "stale\nN0001:$W:0000\nold error\n";
    const CompileResult reduced = compileText("N0001 G1 X0 Y0 F100\nN0002 X4 RD6\nN0003 Y10\n");
    ASSERT_EQ(reduced.status, CompileStatus::Compiled);
    ASSERT_EQ(codes(reduced), std::vector<std::string>{"COMPILER_CFRD_REDUCED"});
    std::string errorPath, error;
    ASSERT_TRUE(writeCompileFiles(source, "", reduced, errorPath, error)) << error;
    EXPECT_TRUE(fs::exists(dir / "N0010009.NCO"));
    EXPECT_FALSE(fs::exists(dir / "N0010009.ERR"));  // seed 001 ch. 9: only on errors
    EXPECT_TRUE(errorPath.empty());
    // an error file with notices only (older versions) is no error
    EXPECT_FALSE(errorFileHasErrors("ident\nN0002:$I:0000\nRD reduced to 4.\n"));
    EXPECT_TRUE(
        errorFileHasErrors("ident\nN0002:$I:0000\nRD reduced.\nA0001:$W:0000\nToo long.\n"));
    fs::remove_all(dir);
}

TEST(CompilerAgreement, SourceBlocksWithEnhancedNumbersKeepTheirOrder) {
    // the GNE writes blocks it inserts as N0003:0001 ... (GS-007); the object
    // keeps them after N0003 and numbers on
    const CompileResult r = compileText(
        "N0001 G1 X0 Y0 F100\nN0003 X10 CF1\nN0003:0001 Y10\nN0003:0002 X0\nN0004 M30\n");
    ASSERT_EQ(r.status, CompileStatus::Compiled);
    EXPECT_EQ(objectBlocks(r),
              (std::vector<std::string>{"N0001:0000 G1 X0 Y0 F100", "N0003:0000 X9 Y0",
                                        "N0003:0001 G1 X10 Y1", "N0003:0002 Y10", "N0003:0003 X0",
                                        "N0004:0000 M30"}));
}

}  // namespace
