// The compile status and runtime program live in the core (issue 16): the
// cell's ProgramCompilation is the station's program preparer, so Start
// compiles on demand, refuses a program with errors and runs the object,
// with no user interface in between -- the same rules for the panel, the
// CLI and these tests (seed 001 ch. 7-11).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "InterpTestSupport.h"
#include "cnc_core/cell/Cell.h"
#include "tests/support/TempDir.h"

namespace mtc::test {
namespace {

namespace fs = std::filesystem;
using core::CompileStatus;
using core::ControlKey;

const std::string kRounded = "N0001 G1 G90 X0 Y0 F800\nN0002 X30 RD4\nN0003 Y30\nN0004 M30\n";
const std::string kBroken = "N0001 G1 G90 X0 Y0 F800\nN0002 X5 RD=@3\nN0003 Y5\nN0004 M30\n";

/// A program folder in a temporary directory, removed afterwards.
class ProgramCompilationTest : public ::testing::Test {
  protected:
    /// A cell on the folder with program `number` from file `name`.
    void addFile(core::Cell& cell, int number, const std::string& name, const std::string& text) {
        std::ofstream(dir_.path() / name, std::ios::binary) << text;
        cell.setProgramDirectory(dir_.path().string());
        cell.addProgram(0, number, name, text);
    }
    static void activateCompiler(core::Cell& cell) {
        core::NcOptions options;
        options.compilerActive = true;
        cell.setNcOptions(options);
    }
    bool exists(const std::string& name) const { return dir_.exists(name); }

    mtc::test::TempDir dir_{"mtc-compilation"};
};

TEST_F(ProgramCompilationTest, StartCompilesOnDemandAndRunsTheObject) {
    core::Cell cell(demoCell());
    activateCompiler(cell);
    addFile(cell, 7, "P7.DAT", kRounded);
    core::ProgramCompilation& compilation = cell.compilation(0);
    EXPECT_EQ(compilation.status(7), CompileStatus::NotCompiled);

    core::Station& mill = cell.station(0);
    ASSERT_TRUE(mill.selectProgram(7));
    ASSERT_TRUE(mill.press(ControlKey::Start)) << mill.control().alarm();
    EXPECT_EQ(compilation.status(7), CompileStatus::Compiled);
    EXPECT_TRUE(exists("P7.NCO"));
    EXPECT_FALSE(exists("P7.ERR"));
    const auto runtime = cell.store().findRuntime(mill.process(), 7);
    ASSERT_NE(runtime, nullptr) << "the object runs, not the source";
    EXPECT_EQ(runtime->source, compilation.running(7)->objectText);
    EXPECT_EQ(runtime->source.view().find("RD"), std::string::npos);
}

TEST_F(ProgramCompilationTest, ErrorsRefuseStartAndSurviveTheSession) {
    {
        core::Cell cell(demoCell());
        activateCompiler(cell);
        addFile(cell, 8, "P8.DAT", kBroken);
        core::Station& mill = cell.station(0);
        ASSERT_TRUE(mill.selectProgram(8));
        EXPECT_FALSE(mill.press(ControlKey::Start));
        EXPECT_NE(mill.control().alarm().find("compiler errors"), std::string::npos)
            << mill.control().alarm();
        EXPECT_EQ(cell.compilation(0).status(8), CompileStatus::Error);
        EXPECT_TRUE(exists("P8.ERR"));
        EXPECT_FALSE(exists("P8.NCO"));
        ASSERT_FALSE(cell.compilation(0).messages(8).empty());
        EXPECT_EQ(cell.compilation(0).messages(8).front().sourceLine, 2);
    }
    // The next session reads the status and the messages from the files.
    core::Cell cell(demoCell());
    activateCompiler(cell);
    cell.setProgramDirectory(dir_.path().string());
    cell.addProgram(0, 8, "P8.DAT", kBroken);
    core::ProgramCompilation& compilation = cell.compilation(0);
    EXPECT_EQ(compilation.status(8), CompileStatus::Error);
    EXPECT_TRUE(compilation.messages(8).empty());
    compilation.loadErrorFiles();
    ASSERT_FALSE(compilation.messages(8).empty());
    EXPECT_EQ(compilation.messages(8).front().block, "N0002");
    EXPECT_EQ(compilation.messages(8).front().sourceLine, 2);
}

TEST_F(ProgramCompilationTest, SavingMakesTheProgramUncompiledAndRemovesItsObject) {
    core::Cell cell(demoCell());
    activateCompiler(cell);
    addFile(cell, 7, "P7.DAT", kRounded);
    core::ProgramCompilation& compilation = cell.compilation(0);
    std::vector<int> heard;
    compilation.setChangeListener([&](int number) { heard.push_back(number); });
    std::string error;
    ASSERT_TRUE(compilation.compile(7, error)) << error;
    ASSERT_TRUE(exists("P7.NCO"));

    const std::string edited = kRounded + "N0005 M30\n";
    ASSERT_TRUE(compilation.save(7, edited, error)) << error;
    EXPECT_EQ(compilation.status(7), CompileStatus::NotCompiled);
    EXPECT_FALSE(exists("P7.NCO"));
    EXPECT_EQ(cell.program(0, 7)->source, edited);
    std::ifstream file(dir_.path() / "P7.DAT", std::ios::binary);
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(file), {}), edited);
    EXPECT_EQ(heard, (std::vector<int>{7, 7}));
}

TEST_F(ProgramCompilationTest, WithTheCompilerOffAKeywordRefusesStartWithItsPlace) {
    core::Cell cell(demoCell());
    addFile(cell, 7, "P7.DAT", kRounded);
    core::Station& mill = cell.station(0);
    ASSERT_TRUE(mill.selectProgram(7));
    const std::uint64_t before = mill.diagnostics().lastSerial();
    EXPECT_FALSE(mill.press(ControlKey::Start));
    std::vector<core::Diagnostic> logged;
    mill.diagnostics().forEachAfter(
        before, [&](const core::LoggedDiagnostic& r) { logged.push_back(r.diagnostic); });
    ASSERT_EQ(logged.size(), 1u);
    EXPECT_EQ(logged[0].code, "NEEDS_COMPILER");
    EXPECT_EQ(logged[0].where.block, "N0002");
    EXPECT_EQ(logged[0].where.line, 2);
    EXPECT_FALSE(exists("P7.NCO"));
    std::string error;
    EXPECT_FALSE(cell.compilation(0).compile(7, error));
    EXPECT_NE(error.find("not active"), std::string::npos) << error;
}

TEST_F(ProgramCompilationTest, AUserCompilerRunsOnlyWhenApproved) {
    core::Cell cell(demoCell());
    core::NcOptions options;
    options.compilerActive = true;
    const fs::path marker = dir_.path() / "ran";
    options.userCompilers.before[0] = "touch " + marker.string();
    cell.setNcOptions(options);
    addFile(cell, 7, "P7.DAT", kRounded);
    core::ProgramCompilation& compilation = cell.compilation(0);
    compilation.setUserCompilerApproval([](std::string& refusal) {
        refusal = "the operator said no";
        return false;
    });
    std::string error;
    ASSERT_TRUE(compilation.compile(7, error)) << error;
    EXPECT_FALSE(fs::exists(marker)) << "nothing ran";
    EXPECT_EQ(compilation.status(7), CompileStatus::Error);
    ASSERT_EQ(compilation.messages(7).size(), 1u);
    EXPECT_EQ(compilation.messages(7)[0].code, "USER_COMPILER_NOT_APPROVED");
    EXPECT_EQ(compilation.messages(7)[0].details, std::vector<std::string>{"the operator said no"});

    compilation.setUserCompilerApproval([](std::string&) { return true; });
    ASSERT_TRUE(compilation.compile(7, error)) << error;
    compilation.waitForCompiles();
    EXPECT_TRUE(fs::exists(marker)) << "approved, it ran";
}

TEST_F(ProgramCompilationTest, InvalidatedProgramsRunTheirSourceAgain) {
    core::Cell cell(demoCell());
    activateCompiler(cell);
    addFile(cell, 7, "P7.DAT", kRounded);
    core::Station& mill = cell.station(0);
    ASSERT_TRUE(mill.selectProgram(7));
    ASSERT_NE(cell.store().findRuntime(mill.process(), 7), nullptr);
    cell.compilation(0).invalidate({7});
    EXPECT_EQ(cell.store().findRuntime(mill.process(), 7), nullptr);
    EXPECT_EQ(cell.compilation(0).running(7), nullptr);
    EXPECT_FALSE(exists("P7.NCO"));
    EXPECT_EQ(cell.compilation(0).status(7), CompileStatus::NotCompiled);
}

/// A user compiler that waits until the test creates `gate` (the compile
/// runs beside the test until then; 60 s timeout if the test never does).
std::string gatedCompiler(const fs::path& gate) {
    return "sh -c 'while [ ! -e " + gate.string() + " ]; do sleep 0.01; done' gate";
}

/// Compiler active, user compiler 1 gated by `gate`, program 7 in the folder.
void useGatedCompiler(core::Cell& cell, const fs::path& gate) {
    core::NcOptions options;
    options.compilerActive = true;
    options.userCompilers.before[0] = gatedCompiler(gate);
    cell.setNcOptions(options);
}

TEST_F(ProgramCompilationTest, UserCompilersRunBesideTheStationAndStartWaitsForThem) {
    core::Cell cell(demoCell());
    const fs::path gate = dir_.path() / "gate";
    useGatedCompiler(cell, gate);
    addFile(cell, 7, "P7.DAT", kRounded);
    core::ProgramCompilation& compilation = cell.compilation(0);
    std::string error;
    ASSERT_TRUE(compilation.compile(7, error)) << error;
    EXPECT_TRUE(compilation.compiling(7)) << "compile() returned while the user compiler runs";
    EXPECT_EQ(compilation.status(7), CompileStatus::NotCompiled);
    EXPECT_FALSE(compilation.compile(7, error)) << "one user compiler chain at a time";
    EXPECT_NE(error.find("a user compiler runs"), std::string::npos) << error;
    cell.addProgram(1, 7, "P7.DAT", kRounded);
    error.clear();
    EXPECT_FALSE(cell.compilation(1).compile(7, error)) << "in the whole cell";
    EXPECT_NE(error.find("a user compiler runs"), std::string::npos) << error;

    core::Station& mill = cell.station(0);
    ASSERT_TRUE(mill.selectProgram(7));
    EXPECT_FALSE(mill.press(ControlKey::Start));
    EXPECT_NE(mill.control().alarm().find("being compiled"), std::string::npos)
        << mill.control().alarm();
    EXPECT_FALSE(compilation.takeFinished()) << "still waiting at the gate";

    std::ofstream(gate).put('x');
    compilation.waitForCompiles();
    EXPECT_FALSE(compilation.compiling(7));
    EXPECT_EQ(compilation.status(7), CompileStatus::Compiled);
    EXPECT_TRUE(exists("P7.NCO"));
    EXPECT_TRUE(mill.press(ControlKey::Start)) << mill.control().alarm();
    ASSERT_NE(cell.store().findRuntime(mill.process(), 7), nullptr);
}

TEST_F(ProgramCompilationTest, ABackgroundResultOfAnOldSourceIsDropped) {
    core::Cell cell(demoCell());
    const fs::path gate = dir_.path() / "gate";
    useGatedCompiler(cell, gate);
    addFile(cell, 7, "P7.DAT", kRounded);
    core::ProgramCompilation& compilation = cell.compilation(0);
    std::string error;
    ASSERT_TRUE(compilation.compile(7, error)) << error;
    ASSERT_TRUE(compilation.save(7, kRounded + "N0005 M30\n", error)) << error;
    std::ofstream(gate).put('x');
    compilation.waitForCompiles();
    EXPECT_EQ(compilation.status(7), CompileStatus::NotCompiled)
        << "the saved text is not compiled";
    EXPECT_FALSE(exists("P7.NCO"));
    EXPECT_EQ(compilation.lastResult(7), nullptr);
}

}  // namespace
}  // namespace mtc::test
