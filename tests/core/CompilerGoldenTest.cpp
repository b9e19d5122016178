// Golden files of the NC compiler: every tests/golden/compiler/<name>.DAT is
// compiled (compiler active, global macros QUICK and PARK as in the NC
// options below) and the object text compared with <name>.NCO and the error
// file text with <name>.ERR (only when there are messages). The
// identification line is compared as the compiler copies it (the stamp of
// the user interface is tested in CompilerPipelineTest and the CLI tests).
// Nothing is rewritten silently: set MTC_UPDATE_GOLDEN=1 to regenerate.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "CompilerTestSupport.h"
#include "cnc_core/compiler/CompilerFiles.h"

namespace {

using namespace mtc::core;
namespace fs = std::filesystem;

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

void writeFile(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
}

std::vector<fs::path> goldenSources() {
    std::vector<fs::path> sources;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(fs::path(MTC_TEST_DATA_DIR) / "compiler", ec))
        if (entry.path().extension() == ".DAT") sources.push_back(entry.path());
    std::sort(sources.begin(), sources.end());
    return sources;
}

/// The global macros of the golden programs' "NC options".
std::vector<MacroDefinition> goldenGlobalMacros() {
    return {{"QUICK", "G1 F12000"}, {"PARK", "G0 G53 Z0"}};
}

void compareOrUpdate(const fs::path& path, const std::string& actual, bool update) {
    if (update) {
        if (actual.empty())
            fs::remove(path);
        else
            writeFile(path, actual);
        return;
    }
    if (actual.empty()) {
        EXPECT_FALSE(fs::exists(path)) << path << " should not exist";
        return;
    }
    ASSERT_TRUE(fs::exists(path)) << path << " missing (MTC_UPDATE_GOLDEN=1 creates it)";
    EXPECT_EQ(readFile(path), actual) << path;
}

TEST(CompilerGolden, EveryProgramMatchesItsObjectAndErrorFile) {
    const bool update = std::getenv("MTC_UPDATE_GOLDEN") != nullptr;
    const std::vector<fs::path> sources = goldenSources();
    ASSERT_GE(sources.size(), 8u);
    for (const fs::path& source : sources) {
        SCOPED_TRACE(source.filename().string());
        CompilerOptions options;
        options.compilerActive = true;
        options.globalMacros = goldenGlobalMacros();
        options.programName = source.filename().string();
        const CompileResult r = Compiler().compile(readFile(source), options);
        fs::path object = source, errors = source;
        object.replace_extension(".NCO");
        errors.replace_extension(".ERR");
        compareOrUpdate(object, r.objectText, update);
        compareOrUpdate(errors, r.errors.empty() ? "" : formatErrorFile(r.identification, r.errors),
                        update);
    }
}

}  // namespace
