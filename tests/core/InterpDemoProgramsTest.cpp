// The built-in demo programs (resources/programs, NuxxYzzz.DAT) run on the
// demo cell without any diagnostic: program zzz of process y, with program
// 099 of the same process as the label library.
#include <gtest/gtest.h>

#include <map>

#include "InterpTestSupport.h"
#include "cnc_core/compiler/Compiler.h"
#include "resources/EmbeddedResources.h"

namespace {

using namespace mtc::core;
using namespace mtc::test;

TEST(InterpDemoPrograms, RunWithoutDiagnostics) {
    const auto names = mtc::resources::list("programs/");
    ASSERT_FALSE(names.empty());
    std::map<int, std::unique_ptr<Station>> stations;
    std::vector<std::pair<int, int>> mains;
    for (const auto& name : names) {
        const std::string file = name.substr(name.rfind('/') + 1);  // N1010001.DAT
        ASSERT_EQ(file.size(), 12u) << name;
        const int process = file[4] - '0';
        const int number = std::stoi(file.substr(5, 3));
        auto& station = stations[process];
        if (!station) station = std::make_unique<Station>(demoCell(), process);
        std::string source(mtc::resources::find(name));
        if (parse(source, number)->usesCompilerKeywords) {  // GNE demos run compiled
            CompilerOptions options;
            options.compilerActive = true;
            options.process = &station->config;
            options.programNumber = number;
            const CompileResult compiled = Compiler().compile(source, options);
            ASSERT_TRUE(compiled.errors.empty()) << name << ": " << compiled.errors[0].message;
            source = compiled.objectText;
        }
        ProgramPtr program = station->add(source, number);
        EXPECT_TRUE(program->diagnostics.empty()) << name << "\n"
                                                  << diagnosticsText(program->diagnostics);
        if (number != 99) mains.emplace_back(process, number);
    }
    for (const auto& [process, number] : mains) {
        Station& station = *stations[process];
        ASSERT_TRUE(station.interpreter->select(number));
        RunResult r = station.interpreter->run();
        EXPECT_EQ(r.status, RunStatus::Ended) << "process " << process << " program " << number;
        EXPECT_TRUE(r.diagnostics.empty()) << diagnosticsText(r.diagnostics);
        EXPECT_NE(station.sink->text.find("motion"), std::string::npos);
    }
}

}  // namespace
