// Replays the fuzz campaign's findings (tests/fuzz/regressions/<target>/*)
// and the hand-written seeds (tests/fuzz/seeds/<target>/*) through the fuzz
// targets with the normal compiler: a finding that crashes or breaks a
// contract again fails here (the target aborts). Also tests the number
// mutator, which only the libFuzzer build uses.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "FuzzTargets.h"
#include "NumberMutator.h"

namespace {

namespace fs = std::filesystem;
using namespace mtc::fuzz;

std::vector<fs::path> filesUnder(const fs::path& directory) {
    std::vector<fs::path> files;
    std::error_code error;
    for (fs::directory_iterator it(directory, error), end; !error && it != end; it.increment(error))
        if (it->is_regular_file() && it->path().filename().string()[0] != '.')
            files.push_back(it->path());
    std::sort(files.begin(), files.end());
    return files;
}

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

class FuzzReplay : public ::testing::TestWithParam<std::string> {};

TEST_P(FuzzReplay, RegressionInputsAndSeedsPass) {
    const FuzzTarget* target = findFuzzTarget(GetParam());
    ASSERT_NE(target, nullptr);
    int replayed = 0;
    for (const char* kind : {"regressions", "seeds"}) {
        for (const fs::path& file : filesUnder(fs::path(MTC_FUZZ_DIR) / kind / GetParam())) {
            SCOPED_TRACE(file.string());
            target->run(readFile(file));  // aborts (a failed test) on a broken contract
            ++replayed;
        }
    }
    EXPECT_GT(replayed, 0) << "every target has seeds";
}

INSTANTIATE_TEST_SUITE_P(Targets, FuzzReplay,
                         ::testing::Values("parser", "compiler", "gne", "machine_config",
                                           "machine_data", "target_path", "mdi", "removal",
                                           "reentry"));

TEST(FuzzReplayLayout, EveryTargetIsReplayedAndEveryFolderNamesATarget) {
    EXPECT_EQ(fuzzTargets().size(), 9u);
    for (const char* kind : {"regressions", "seeds"}) {
        std::error_code error;
        for (fs::directory_iterator it(fs::path(MTC_FUZZ_DIR) / kind, error), end;
             !error && it != end; it.increment(error))
            EXPECT_NE(findFuzzTarget(it->path().filename().string()), nullptr) << it->path();
    }
}

TEST(NumberMutator, FindsSignedDecimalAndExponentNumbers) {
    const std::string text = "N0010 G1 X-3.5 Y.2 F1e-300 @1=+7 E";
    std::vector<std::string> found;
    for (const NumberSpan& s : findNumbers(text))
        found.push_back(text.substr(s.begin, s.end - s.begin));
    EXPECT_EQ(found, (std::vector<std::string>{"0010", "1", "-3.5", ".2", "1e-300", "1", "+7"}));
}

TEST(NumberMutator, ReplacesANumberByAnExtremeOneWithinTheSizeLimit) {
    std::vector<std::string> expected;  // each number of the text by each extreme
    for (std::string_view e : extremeNumbers())
        for (const std::string& form :
             {"G" + std::string(e) + " X10 Y20", "G1 X" + std::string(e) + " Y20",
              "G1 X10 Y" + std::string(e)})
            expected.push_back(form);
    std::vector<std::string> seen;
    for (std::uint32_t seed = 0; seed < 5000; ++seed) {
        std::string text = "G1 X10 Y20";
        ASSERT_TRUE(replaceNumberByExtreme(text, seed, 1000));
        EXPECT_NE(std::find(expected.begin(), expected.end(), text), expected.end()) << text;
        if (std::find(seen.begin(), seen.end(), text) == seen.end()) seen.push_back(text);
    }
    EXPECT_EQ(seen.size(), expected.size()) << "every number gets every extreme";
    std::string text = "X1";
    EXPECT_FALSE(replaceNumberByExtreme(text, 1, 3)) << "too long for maxSize";
    EXPECT_EQ(text, "X1");
    std::string none = "GX";
    ASSERT_TRUE(replaceNumberByExtreme(none, 5, 100));
    EXPECT_GT(none.size(), 2u) << "a text without numbers gets one inserted";
}

}  // namespace
