// NC compiler pipeline (seed 001 ch. 1, 7-11): object file format, enhanced
// block numbers, line map, limits, error file, pass interface, files.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "CompilerTestSupport.h"
#include "cnc_core/compiler/CompileStatusBook.h"
#include "cnc_core/compiler/CompilerFiles.h"
#include "cnc_core/compiler/CompilerText.h"
#include "cnc_core/compiler/MacroPass.h"
#include "cnc_core/compiler/UserCompilers.h"
#include "cnc_core/language/Parser.h"

using namespace mtc::core;
using namespace mtc::test;

namespace {

/// A directory of its own for the running test: ctest runs the tests of one
/// binary as parallel processes (and other build trees may run them too), so
/// a fixed name would let one test delete another's files.
std::filesystem::path uniqueTestDirectory(const std::string& stem) {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    return std::filesystem::temp_directory_path() /
           (stem + "-" + std::to_string(::getpid()) + "-" + test->name());
}

const std::string kDat =
    "iMTc/000100/01.00/0000000200/03.02.2025/10:11:12/N0010004.DAT/1\n"
    "%NPG:0:01:0:004\n"
    "!01.00\n"
    "*bracket with two corners\n"
    "%NPG\n"
    "N0000 G0 G90 X0 Y0\n"
    "N0001 G1 X30 Y0 F800 RD4 ;first corner\n"
    "N0002 X30 Y25\n"
    "N0003 M30\n"
    "N0004 PROGRAMMENDE\n";

TEST(CompilerPipeline, CopiesIdentificationAndHeaderAndNumbersEveryBlock) {
    const CompileResult r = compileText(kDat);
    ASSERT_EQ(r.status, CompileStatus::Compiled);
    EXPECT_TRUE(r.errors.empty());
    const std::string expected =
        "iMTc/000100/01.00/0000000200/03.02.2025/10:11:12/N0010004.DAT/1\n"
        "%NPG:0:01:0:004\n!01.00\n*bracket with two corners\n%NPG\n"
        "N0000:0000 G0 G90 X0 Y0\n"
        "N0001:0000 G1 X26 Y0 F800 ;first corner\n"
        "N0001:0001 G3 X30 Y4 I26 J4\n"
        "N0002:0000 G1 X30 Y25\n"
        "N0003:0000 M30\n"
        "N0004:0000 PROGRAMMENDE\n";
    EXPECT_EQ(r.objectText, expected);
    EXPECT_EQ(r.objectBlocks, 5u);
}

TEST(CompilerPipeline, LineMapNamesSourceLinesAndIntermediateBlocks) {
    const CompileResult r = compileText(kDat);
    ASSERT_EQ(r.lineMap.size(), 11u);
    EXPECT_EQ(r.lineMap[0].kind, ObjectLineKind::Identification);
    for (int i = 1; i <= 4; ++i)
        EXPECT_EQ(r.lineMap[static_cast<std::size_t>(i)].kind, ObjectLineKind::Header);
    const ObjectLine& inserted = r.lineMap[7];
    EXPECT_EQ(inserted.kind, ObjectLineKind::Block);
    EXPECT_TRUE(inserted.intermediate);
    EXPECT_EQ(inserted.sourceNumber, 1);
    EXPECT_EQ(inserted.subNumber, 1);
    EXPECT_EQ(inserted.sourceLine, 7u);
    EXPECT_FALSE(r.lineMap[8].intermediate);
    EXPECT_EQ(r.lineMap[8].sourceLine, 8u);
    EXPECT_EQ(r.lineMap[10].kind, ObjectLineKind::ProgramEnd);
}

TEST(CompilerPipeline, ObjectProgramParsesWithoutDiagnostics) {
    const CompileResult r = compileText(kDat);
    const Program object = parseProgram(r.objectText);
    EXPECT_TRUE(object.diagnostics.empty());
    EXPECT_EQ(object.blockId(2), "N0001:0001");
}

TEST(CompilerPipeline, LooseFilesHaveNoLineLimit) {
    std::string source;
    for (int i = 0; i < 10001; ++i)
        source += "N" + formatFourDigits(i % 10000) + " M8\n";
    const CompileResult r = compileText(source);
    EXPECT_EQ(r.status, CompileStatus::Compiled);
    EXPECT_EQ(r.lineMap.size(), 10002u);
}

TEST(CompilerPipeline, LooseFileGetsProgramEndAfterTheLastNumber) {
    const CompileResult r = compileText("N0007 G1 X1\nN0009 X2\n");
    ASSERT_EQ(r.status, CompileStatus::Compiled);
    EXPECT_EQ(r.objectText, "N0007:0000 G1 X1\nN0009:0000 X2\nN0010:0000 PROGRAMMENDE\n");
}

TEST(CompilerPipeline, LongBlocksWrapAtSeventyOneWithSixBlanks) {
    std::string block = "N0001 G1 X1";
    while (block.size() < 69)
        block += " M8";
    const CompileResult r = compileText(block + "\n");
    ASSERT_EQ(r.status, CompileStatus::Compiled) << r.objectText;
    std::istringstream lines(r.objectText);
    std::string line;
    int continuation = 0;
    while (std::getline(lines, line)) {
        EXPECT_LE(line.size(), kMaxObjectLine) << line;
        if (line.rfind("      ", 0) == 0) ++continuation;
    }
    EXPECT_EQ(continuation, 1);
    EXPECT_TRUE(parseProgram(r.objectText).diagnostics.empty());
}

TEST(CompilerPipeline, MoreThanTenThousandObjectLinesIsAGeneralError) {
    // 8,001 source blocks, a rounding at every second corner: ~12,000 lines
    std::string source = "iMTc/x\n%NPG:0:01:0:009\n*staircase\n%NPG\nN0000 G1 X0 Y0 F900\n";
    for (int i = 1; i <= 8000; ++i)
        source += "N" + formatFourDigits(i % 10000) + (i % 2 ? " X" : " Y") +
                  std::to_string((i + 1) / 2) + (i % 2 ? " RD0.2\n" : "\n");
    const CompileResult r = compileText(source);
    ASSERT_EQ(r.status, CompileStatus::Error);
    ASSERT_EQ(codes(r), std::vector<std::string>{"COMPILER_TOO_MANY_LINES"});
    EXPECT_EQ(r.errors[0].generalNumber, 1);
    EXPECT_TRUE(r.errors[0].block.empty());
    EXPECT_TRUE(r.objectText.empty());
}

TEST(CompilerPipeline, StopsAfterFortyErrors) {
    std::string source = "N0000 G1 X0 Y0\n";
    for (int i = 1; i <= 60; ++i)
        source += "N" + formatFourDigits(i) + " X" + std::to_string(i) + " CF=@1\n";
    const CompileResult r = compileText(source);
    EXPECT_EQ(r.status, CompileStatus::Error);
    EXPECT_EQ(r.errors.size(), 40u);
    EXPECT_EQ(r.errors.back().block, "N0040");
}

TEST(CompilerPipeline, KeywordWithoutPassIsUnsupported) {
    CompilerOptions options;
    options.compilerActive = true;
    const Compiler onlyMacros(CompilerPassList{std::make_shared<MacroPass>()});
    const CompileResult r = onlyMacros.compile("N0001 G1 X5\nN0002 LA_ON\n", options);
    ASSERT_EQ(codes(r), std::vector<std::string>{"COMPILER_KEYWORD_UNSUPPORTED"});
    EXPECT_EQ(r.errors[0].block, "N0002");
    EXPECT_EQ(r.errors[0].sourceLine, 2);
}

/// A test pass: inserts two blocks after every block that has "M8".
class InsertAfterM8 : public CompilerPass {
  public:
    std::string_view name() const override { return "test"; }
    int order() const override { return 600; }
    std::vector<std::string> keywords() const override { return {}; }
    void run(BlockSequence& blocks, CompileContext&) const override {
        BlockSequence out;
        for (CompileBlock& block : blocks) {
            const bool m8 = block.text == "M8";
            out.push_back(block);
            for (int k = 0; m8 && k < 2; ++k) {
                CompileBlock extra = block;
                extra.intermediate = true;
                extra.changed = true;
                extra.text = "M" + std::to_string(10 + k);
                out.push_back(extra);
            }
        }
        blocks = std::move(out);
    }
};

TEST(CompilerPipeline, RegisteredPassesRunInOrderAndInsertedBlocksCountUp) {
    Compiler compiler;
    compiler.addPass(std::make_shared<InsertAfterM8>());
    EXPECT_EQ(compiler.passes().back()->name(), "test");
    CompilerOptions options;
    const CompileResult r = compiler.compile("N0001 M8\nN0002 M9\n", options);
    EXPECT_EQ(objectBlocks(r), (std::vector<std::string>{"N0001:0000 M8", "N0001:0001 M10",
                                                         "N0001:0002 M11", "N0002:0000 M9"}));
}

TEST(CompilerErrorFile, FormatsBlockAndGeneralErrorsWithLimits) {
    CompilerError block;
    block.block = "N0030";
    block.message = std::string(70, 'm');
    block.details = {std::string(100, 'd')};
    CompilerError general;
    general.generalNumber = 1;
    general.message = "Too long.";
    CompilerError warning;
    warning.severity = Severity::Warning;
    warning.block = "N0031:0001";
    warning.message = "Reduced.";
    const std::string text = formatErrorFile("ident", {block, general, warning});
    const std::string expected = "ident\nN0030:$W:0002\n" + std::string(52, 'm') + "\n" +
                                 std::string(65, 'd') + "\n" + std::string(35, 'd') +
                                 "\nA0001:$W:0000\nToo long.\nN0031:$I:0000\nReduced.\n";
    EXPECT_EQ(text, expected);
    std::string identification;
    const std::vector<CompilerError> back = parseErrorFile(text, identification);
    EXPECT_EQ(identification, "ident");
    ASSERT_EQ(back.size(), 3u);
    EXPECT_EQ(back[0].block, "N0030");
    EXPECT_EQ(back[0].details.size(), 2u);
    EXPECT_EQ(back[1].generalNumber, 1);
    EXPECT_EQ(back[2].severity, Severity::Warning);
}

TEST(CompilerErrorFile, AtMostFourteenDetailLines) {
    std::vector<std::string> many(20, "line");
    EXPECT_EQ(limitDetails(many).size(), 14u);
}

TEST(CompilerFiles, IdentificationGetsNameStampAndSize) {
    const std::string id = "iMTc/002004/04.16/0000002737/07.08.1996/14:44:42/N0010001.DAT/4";
    const std::string rest(100, 'x');
    const std::string updated =
        updatedIdentification(id, "N0010001.NCO", rest.size(), "01.02.2025 03:04:05");
    EXPECT_EQ(updated, "iMTc/002004/04.16/0000000164/01.02.2025/03:04:05/N0010001.NCO/4");
    EXPECT_EQ(updated.size() + 1 + rest.size(), 164u);
    EXPECT_EQ(updatedIdentification("my own line", "x.NCO", 5, "01.02.2025 03:04:05"),
              "my own line");
}

TEST(CompilerFiles, WritesObjectOrErrorFileAndRemovesTheStaleOne) {
    namespace fs = std::filesystem;
    const fs::path dir = uniqueTestDirectory("mtc_compiler_files_test");
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string source = (dir / "N0010004.DAT").string();
    std::string errorPath, error;
    ASSERT_TRUE(writeCompileFiles(source, "", compileText(kDat), errorPath, error)) << error;
    EXPECT_TRUE(fs::exists(dir / "N0010004.NCO"));
    EXPECT_FALSE(fs::exists(dir / "N0010004.ERR"));
    std::ifstream object(dir / "N0010004.NCO");
    std::string first;
    std::getline(object, first);
    EXPECT_NE(first.find("/N0010004.NCO/"), std::string::npos);
    const CompileResult bad = compileText("N0001 G1 X0 Y0\nN0002 X5 RD=@3\nN0003 Y5\n");
    ASSERT_TRUE(writeCompileFiles(source, "", bad, errorPath, error)) << error;
    EXPECT_FALSE(fs::exists(dir / "N0010004.NCO"));
    ASSERT_TRUE(fs::exists(dir / "N0010004.ERR"));
    std::ifstream err(dir / "N0010004.ERR");
    std::stringstream text;
    text << err.rdbuf();
    EXPECT_NE(text.str().find("N0002:$W:0001\nInvalid RD value.\n"), std::string::npos);
    fs::remove_all(dir);
}

TEST(CompilerStatus, NeedsCompilationOnlyWhenActiveAndKeywordOrGlobalMacro) {
    CompilerOptions options;
    const Program plain = parseProgram("N0001 G1 X1\nN0002 QUICK X2\n");
    const Program keyword = parseProgram("N0001 G1 X1 CF2\nN0002 Y1\n");
    EXPECT_FALSE(needsCompilation(keyword, options));
    options.compilerActive = true;
    EXPECT_TRUE(needsCompilation(keyword, options));
    EXPECT_FALSE(needsCompilation(plain, options));
    options.globalMacros = {{"QUICK", "G1 F9000"}};
    EXPECT_TRUE(needsCompilation(plain, options));
    EXPECT_EQ(statusLetter(CompileStatus::NotCompiled), 'N');
    EXPECT_EQ(statusLetter(CompileStatus::Compiled), 'C');
    EXPECT_EQ(statusLetter(CompileStatus::Error), 'E');
    EXPECT_EQ(statusLetter(CompileStatus::NotNeeded), ' ');
}

}  // namespace

namespace {

TEST(CompilerStatus, BookSaysNThenCOrEAndNAgainAfterAnEdit) {
    CompilerOptions options;
    options.compilerActive = true;
    CompileStatusBook book;
    const Program good = parseProgram("N0001 G1 X0 Y0\nN0002 X5 CF1\nN0003 Y5\n");
    EXPECT_TRUE(book.mustCompile(0, 1, good, options));
    book.record(0, 1, good, Compiler().compile(good, options));
    EXPECT_EQ(book.status(0, 1, good, options), CompileStatus::Compiled);
    EXPECT_FALSE(book.mustCompile(0, 1, good, options));
    const Program edited = parseProgram("N0001 G1 X0 Y0\nN0002 X5 CF=@2\nN0003 Y5\n");
    EXPECT_EQ(book.status(0, 1, edited, options), CompileStatus::NotCompiled);
    book.record(0, 1, edited, Compiler().compile(edited, options));
    EXPECT_EQ(book.status(0, 1, edited, options), CompileStatus::Error);
    book.invalidateAll();
    EXPECT_EQ(book.status(0, 1, edited, options), CompileStatus::NotCompiled);
    options.compilerActive = false;
    EXPECT_EQ(book.status(0, 1, edited, options), CompileStatus::NotNeeded);
}

}  // namespace

namespace {

class UserCompilerTest : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = uniqueTestDirectory("mtc_user_compiler_test");
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }
    std::filesystem::path dir_;
};

TEST_F(UserCompilerTest, BeforeSeesTheSourceAfterSeesTheObject) {
    UserCompilerSlots slots;
    // compiler 1 turns ELLIPSE into a keyword the INDRAMAT compiler knows
    slots.before[0] = "sh -c 'sed \"s/ELLIPSE/RD2/\" \"$0\" > \"$1\"'";
    // compiler 4 appends a marker to the compiled block N0002
    slots.after[1] = "sh -c 'sed \"s/^N0002:0000 .*/& M99/\" \"$0\" > \"$1\"'";
    CompilerOptions options;
    options.compilerActive = true;
    const CompileResult r =
        compileWithUserCompilers(Compiler(), "N0001 G1 X0 Y0\nN0002 X10 ELLIPSE\nN0003 Y10\n",
                                 options, slots, dir_.string());
    ASSERT_EQ(r.status, CompileStatus::Compiled) << (r.errors.empty() ? "" : r.errors[0].message);
    EXPECT_EQ(objectBlocks(r)[1], "N0002:0000 X8 Y0 M99");
    EXPECT_EQ(objectBlocks(r)[2], "N0002:0001 G3 X10 Y2 I8 J2");
    EXPECT_TRUE(r.lineMap[2].intermediate);
}

TEST_F(UserCompilerTest, ErrorsOfAUserCompilerStopTheChain) {
    UserCompilerSlots slots;
    slots.before[1] =
        "sh -c 'printf \"id\\nN0002:\\$W:0001\\nUnknown ELLIPSE.\\nno such function\\n\" > "
        "\"$2\"; exit 1'";
    slots.after[0] = "sh -c 'exit 7'";
    CompilerOptions options;
    const CompileResult r = compileWithUserCompilers(Compiler(), "N0001 G1 X0\nN0002 ELLIPSE\n",
                                                     options, slots, dir_.string());
    EXPECT_EQ(r.status, CompileStatus::Error);
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].block, "N0002");
    EXPECT_EQ(r.errors[0].message, "Unknown ELLIPSE.");
    slots.before[1].clear();
    const CompileResult failed =
        compileWithUserCompilers(Compiler(), "N0001 G1 X0\n", options, slots, dir_.string());
    ASSERT_EQ(codes(failed), std::vector<std::string>{"USER_COMPILER_FAILED"});
    EXPECT_NE(failed.errors[0].details[0].find("exit status 7"), std::string::npos);
}

}  // namespace
