// Robustness: thousands of random and mutated programs run on both demo
// processes. Every run must end (bounded by its budget) without a crash or
// an exception, and every error must carry a stable code and a location.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "InterpTestSupport.h"

namespace {

using namespace mtc::core;
using namespace mtc::test;

const char* const kVocabulary[] = {
    "G0",
    "G1",
    "G2",
    "G3",
    "G4",
    "G17",
    "G18",
    "G19",
    "G20",
    "G30",
    "G31",
    "G32",
    "G53",
    "G54",
    "G55",
    "G90",
    "G91",
    "G70",
    "G71",
    "G15",
    "G16",
    "G94",
    "G95",
    "G96",
    "G97",
    "G41",
    "G48",
    "G92",
    "G77",
    "G99",
    "G25",
    "G26",
    "ITM",
    "AXD(X:P-7-3651)=5",
    "AXD(S1:P-7-3651)=@1",
    "@7=AXD(S:P-7-3652)",
    "@8=AXD(X:P-7-9)",
    "G=@1",
    "X10",
    "X-5.5",
    "Y3",
    "Z-2",
    "Z1-42",
    "Y1 25",
    "X1 7",
    "C0",
    "C90",
    "Z2 5",
    "A1",
    "W3",
    "X=@2",
    "Y=@1*2",
    "I5",
    "J-3",
    "K2",
    "I0 J0",
    "F100",
    "F.2",
    "F0",
    "S1200",
    "S2 3000",
    "S3 100",
    "T3",
    "T99",
    "E1",
    "D2",
    "M3",
    "M5",
    "M30",
    "M0",
    "M2",
    "M68",
    "M=@1",
    "Q7",
    "Q=@3",
    "RI 36.5",
    "RI=0",
    "RI -1",
    "@1=@1+1",
    "@2=@1/(@1-@1)",
    "@3=M(2)-5",
    "@4=G(2)",
    "@5=MTD(180,,,1)",
    "MTD(180,,,1)=1",
    "MTD(61,,1,@1)=4",
    "@6=S2+T",
    "@7=TIME",
    "@999=1",
    "@1000=1",
    "BEQ .A",
    "BNE .B",
    "BMI .A",
    "BPL .C",
    "BRA .A",
    "BSR .S",
    "RTS",
    "JSR 5",
    "JSR @1",
    "JMP 7",
    "BES .A 0:1",
    "BEV .S 1:2",
    "JEV 5 0:3",
    "BTE .A",
    "BSE .B",
    "BRF .A",
    "BST",
    "RET",
    "MTP",
    "TCH(1,2)",
    "LA_ON",
    "(text)",
    "[note]",
    ";comment",
    "/",
    ":",
    ".A",
    ".B",
    ".C",
    ".S",
    "N0001",
};

std::string randomProgram(std::mt19937& rng) {
    std::uniform_int_distribution<int> lines(1, 25), words(0, 6);
    std::uniform_int_distribution<size_t> pick(0, std::size(kVocabulary) - 1);
    std::string text;
    const int n = lines(rng);
    for (int i = 0; i < n; ++i) {
        const int w = words(rng);
        for (int j = 0; j < w; ++j)
            text += std::string(kVocabulary[pick(rng)]) + " ";
        text += "\n";
    }
    return text;
}

std::string mutate(std::string text, std::mt19937& rng) {
    std::uniform_int_distribution<int> count(1, 8), kind(0, 2), byte(0, 255);
    for (int i = count(rng); i > 0 && !text.empty(); --i) {
        std::uniform_int_distribution<size_t> at(0, text.size() - 1);
        const size_t p = at(rng);
        switch (kind(rng)) {
            case 0:
                text[p] = static_cast<char>(byte(rng));
                break;
            case 1:
                text.insert(p, 1, static_cast<char>(byte(rng)));
                break;
            default:
                text.erase(p, 1);
                break;
        }
    }
    return text;
}

std::vector<std::string> goldenSources() {
    std::vector<std::string> sources;
    std::error_code ec;
    for (const auto& e :
         std::filesystem::directory_iterator(std::string(MTC_TEST_DATA_DIR) + "/interp", ec))
        if (e.path().extension() == ".nc") {
            std::ifstream in(e.path(), std::ios::binary);
            std::stringstream s;
            s << in.rdbuf();
            sources.push_back(s.str());
        }
    return sources;
}

void runOnce(const std::string& source, int process, bool checkMode) {
    Station station(demoCell(), process);
    station.add(".S @9=1\nRTS\n", 99);
    station.add("N1 @8=1\nN2 RTS\n", 5);
    station.interpreter->options().continueAfterError = checkMode;
    const RunResult r = station.run(source, 1, 2000);
    EXPECT_LE(r.blocksInterpreted, 2000u);
    for (const auto& d : r.diagnostics.items()) {
        EXPECT_FALSE(d.code.empty()) << d.message;
        if (d.severity == Severity::Error) {
            EXPECT_GT(d.where.line, 0) << d.code << " " << d.message << "\n" << source;
        }
    }
    // The state stays usable after anything: control reset and a second run.
    station.interpreter->controlReset();
    station.interpreter->run(100);
}

TEST(InterpFuzz, RandomProgramsNeverCrashOrHang) {
    std::mt19937 rng(20260101);
    for (int i = 0; i < 2000; ++i)
        runOnce(randomProgram(rng), i % 2, i % 3 == 0);
}

TEST(InterpFuzz, MutatedGoldenProgramsNeverCrashOrHang) {
    std::mt19937 rng(4242);
    const auto sources = goldenSources();
    ASSERT_FALSE(sources.empty());
    for (int i = 0; i < 1500; ++i)
        runOnce(mutate(sources[static_cast<size_t>(i) % sources.size()], rng), i % 2, i % 2 == 0);
}

}  // namespace
