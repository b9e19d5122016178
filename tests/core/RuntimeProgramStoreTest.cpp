// ProgramStore's runtime version (decision C-013): the compiled object of a
// program is what the interpreter and the restart find; the source stays
// what the editor sees; a new source drops the compiled version.
#include <gtest/gtest.h>

#include "InterpTestSupport.h"
#include "cnc_core/compiler/Compiler.h"
#include "cnc_core/language/Parser.h"

namespace mtc::test {
namespace {

const char* kSource =
    "N0000 G0 G17 G90 X0 Y0 Z0\n"
    "N0001 G1 X30 Y0 F1000 RD5\n"
    "N0002 G1 X30 Y30\n"
    "N0003 M30\n";

core::ProgramPtr compiled(const core::Program& source, int number) {
    core::CompilerOptions options;
    options.compilerActive = true;
    options.programNumber = number;
    const core::CompileResult result = core::Compiler().compile(source, options);
    EXPECT_EQ(result.status, core::CompileStatus::Compiled);
    core::ParseOptions parse;
    parse.programNumber = number;
    return std::make_shared<core::Program>(core::parseProgram(result.objectText, parse));
}

TEST(RuntimeProgramStore, FindReturnsTheRuntimeVersionAndFindSourceTheSource) {
    core::ProgramStore store;
    const core::ProgramPtr source = parse(kSource, 5);
    store.put(0, 5, source);
    EXPECT_EQ(store.find(0, 5), source);
    EXPECT_EQ(store.findRuntime(0, 5), nullptr);
    const core::ProgramPtr object = compiled(*source, 5);
    store.putRuntime(0, 5, object);
    EXPECT_EQ(store.find(0, 5), object);
    EXPECT_EQ(store.findSource(0, 5), source);
    EXPECT_EQ(store.find(1, 5), nullptr);  // per process
    store.putRuntime(0, 5, nullptr);
    EXPECT_EQ(store.find(0, 5), source);
}

TEST(RuntimeProgramStore, ANewSourceDropsTheCompiledVersion) {
    core::ProgramStore store;
    store.put(0, 5, parse(kSource, 5));
    store.putRuntime(0, 5, compiled(*store.find(0, 5), 5));
    const core::ProgramPtr edited = parse("N0000 G0 X1\nN0001 M30\n", 5);
    store.put(0, 5, edited);
    EXPECT_EQ(store.find(0, 5), edited);
    EXPECT_EQ(store.findRuntime(0, 5), nullptr);
}

TEST(RuntimeProgramStore, TheInterpreterRunsTheCompiledGeometry) {
    Station mill(demoCell(), 0);
    const core::ProgramPtr source = mill.add(kSource, 5);
    mill.store.putRuntime(mill.config.index, 5, compiled(*source, 5));
    ASSERT_TRUE(mill.interpreter->select(5));
    mill.interpreter->run();
    const std::string& path = mill.sink->text;
    // The line ends at the first tangent point, the inserted arc (N0001:0001)
    // at the second; the sharp corner X30 Y0 of the source is never reached.
    EXPECT_NE(path.find("N0001:0000 L2 linear X=25.0000 F"), std::string::npos) << path;
    EXPECT_NE(path.find("N0001:0001 L3 ccw X=30.0000 Y=5.0000 centre X=25.0000 Y=5.0000"),
              std::string::npos)
        << path;
    EXPECT_EQ(path.find("linear X=30.0000"), std::string::npos) << path;
}

}  // namespace
}  // namespace mtc::test
